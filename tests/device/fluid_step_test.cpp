// The device step of the fluid (include/device/fluid_step.hpp), run by the host execution: the
// functors the CUDA kernels launch, in plain loops, against the CPU engine (sph::Solver and
// sph::Run with the fluid model's terms) on small 2D and 3D dam breaks and a periodic channel.
//
// Bitwise where the order of operations is the CPU's: the particles are first sorted as the
// device grid sorts them, so that both visit every particle's neighbours in the same order (no
// periodic wrap): then every single term's sum (pressure, density of walls, kernel sums, the
// shifting sums) is the CPU's bit for bit. The rates that add several terms (acceleration: the
// pressure gradient, artificial and laminar viscosity, gravity; density: continuity and
// delta-SPH) differ in round-off only: the CPU adds each term's sum into one register in turn,
// the device step keeps each term's sum apart and adds the sums at the end.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>

#include "device/fluid_run.hpp"
#include "device_test_case.hpp"
#include "geometry/combination.hpp"
#include "geometry/primitives.hpp"
#include "sph/timestepping.hpp"

namespace {

using namespace num;
using namespace num::sph;
using device::ParticleArrays;

template <int Dim>
struct Case {
    FluidModel<Dim> model;
    FluidGeometry<Dim> geometry;
    RunSettings settings;
    std::function<void(Storage<Dim>&)> prepare;  ///< changes to the particles made (or none)
    Storage<Dim> storage() const {
        Storage<Dim> s = makeFluidStorage(model, geometry, settings);
        if (prepare) prepare(s);
        return s;
    }
};

/// A dam break: a block of water in the corner of a closed tank, gravity, the default numerics
/// (delta-SPH, shifting, tension limit) with artificial and laminar viscosity; periodicX: a
/// channel periodic in x instead, water filling the lower part; body: a solid ball (boundary
/// particles of kind BODY) in the water's path.
template <int Dim>
Case<Dim> damBreak(bool periodicX = false, bool body = false) {
    Case<Dim> c;
    const double dx = Dim == 2 ? 0.04 : 0.08;
    c.geometry.spacing = dx;
    for (int k = 0; k < Dim; ++k) c.geometry.domain.min[k] = 0, c.geometry.domain.max[k] = 0.8;
    c.geometry.domain.max[Dim - 1] = 0.6;
    Vector<Dim> hi = c.geometry.domain.max;
    hi[0] = periodicX ? 0.8 : 0.32, hi[Dim - 1] = 0.32;
    c.geometry.domain.periodic[0] = periodicX;
    if (body) {
        Vector<Dim> centre = c.geometry.domain.max * 0.5;
        centre[0] = 0.5, centre[Dim - 1] = 0.12;
        SolidBody<Dim> ball;
        ball.shape = BoxOrBall<Dim>::ball(centre, 2.5 * dx);
        c.geometry.bodies.push_back(ball);
    }
    c.geometry.fluid.push_back(
        FluidRegion<Dim>::filling(BoxOrBall<Dim>::box(c.geometry.domain.min, hi)));
    if (periodicX)  // a flow along the channel
        c.geometry.fluid.back().velocity = [](const Vector<Dim>& x) {
            Vector<Dim> v{};
            v[0] = 0.5 * x[Dim - 1];
            return v;
        };
    device_tests::setDamBreakNumerics(c.model, c.settings, dx);
    return c;
}

/// The dam break with its body and heat: water at 50 C, the body at 90 C, the box's walls at
/// 20 C, each with its thermal condition (bodies fixed or conducting, walls fixed or adiabatic);
/// conduction raised so that the diffusion limit can limit the step (diffusionLimited),
/// Boussinesq buoyancy and the exponential temperature-dependent viscosity.
template <int Dim>
Case<Dim> heatedDamBreak(ThermalCondition walls, ThermalCondition bodies,
                         bool diffusionLimited = false) {
    Case<Dim> c = damBreak<Dim>(false, true);
    c.geometry.fluid[0].temperature = 50;
    c.geometry.bodies[0].temperature = 90;
    c.model.heat.conduction = true;
    c.model.heat.walls = walls, c.model.heat.bodies = bodies;
    c.model.heat.buoyancy = true;
    c.model.heat.temperatureViscosity = true;
    auto water = std::make_shared<Material>("water");
    water->params()
        .set("density", c.model.restDensity)
        .set("sound_speed", c.model.c0())
        .set("viscosity", c.model.viscosity)
        .set("artificial_viscosity", c.model.artificialViscosity)
        .set("conductivity", diffusionLimited ? 2e7 : 2e4)
        .set("thermal_expansion", 2e-3)
        .set("reference_temperature", 20.0);
    c.model.materials = {water};
    return c;
}

template <class V>
double largest(const std::vector<V>& v) {
    double m = 0;
    for (const V& e : v) {
        if constexpr (std::is_arithmetic_v<V>)
            m = std::max(m, std::abs(double(e)));
        else
            m = std::max(m, norm(e));
    }
    return m;
}

template <int Dim>
ParticleArrays<Dim> stateOf(const Storage<Dim>& s) {
    ParticleArrays<Dim> p = device::particleArrays(s);
    p.volume = std::vector<Float>(s.template getValue<Float>(FluidId::VOLUME).begin(),
                                  s.template getValue<Float>(FluidId::VOLUME).end());
    auto vec = [&](QuantityId id) {
        const auto v = s.template getValue<Vector<Dim>>(id);
        return std::vector<Vector<Dim>>(v.begin(), v.end());
    };
    p.kernelSumGradient = vec(FluidId::KERNEL_SUM_GRADIENT);
    p.densityGradient = vec(FluidId::DENSITY_GRADIENT);
    p.wallDirection = vec(FluidId::WALL_DIRECTION);
    for (int b = 0; b < Dim; ++b) p.velocityGradient[b] = vec(velocityGradientId<Dim>(b));
    return p;
}

#define EXPECT_SAME(a, b, what)                                                       \
    do {                                                                              \
        ASSERT_EQ((a).size(), (b).size()) << what;                                    \
        std::size_t differ = 0;                                                       \
        for (std::size_t i = 0; i < (a).size(); ++i) differ += !((a)[i] == (b)[i]);   \
        EXPECT_EQ(differ, 0u) << what << ": particles that differ of " << (a).size(); \
    } while (0)

template <class V>
double largestDifference(const std::vector<V>& a, const std::vector<V>& b) {
    double m = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if constexpr (std::is_arithmetic_v<V>)
            m = std::max(m, std::abs(double(a[i] - b[i])));
        else
            m = std::max(m, norm(a[i] - b[i]));
    }
    return m;
}

