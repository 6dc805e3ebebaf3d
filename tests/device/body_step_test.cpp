// The moving bodies on the device step (device/body_step.hpp, device/body_run.hpp), run by the
// host execution, against the CPU engine's RigidBodyCoupling and ParticleContainment: a free
// ball sinking onto the floor of a small 2D tank of water (the fluid's force and the contacts
// with the floor's wall particles) and a turning, travelling paddle in 3D (prescribed motion).
//
// One evaluation from particles sorted as the device grid sorts them: each moving particle
// visits its neighbours in the CPU's order and the host sums them in the storage's order, so the
// body loads are the CPU's to round-off. Over a short run the bodies' states and the particles
// stay within round-off that grows over the steps, far below what the bodies moved.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

#include "device/fluid_run.hpp"
#include "device_test_case.hpp"
#include "sph/timestepping.hpp"

namespace {

using namespace num;
using namespace num::sph;

template <int Dim>
struct BodyCase {
    FluidModel<Dim> model;
    FluidGeometry<Dim> geometry;
    RunSettings settings;
    Vector<Dim> shift{};  ///< the body's particles moved by this at the start (contacts)
};

/// A tank of water 0.8 wide (and deep in 3D), 0.32 high, gravity; a ball of radius 2.5 dx at
/// (0.5, 0.1): free and twice as dense as water (its particles moved down 0.3 dx, so that the
/// lowest touch the floor's wall particles, and 0.2 dx along x, so that the loads have a
/// torque about its reference point), or prescribed: travelling at 0.4 m/s and turning at
/// 3 rad/s.
template <int Dim>
BodyCase<Dim> ballInATank(bool free) {
    BodyCase<Dim> c;
    const double dx = Dim == 2 ? 0.04 : 0.08, radius = 2.5 * dx;
    c.geometry.spacing = dx;
    for (int k = 0; k < Dim; ++k) c.geometry.domain.min[k] = 0, c.geometry.domain.max[k] = 0.8;
    c.geometry.domain.max[Dim - 1] = 0.6;
    Vector<Dim> hi = c.geometry.domain.max;
    hi[Dim - 1] = 0.32;
    c.geometry.fluid.push_back(
        FluidRegion<Dim>::filling(BoxOrBall<Dim>::box(c.geometry.domain.min, hi)));
    Vector<Dim> centre = c.geometry.domain.max * 0.5;
    centre[0] = 0.5, centre[Dim - 1] = 0.1;
    SolidBody<Dim> ball;
    ball.shape = BoxOrBall<Dim>::ball(centre, radius);
    c.geometry.bodies.push_back(ball);
    MovingBody<Dim> body;
    body.state.position = body.initialPosition = centre, body.reach = radius;
    if (free) {
        body.motion.type = MotionType::FREE;
        body.motion.mass =
            2000 * (Dim == 2 ? 3.14159 * radius * radius : 4.18879 * radius * radius * radius);
        const double I = (Dim == 2 ? 0.5 : 0.4) * body.motion.mass * radius * radius;
        if constexpr (Dim == 2)
            body.motion.inertia.zz = I;
        else
            body.motion.inertia = Inertia<3>::diagonal(Vector<3>{{I, I, I}});
        c.shift[0] = 0.2 * dx, c.shift[Dim - 1] = -0.3 * dx;
    } else {
        body.motion.type = MotionType::PRESCRIBED;
        body.motion.velocity = [](Float) {
            Vector<Dim> v{};
            v[0] = 0.4;
            return v;
        };
        body.motion.spin = [](Float) {
            Spin<Dim> w{};
            w[Dim == 2 ? 0 : 1] = 3;
            return w;
        };
    }
    c.model.movingBodies = std::make_shared<MovingBodies<Dim>>();
    c.model.movingBodies->bodies.push_back(body);
    device_tests::setDamBreakNumerics(c.model, c.settings, dx);
    return c;
}

/// The case's particles, the body's moved by c.shift (positions and offsets alike).
template <int Dim>
Storage<Dim> storageOf(const BodyCase<Dim>& c) {
    Storage<Dim> s = makeFluidStorage(c.model, c.geometry, c.settings);
    auto x = s.template getValue<Vector<Dim>>(QuantityId::POSITION);
    auto offset = s.template getValue<Vector<Dim>>(QuantityId::BODY_OFFSET);
    const auto body = s.template getValue<int>(QuantityId::BODY_INDEX);
    for (Size i = 0; i < s.size(); ++i)
        if (body[i] >= 0) x[i] += c.shift, offset[i] += c.shift;
    return s;
}

/// A copy of the case with bodies of its own (the CPU run and the device run each move theirs).
template <int Dim>
BodyCase<Dim> withOwnBodies(BodyCase<Dim> c) {
    c.model.movingBodies = std::make_shared<MovingBodies<Dim>>(*c.model.movingBodies);
    return c;
}

template <int N>
double largestOf(const Vec<Float, N>& a) {
    double m = 0;
    for (int k = 0; k < N; ++k) m = std::max(m, std::abs(a[k]));
    return m;
}
template <int N>
double differenceOf(const Vec<Float, N>& a, const Vec<Float, N>& b) {
    return largestOf<N>(a - b);
}

TEST(DeviceBodyStep, OneEvaluationsBodyLoadsAreTheCpus2D) {
    const BodyCase<2> cpuCase = withOwnBodies(ballInATank<2>(true));
    const BodyCase<2> devCase = withOwnBodies(cpuCase);
    ASSERT_EQ(device::unsupported(devCase.model, devCase.geometry, devCase.settings), "");
    const auto config =
        device::makeFluidStepConfig(devCase.model, devCase.geometry, devCase.settings);
    Storage<2> storage = storageOf(cpuCase);
    device_tests::sortAsTheDevice(storage, config);
    SequentialScheduler scheduler;
    Solver<2> solver(scheduler, cpuCase.settings,
                     makeFluidEquations(cpuCase.model, cpuCase.geometry), cpuCase.geometry.domain);
    device::DeviceRun<2> run(std::make_unique<device::HostFluidStep<2>>(config), config);
    run.upload(storage, false);
    solver.evaluate(storage, 0.0);
    run.prime();
    const MovingBody<2>&cpu = cpuCase.model.movingBodies->bodies[0],
          &dev = devCase.model.movingBodies->bodies[0];
    ASSERT_GT(largestOf(cpu.fluidForce), 1.0);    // the water's weight on the ball
    ASSERT_GT(largestOf(cpu.contactForce), 1.0);  // the floor pushes back
    ASSERT_GT(largestOf(cpu.fluidTorque), 1e-6);  // the ball is off the tank's middle
    const double eps = 1e-12;
    std::cout << "relative differences device - cpu: force "
              << differenceOf(dev.fluidForce, cpu.fluidForce) / largestOf(cpu.fluidForce)
              << ", torque "
              << differenceOf(dev.fluidTorque, cpu.fluidTorque) / largestOf(cpu.fluidTorque)
              << ", contact force "
              << differenceOf(dev.contactForce, cpu.contactForce) / largestOf(cpu.contactForce)
              << "\n";
    EXPECT_LE(differenceOf(dev.fluidForce, cpu.fluidForce), eps * largestOf(cpu.fluidForce));
    EXPECT_LE(differenceOf(dev.fluidTorque, cpu.fluidTorque), eps * largestOf(cpu.fluidTorque));
    EXPECT_LE(differenceOf(dev.contactForce, cpu.contactForce), eps * largestOf(cpu.contactForce));
    EXPECT_LE(differenceOf(dev.contactTorque, cpu.contactTorque),
              eps * std::max(largestOf(cpu.contactTorque), 1e-9));
}

/// The CPU run and the device run over the same steps: the body's state and the particles.
template <int Dim>
void compareShortRun(const BodyCase<Dim>& c, int steps) {
    const BodyCase<Dim> cpuCase = withOwnBodies(c), devCase = withOwnBodies(c);
    const auto config =
        device::makeFluidStepConfig(devCase.model, devCase.geometry, devCase.settings);
    Storage<Dim> storage = storageOf(cpuCase);
    device::DeviceRun<Dim> deviceRun(std::make_unique<device::HostFluidStep<Dim>>(config), config);
    deviceRun.upload(storage, false);
    SequentialScheduler scheduler;
    Solver<Dim> solver(scheduler, cpuCase.settings,
                       makeFluidEquations(cpuCase.model, cpuCase.geometry),
                       cpuCase.geometry.domain);
    LeapfrogKDK<Dim> integrator;
    sph::Run<Dim> run(storage, solver, integrator);
    for (int k = 0; k < steps; ++k) {
        const double dtCpu = run.step(), dtDevice = deviceRun.step();
        ASSERT_NEAR(dtDevice, dtCpu, 1e-9 * dtCpu) << "step " << k;
    }
    const BodyState<Dim>&cpu = cpuCase.model.movingBodies->bodies[0].state,
          &dev = devCase.model.movingBodies->bodies[0].state;
    const double moved = differenceOf(cpu.position, c.model.movingBodies->bodies[0].state.position);
    std::cout << "body moved " << moved << " m; device - cpu: position "
              << differenceOf(dev.position, cpu.position) << " m, velocity "
              << differenceOf(dev.velocity, cpu.velocity) << " of " << largestOf(cpu.velocity)
              << " m/s, spin " << differenceOf(dev.spin, cpu.spin) << " of " << largestOf(cpu.spin)
              << " rad/s\n";
    EXPECT_GT(moved, 1e-6);  // the body moved
    EXPECT_LE(differenceOf(dev.position, cpu.position), 1e-6 * moved);
    EXPECT_LE(differenceOf(dev.velocity, cpu.velocity), 1e-6 * largestOf(cpu.velocity));
    EXPECT_LE(differenceOf(dev.spin, cpu.spin), 1e-6 * std::max(largestOf(cpu.spin), 1e-9));
    Storage<Dim> fromDevice = storage;
    deviceRun.download(fromDevice);
    const auto xc = storage.template getValue<Vector<Dim>>(QuantityId::POSITION);
    const auto xd = fromDevice.template getValue<Vector<Dim>>(QuantityId::POSITION);
    const auto wc = storage.template getValue<Vector<Dim>>(QuantityId::WALL_VELOCITY);
    const auto wd = fromDevice.template getValue<Vector<Dim>>(QuantityId::WALL_VELOCITY);
    double dxMax = 0, dwMax = 0, wMax = 0;
    for (Size i = 0; i < storage.size(); ++i) {
        dxMax = std::max(dxMax, norm(xd[i] - xc[i]));
        dwMax = std::max(dwMax, norm(wd[i] - wc[i])), wMax = std::max(wMax, norm(wc[i]));
    }
    std::cout << "particles: largest position difference " << dxMax << " m, wall velocity " << dwMax
              << " of " << wMax << " m/s\n";
    EXPECT_GT(wMax, 1e-6);  // the body's particles move with it
    EXPECT_LE(dxMax, 1e-6 * moved + 1e-12 * c.geometry.spacing);
    EXPECT_LE(dwMax, 1e-6 * wMax);
}

TEST(DeviceBodyStep, AShortRunWithAFreeBodyStaysCloseToTheCpuRun2D) {
    compareShortRun(ballInATank<2>(true), 20);
}
TEST(DeviceBodyStep, AShortRunWithAFreeBodyStaysCloseToTheCpuRun3D) {
    compareShortRun(ballInATank<3>(true), 8);
}
TEST(DeviceBodyStep, AShortRunWithAPrescribedBodyStaysCloseToTheCpuRun2D) {
    compareShortRun(ballInATank<2>(false), 20);
}
TEST(DeviceBodyStep, AShortRunWithAPrescribedBodyStaysCloseToTheCpuRun3D) {
    compareShortRun(ballInATank<3>(false), 6);
}

/// A run stopped, copied back into a storage and continued from it with the bodies' states of
/// the stop (as from a checkpoint) ends bitwise as the uninterrupted run.
TEST(DeviceBodyStep, ARestartFromTheDownloadedStateContinuesBitwise) {
    const BodyCase<2> a = withOwnBodies(ballInATank<2>(true));
    const auto configA = device::makeFluidStepConfig(a.model, a.geometry, a.settings);
    Storage<2> storage = storageOf(a);
    device::DeviceRun<2> first(std::make_unique<device::HostFluidStep<2>>(configA), configA);
    first.upload(storage, false);
    for (int k = 0; k < 6; ++k) first.step();
    first.download(storage);
    const BodyCase<2> b = withOwnBodies(a);  // the states at the stop
    const auto configB = device::makeFluidStepConfig(b.model, b.geometry, b.settings);
    device::DeviceRun<2> second(std::make_unique<device::HostFluidStep<2>>(configB), configB,
                                first.time());
    second.upload(storage, true);
    for (int k = 0; k < 6; ++k) first.step(), second.step();
    const BodyState<2>&sa = a.model.movingBodies->bodies[0].state,
          &sb = b.model.movingBodies->bodies[0].state;
    EXPECT_GT(norm(sa.velocity), 0.1);  // the ball bounced off the floor
    EXPECT_EQ(sa, sb);
    device::ParticleArrays<2> pa, pb;
    first.fluid().download(pa);
    second.fluid().download(pb);
    EXPECT_EQ(pa.x, pb.x);
    EXPECT_EQ(pa.v, pb.v);
    EXPECT_EQ(pa.wallVelocity, pb.wallVelocity);
}

/// A fluid particle that ends a step inside a moving body is reflected out of it in the body's
/// frame, its velocity into the body (relative to the body's) removed, by both engines alike.
TEST(DeviceBodyStep, ContainmentKeepsFluidOutOfAMovingBody) {
    const BodyCase<2> c = ballInATank<2>(false);
    const BodyCase<2> cpuCase = withOwnBodies(c), devCase = withOwnBodies(c);
    const auto config =
        device::makeFluidStepConfig(devCase.model, devCase.geometry, devCase.settings);
    ASSERT_TRUE(config.contain);
    Storage<2> storage = storageOf(cpuCase);
    auto x = storage.getValue<Vector<2>>(QuantityId::POSITION);
    auto v = storage.getDt<Vector<2>>(QuantityId::POSITION);
    const auto kind = storage.getValue<int>(QuantityId::KIND);
    Size moved = 0;
    while (kind[moved] != int(ParticleKind::FLUID)) ++moved;
    const BoxOrBall<2>& ball = c.geometry.bodies[0].shape;
    x[moved] = ball.center + Vector<2>{{0.3 * ball.radius, 0.2 * ball.radius}};
    v[moved] = Vector<2>{{-1.0, -0.5}};  // into the body
    device::DeviceRun<2> deviceRun(std::make_unique<device::HostFluidStep<2>>(config), config);
    deviceRun.upload(storage, false);
    SequentialScheduler scheduler;
    Solver<2> solver(scheduler, cpuCase.settings,
                     makeFluidEquations(cpuCase.model, cpuCase.geometry), cpuCase.geometry.domain);
    LeapfrogKDK<2> integrator;
    sph::Run<2> run(storage, solver, integrator);
    run.step(), deviceRun.step();
    Storage<2> fromDevice = storage;
    deviceRun.download(fromDevice);
    const auto xc = storage.getValue<Vector<2>>(QuantityId::POSITION);
    const auto xd = fromDevice.getValue<Vector<2>>(QuantityId::POSITION);
    const auto vd = fromDevice.getDt<Vector<2>>(QuantityId::POSITION);
    const MovingBodies<2>& bodies = *devCase.model.movingBodies;
    const Vector<2> x0 = bodies.toInitialPose(0, xd[moved]);
    EXPECT_GE(c.geometry.bodies[0].signedDistance(x0), 0);
    EXPECT_GE(
        dot(bodies.bodies[0].state.attitude.rotateBack(vd[moved] - bodies.velocityAt(0, xd[moved])),
            c.geometry.bodies[0].outwardNormal(x0)),
        -1e-12);
    EXPECT_LE(norm(xd[moved] - xc[moved]), 1e-12 * c.geometry.spacing);
}

}  // namespace