/// Two evaluations (the second with the first's kernel sums: the tension limit and the surface
/// flags act) by the CPU solver and by the device step, from the same particles.
/// Boundary particles that conduct gather their neighbours in the CPU engine's fused pair pass,
/// which then also leaves the fluid's kernel and shifting sums on them; nothing reads those (the
/// free-surface test and shifting are the fluid's), and the device step leaves them zero.
template <int Dim>
void clearBoundarySums(ParticleArrays<Dim>& cpu) {
    for (std::size_t i = 0; i < cpu.size(); ++i) {
        if (cpu.kind[i] == int(ParticleKind::FLUID)) continue;
        cpu.kernelSum[i] = 0, cpu.surfaceNeighbours[i] = 0;
        cpu.kernelSumGradient[i] = {}, cpu.densityGradient[i] = {}, cpu.wallDirection[i] = {};
        for (int b = 0; b < Dim; ++b) cpu.velocityGradient[b][i] = {};
    }
}

template <int Dim>
void compareOneEvaluation(const Case<Dim>& c) {
    const bool periodicX = c.geometry.domain.periodic[0];
    const auto config = device::makeFluidStepConfig(c.model, c.geometry, c.settings);
    ASSERT_EQ(device::unsupported(c.model, c.geometry, c.settings), "");
    Storage<Dim> storage = c.storage();
    device_tests::sortAsTheDevice(storage, config);
    SequentialScheduler scheduler;
    Solver<Dim> solver(scheduler, c.settings, makeFluidEquations(c.model, c.geometry),
                       c.geometry.domain);
    device::HostFluidStep<Dim> step(config);
    step.upload(device::particleArrays(storage));
    solver.evaluate(storage, 0.0);
    step.evaluate(0.0);
    solver.evaluate(storage, 0.01);
    step.evaluate(0.01);
    ParticleArrays<Dim> cpu = stateOf(storage);
    ParticleArrays<Dim> dev;
    step.download(dev);
    if (c.model.heat.conduction) clearBoundarySums(cpu);

    EXPECT_GT(largest(cpu.a), 1.0);  // the case has accelerations to compare
    EXPECT_GT(largest(cpu.kernelSumGradient), 0.0);
    if (!periodicX) {  // the same neighbour order: bitwise
        EXPECT_SAME(dev.x, cpu.x, "positions");
        EXPECT_SAME(dev.p, cpu.p, "pressure (equation of state, tension limit, walls)");
        EXPECT_SAME(dev.rho, cpu.rho, "density (tension limit, walls)");
        EXPECT_SAME(dev.pairVelocity, cpu.pairVelocity, "pair velocity (walls)");
        EXPECT_SAME(dev.volume, cpu.volume, "volume");
        EXPECT_SAME(dev.kernelSum, cpu.kernelSum, "kernel sum");
        EXPECT_SAME(dev.surfaceNeighbours, cpu.surfaceNeighbours, "surface neighbours");
        EXPECT_SAME(dev.kernelSumGradient, cpu.kernelSumGradient, "kernel sum gradient");
        EXPECT_SAME(dev.densityGradient, cpu.densityGradient, "density gradient");
        EXPECT_SAME(dev.wallDirection, cpu.wallDirection, "wall direction");
        for (int b = 0; b < Dim; ++b)
            EXPECT_SAME(dev.velocityGradient[b], cpu.velocityGradient[b], "velocity gradient");
        EXPECT_SAME(dev.nu, cpu.nu, "viscosity");
        EXPECT_SAME(dev.T, cpu.T, "temperature");
        EXPECT_SAME(dev.dT, cpu.dT, "temperature rate (conduction, thermal conditions)");
        EXPECT_SAME(dev.Tb, cpu.Tb, "temperature shown to conduction (walls)");
    }
    if (c.model.heat.conduction) {
        EXPECT_GT(largest(cpu.dT), 0.0);  // heat flows
        EXPECT_LE(largestDifference(dev.dT, cpu.dT), 1e-12 * largest(cpu.dT));
    }
    // Round-off: relative to the largest value of each.
    const double eps = periodicX ? 1e-9 : 1e-12;
    EXPECT_LE(largestDifference(dev.a, cpu.a), eps * largest(cpu.a));
    EXPECT_LE(largestDifference(dev.drho, cpu.drho), eps * largest(cpu.drho));
    EXPECT_LE(largestDifference(dev.p, cpu.p), eps * largest(cpu.p));
    EXPECT_LE(largestDifference(dev.kernelSum, cpu.kernelSum), eps);
    EXPECT_LE(largestDifference(dev.kernelSumGradient, cpu.kernelSumGradient),
              eps * largest(cpu.kernelSumGradient));
}

TEST(DeviceFluidStep, OneEvaluationMatchesTheCpuSolver2D) { compareOneEvaluation(damBreak<2>()); }
TEST(DeviceFluidStep, OneEvaluationMatchesTheCpuSolver3D) { compareOneEvaluation(damBreak<3>()); }
TEST(DeviceFluidStep, OneEvaluationMatchesTheCpuSolverOnAPeriodicChannel) {
    compareOneEvaluation(damBreak<2>(true));
}
TEST(DeviceFluidStep, OneEvaluationMatchesTheCpuSolverWithABody2D) {
    compareOneEvaluation(damBreak<2>(false, true));
}
TEST(DeviceFluidStep, OneEvaluationMatchesTheCpuSolverWithABody3D) {
    compareOneEvaluation(damBreak<3>(false, true));
}
TEST(DeviceFluidStep, OneEvaluationMatchesTheCpuSolverWithHeat2D) {
    compareOneEvaluation(heatedDamBreak<2>(ThermalCondition::FIXED_TEMPERATURE,
                                           ThermalCondition::FIXED_TEMPERATURE));
}
/// A heater plate on the floor (HEAT_FLUX: a heat source on the wall particles) and the
/// temperature-dependent viscosity of water (Vogel's law).
Case<2> heatedFromBelow() {
    Case<2> c = heatedDamBreak<2>(ThermalCondition::ADIABATIC, ThermalCondition::FIXED_TEMPERATURE);
    c.model.heat.viscosityLaw.law = ViscosityLaw::WATER_VOGEL;
    c.prepare = [](Storage<2>& s) {
        const auto x = s.getValue<Vector<2>>(QuantityId::POSITION);
        const auto kind = s.getValue<int>(QuantityId::KIND);
        ThermalBoundary<2>::setHeatFlux(
            s, 5e4, 0.8, [&](Size i) { return kind[i] == int(ParticleKind::WALL) && x[i][1] < 0; });
    };
    return c;
}
TEST(DeviceFluidStep, OneEvaluationMatchesTheCpuSolverWithAHeaterAndWaterViscosity) {
    compareOneEvaluation(heatedFromBelow());
}
TEST(DeviceFluidStep, OneEvaluationMatchesTheCpuSolverWithHeat3D) {
    compareOneEvaluation(
        heatedDamBreak<3>(ThermalCondition::ADIABATIC, ThermalCondition::CONDUCTING));
}

/// The dam break with density by summation (no continuity, no delta-SPH; the shifting moves no
/// density).
/// The dam break's tank as a channel with an inlet and an outlet (boundary/flow_boundaries.hpp):
/// water along the whole of it flowing along x, an inlet on x_min imposing 0.5 m/s and an outlet
/// on x_max holding p = 50 + 200 y, an expression of the place that the device step evaluates on
/// the host.
template <int Dim>
Case<Dim> channelWithInletAndOutlet() {
    Case<Dim> c = damBreak<Dim>(true);
    c.geometry.domain.periodic[0] = false;
    const double dx = c.geometry.spacing;
    const double depth = wallLayersFor(RunKernel<Dim>(c.settings).supportRadius(), dx) * dx;
    FlowSide<Dim> inlet, outlet;
    inlet.kind = ParticleKind::INLET, inlet.axis = 0, inlet.high = 0, inlet.depth = depth;
    inlet.plane = c.geometry.domain.min[0];
    inlet.velocity = [](const Vector<Dim>&, Float) {
        Vector<Dim> v{};
        v[0] = 0.5;
        return v;
    };
    outlet.kind = ParticleKind::OUTLET, outlet.axis = 0, outlet.high = 1, outlet.depth = depth;
    outlet.plane = c.geometry.domain.max[0];
    outlet.pressure = [](const Vector<Dim>& x, Float) { return 50 + 200 * x[Dim - 1]; };
    auto flow = std::make_shared<FlowBoundaries<Dim>>();
    flow->sides = {inlet, outlet};
    c.model.flowBoundaries = flow;
    c.geometry.walls[0][0].layers = ParticleKind::INLET;
    c.geometry.walls[0][1].layers = ParticleKind::OUTLET;
    c.prepare = [flow](Storage<Dim>& s) {
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        ASSERT_GT(std::count(kind.begin(), kind.end(), int(ParticleKind::OUTLET)), 0);
        flow->prepare(s, 0.0);
    };
    return c;
}
TEST(DeviceFluidStep, OneEvaluationMatchesTheCpuSolverWithAnInletAndAnOutlet2D) {
    compareOneEvaluation(channelWithInletAndOutlet<2>());
}
TEST(DeviceFluidStep, OneEvaluationMatchesTheCpuSolverWithAnInletAndAnOutlet3D) {
    compareOneEvaluation(channelWithInletAndOutlet<3>());
}

template <int Dim>
Case<Dim> summationDamBreak() {
    Case<Dim> c = damBreak<Dim>();
    c.model.density = DensityMode::SUMMATION;
    return c;
}
TEST(DeviceFluidStep, OneEvaluationMatchesTheCpuSolverWithDensityBySummation2D) {
    compareOneEvaluation(summationDamBreak<2>());
}
TEST(DeviceFluidStep, OneEvaluationMatchesTheCpuSolverWithDensityBySummation3D) {
    compareOneEvaluation(summationDamBreak<3>());
}

/// The CPU run and the device step's run over the same steps.
template <int Dim>
void compareShortRun(const Case<Dim>& c, int steps) {
    const auto config = device::makeFluidStepConfig(c.model, c.geometry, c.settings);
    Storage<Dim> storage = c.storage();
    device::DeviceRun<Dim> deviceRun(std::make_unique<device::HostFluidStep<Dim>>(config), config);
    deviceRun.upload(storage, false);
    SequentialScheduler scheduler;
    Solver<Dim> solver(scheduler, c.settings, makeFluidEquations(c.model, c.geometry),
                       c.geometry.domain);
    LeapfrogKDK<Dim> integrator;
    sph::Run<Dim> run(storage, solver, integrator);
    for (int k = 0; k < steps; ++k) {
        const double dtCpu = run.step(), dtDevice = deviceRun.step();
        ASSERT_NEAR(dtDevice, dtCpu, 1e-9 * dtCpu) << "step " << k;
        ASSERT_EQ(deviceRun.limitingCriterion(), run.limitingCriterion());
    }
    EXPECT_NEAR(deviceRun.time(), run.time(), 1e-9 * run.time());
    Storage<Dim> fromDevice = storage;
    deviceRun.download(fromDevice);
    const ParticleArrays<Dim> cpu = stateOf(storage), dev = stateOf(fromDevice);
    const double dx = c.geometry.spacing;
    double moved = 0;
    const ParticleArrays<Dim> start = device::particleArrays(c.storage());
    moved = largestDifference(cpu.x, start.x);
    EXPECT_GT(moved, 1e-3 * dx);  // the particles moved
    // Round-off grows over the steps, but stays far below what the flow moved them.
    EXPECT_LE(largestDifference(dev.x, cpu.x), 1e-6 * moved);
    EXPECT_LE(largestDifference(dev.v, cpu.v), 1e-6 * largest(cpu.v));
    EXPECT_LE(largestDifference(dev.rho, cpu.rho), 1e-9 * c.model.restDensity);
    if (c.model.heat.conduction) {
        const double warmed = largestDifference(cpu.T, start.T);
        EXPECT_GT(warmed, 1e-3);  // heat flowed
        EXPECT_LE(largestDifference(dev.T, cpu.T), 1e-9 * warmed);
        EXPECT_LE(largestDifference(dev.nu, cpu.nu), 1e-9 * largest(cpu.nu));
    }
}

TEST(DeviceFluidStep, AShortRunStaysCloseToTheCpuRun2D) { compareShortRun(damBreak<2>(), 20); }
TEST(DeviceFluidStep, AShortRunStaysCloseToTheCpuRun3D) { compareShortRun(damBreak<3>(), 8); }
TEST(DeviceFluidStep, AShortRunStaysCloseToTheCpuRunOnAPeriodicChannel) {
    compareShortRun(damBreak<2>(true), 20);
}
TEST(DeviceFluidStep, AShortRunStaysCloseToTheCpuRunWithABody2D) {
    compareShortRun(damBreak<2>(false, true), 20);
}
TEST(DeviceFluidStep, AShortRunStaysCloseToTheCpuRunWithABody3D) {
    compareShortRun(damBreak<3>(false, true), 8);
}
TEST(DeviceFluidStep, AShortRunStaysCloseToTheCpuRunWithHeat2D) {
    compareShortRun(
        heatedDamBreak<2>(ThermalCondition::FIXED_TEMPERATURE, ThermalCondition::FIXED_TEMPERATURE),
        20);
}
TEST(DeviceFluidStep, AShortRunStaysCloseToTheCpuRunWithHeat3D) {
    compareShortRun(heatedDamBreak<3>(ThermalCondition::ADIABATIC, ThermalCondition::CONDUCTING),
                    8);
}
TEST(DeviceFluidStep, AShortRunStaysCloseToTheCpuRunWithAHeater) {
    compareShortRun(heatedFromBelow(), 20);
}
TEST(DeviceFluidStep, AShortRunStaysCloseToTheCpuRunWithDensityBySummation) {
    compareShortRun(summationDamBreak<2>(), 20);
}
/// Conduction fast enough that the diffusion limit sets the step: the same limit, the same
/// steps.
TEST(DeviceFluidStep, TheDiffusionLimitIsTheCpuRunsLimit) {
    const Case<2> c =
        heatedDamBreak<2>(ThermalCondition::FIXED_TEMPERATURE, ThermalCondition::CONDUCTING, true);
    const auto config = device::makeFluidStepConfig(c.model, c.geometry, c.settings);
    Storage<2> storage = c.storage();
    device::DeviceRun<2> deviceRun(std::make_unique<device::HostFluidStep<2>>(config), config);
    deviceRun.upload(storage, false);
    SequentialScheduler scheduler;
    Solver<2> solver(scheduler, c.settings, makeFluidEquations(c.model, c.geometry),
                     c.geometry.domain);
    LeapfrogKDK<2> integrator;
    sph::Run<2> run(storage, solver, integrator);
    for (int k = 0; k < 5; ++k) {
        const double dtCpu = run.step(), dtDevice = deviceRun.step();
        EXPECT_EQ(run.limitingCriterion(), "diffusion");
        EXPECT_EQ(deviceRun.limitingCriterion(), "diffusion");
        EXPECT_NEAR(dtDevice, dtCpu, 1e-12 * dtCpu) << "step " << k;
    }
}

/// A fluid particle that ends a step inside a body is reflected out of it, its velocity into
/// the body removed, by both engines alike.
/// One step of the CPU run and the device step from particles where one fluid particle sits
/// at `inside` in `solid` (a body or a wall of the case), moving into it: both reflect it out,
/// the same way.
void checkContainment(const Case<2>& c, const PlacedShape<2>& solid, const Vector<2>& inside) {
    const auto config = device::makeFluidStepConfig(c.model, c.geometry, c.settings);
    ASSERT_TRUE(config.contain);
    Storage<2> storage = c.storage();
    auto x = storage.getValue<Vector<2>>(QuantityId::POSITION);
    auto v = storage.getDt<Vector<2>>(QuantityId::POSITION);
    const auto kind = storage.getValue<int>(QuantityId::KIND);
    Size moved = 0;
    while (kind[moved] != int(ParticleKind::FLUID)) ++moved;
    x[moved] = inside;
    v[moved] = Vector<2>{{-1.0, -0.5}};  // into the solid
    ASSERT_LT(solid.signedDistance(x[moved]), 0);
    device::DeviceRun<2> deviceRun(std::make_unique<device::HostFluidStep<2>>(config), config);
    deviceRun.upload(storage, false);
    SequentialScheduler scheduler;
    Solver<2> solver(scheduler, c.settings, makeFluidEquations(c.model, c.geometry),
                     c.geometry.domain);
    LeapfrogKDK<2> integrator;
    sph::Run<2> run(storage, solver, integrator);
    run.step(), deviceRun.step();
    Storage<2> fromDevice = storage;
    deviceRun.download(fromDevice);
    const ParticleArrays<2> cpu = stateOf(storage), dev = stateOf(fromDevice);
    EXPECT_GE(solid.signedDistance(cpu.x[moved]), 0);
    EXPECT_GE(solid.signedDistance(dev.x[moved]), 0);
    EXPECT_GE(dot(dev.v[moved], solid.outwardNormal(dev.x[moved])), -1e-12);
    EXPECT_LE(largestDifference(dev.x, cpu.x), 1e-9 * c.geometry.spacing);
    EXPECT_LE(largestDifference(dev.v, cpu.v), 1e-9 * largest(cpu.v));
}

TEST(DeviceFluidStep, ContainmentKeepsFluidOutOfBodies) {
    const Case<2> c = damBreak<2>(false, true);
    const BoxOrBall<2>& ball = c.geometry.bodies[0].shape;
    checkContainment(c, c.geometry.bodies[0],
                     ball.center + Vector<2>{{0.3 * ball.radius, 0.2 * ball.radius}});
}

/// The dam break with a wall inside the box of a general shape: a tilted plate with a round
/// notch (a turned box minus a disc), flattened for the device.
Case<2> damBreakWithATiltedWall() {
    Case<2> c = damBreak<2>();
    InteriorWall<2> wall;
    const auto plate = geometry::rotatedBox<2>(Vector<2>{{0.55, 0.15}}, Vector<2>{{0.12, 0.03}},
                                               geometry::Rotation<2>(geometry::Angles<2>{{23.0}}));
    const auto notch = std::make_shared<geometry::Ball<2>>(Vector<2>{{0.62, 0.2}}, 0.04);
    wall.solid = std::make_shared<geometry::Combination<2>>(
        geometry::Combine::DIFFERENCE, std::vector<geometry::SolidPtr<2>>{plate, notch});
    wall.solidBounds = wall.solid->bounds();
    c.geometry.interiorWalls.push_back(wall);
    return c;
}

TEST(DeviceFluidStep, ContainmentKeepsFluidOutOfAWallOfAnyShape) {
    const Case<2> c = damBreakWithATiltedWall();
    ASSERT_EQ(device::unsupported(c.model, c.geometry, c.settings), "");
    checkContainment(c, c.geometry.interiorWalls[0], Vector<2>{{0.5, 0.13}});
}

TEST(DeviceFluidStep, AShortRunStaysCloseToTheCpuRunWithAWallOfAnyShape) {
    compareShortRun(damBreakWithATiltedWall(), 20);
}

template <int Dim>
ParticleArrays<Dim> deviceRunOf(const Case<Dim>& c, int steps) {
    const auto config = device::makeFluidStepConfig(c.model, c.geometry, c.settings);
    Storage<Dim> storage = c.storage();
    device::DeviceRun<Dim> run(std::make_unique<device::HostFluidStep<Dim>>(config), config);
    run.upload(storage, false);
    for (int k = 0; k < steps; ++k) run.step();
    ParticleArrays<Dim> p;
    run.fluid().download(p);
    return p;
}

TEST(DeviceFluidStep, TwoRunsAreBitwiseIdentical) {
    const Case<2> c = damBreak<2>();
    const ParticleArrays<2> a = deviceRunOf(c, 15), b = deviceRunOf(c, 15);
    EXPECT_SAME(a.x, b.x, "positions");
    EXPECT_SAME(a.v, b.v, "velocities");
    EXPECT_SAME(a.rho, b.rho, "densities");
    EXPECT_SAME(a.a, b.a, "accelerations");
}

/// A run stopped, copied back into a storage and continued from it (as from a checkpoint)
/// ends bitwise as the uninterrupted run; and the CPU engine continues the device's state.
TEST(DeviceFluidStep, ARestartFromTheDownloadedStateContinuesBitwise) {
    const Case<2> c = damBreak<2>();
    const auto config = device::makeFluidStepConfig(c.model, c.geometry, c.settings);
    Storage<2> storage = c.storage();
    device::DeviceRun<2> first(std::make_unique<device::HostFluidStep<2>>(config), config);
    first.upload(storage, false);
    for (int k = 0; k < 6; ++k) first.step();
    first.download(storage);
    device::DeviceRun<2> second(std::make_unique<device::HostFluidStep<2>>(config), config,
                                first.time());
    second.upload(storage, true);
    for (int k = 0; k < 6; ++k) first.step(), second.step();
    ParticleArrays<2> a, b;
    first.fluid().download(a);
    second.fluid().download(b);
    EXPECT_SAME(a.x, b.x, "positions");
    EXPECT_SAME(a.v, b.v, "velocities");
    EXPECT_SAME(a.rho, b.rho, "densities");
    EXPECT_EQ(first.time(), second.time());

    // The CPU engine continues from the device's state (primed: the rates are current).
    second.download(storage);
    SequentialScheduler scheduler;
    Solver<2> solver(scheduler, c.settings, makeFluidEquations(c.model, c.geometry),
                     c.geometry.domain);
    LeapfrogKDK<2> integrator;
    sph::Run<2> cpu(storage, solver, integrator, second.time());
    cpu.markPrimed(true);
    const double dtCpu = cpu.step(), dtDevice = second.step();
    EXPECT_NEAR(dtCpu, dtDevice, 1e-9 * dtCpu);
    ParticleArrays<2> after;
    second.fluid().download(after);
    EXPECT_LE(largestDifference(stateOf(storage).x, after.x), 1e-9 * c.geometry.spacing);
}

}  // namespace
