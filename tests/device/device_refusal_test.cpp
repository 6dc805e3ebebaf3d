// The device refuses by construction: a model runs on the device step only if every term of its
// CPU equations is one the device implements (device/device_terms.hpp); any other term is
// refused by its name, without a list of what the device lacks.
#include <gtest/gtest.h>

#include "device/fluid_run.hpp"
#include "geometry/primitives.hpp"

namespace {

using namespace num;
using namespace num::sph;

/// A 2D tank of water with gravity: the device runs all of it.
FluidGeometry<2> tank() {
    FluidGeometry<2> g;
    g.spacing = 0.05;
    g.domain.min = {{0, 0}}, g.domain.max = {{1, 1}};
    g.fluid.push_back(FluidRegion<2>::filling(BoxOrBall<2>::box({{0, 0}}, {{0.5, 0.5}})));
    return g;
}

FluidModel<2> water() {
    FluidModel<2> m;
    m.bodyForce = constantForce(Vector<2>{{0, -9.81}});
    m.maxVelocity = 3;
    m.viscosity = 1e-6;
    m.heat.conduction = true;
    return m;
}

/// A drag a user adds to the CPU engine: the device has no kernel for it.
class Drag : public IEquationTerm<2> {
  public:
    void setDerivatives(DerivativeHolder<2>&, const RunSettings&) override {}
    void initialize(IScheduler&, Storage<2>&, Float) override {}
    void finalize(IScheduler&, Storage<2>&, Float) override {}
    void create(Storage<2>&, IMaterial&) const override {}
    std::string name() const override { return "drag"; }
};

/// A built-in term changed by a subclass: not the term the device implements.
class SofterPressure : public PressureGradient<2> {};

std::string refusal(const FluidModel<2>& model, const FluidGeometry<2>& geometry = tank()) {
    return device::unsupported(model, geometry, RunSettings());
}

TEST(DeviceRefusal, RunsTheDefaultFluidWithHeat) { EXPECT_EQ(refusal(water()), ""); }

TEST(DeviceRefusal, RefusesATermAddedOnTheCpuByItsName) {
    FluidModel<2> m = water();
    m.extraTerms += makeTerm<Drag>();
    EXPECT_EQ(refusal(m), "the equation term \"drag\"");
}

TEST(DeviceRefusal, RefusesASubclassOfABuiltInTerm) {
    FluidModel<2> m = water();
    m.extraTerms += makeTerm<SofterPressure>();
    EXPECT_NE(refusal(m).find("SofterPressure"), std::string::npos) << refusal(m);
}

TEST(DeviceRefusal, RunsDensityBySummation) {
    FluidModel<2> m = water();
    m.density = DensityMode::SUMMATION;
    EXPECT_EQ(refusal(m), "");
}

/// Moving bodies (the rigid body coupling term): a free box and a prescribed paddle.
TEST(DeviceRefusal, RunsMovingBodies) {
    FluidGeometry<2> g = tank();
    FluidModel<2> m = water();
    m.movingBodies = std::make_shared<MovingBodies<2>>();
    for (const double x : {0.6, 0.8}) {
        SolidBody<2> body;
        body.shape = BoxOrBall<2>::box({{x, 0.6}}, {{x + 0.1, 0.7}});
        g.bodies.push_back(body);
        MovingBody<2> moving;
        moving.motion.type = x < 0.7 ? MotionType::FREE : MotionType::PRESCRIBED;
        moving.motion.mass = 5, moving.motion.inertia.zz = 0.01;
        moving.motion.velocity = [](Float) { return Vector<2>{{0.1, 0}}; };
        moving.motion.spin = [](Float) { return Spin<2>{{1}}; };
        moving.state.position = moving.initialPosition = Vector<2>{{x + 0.05, 0.65}};
        m.movingBodies->bodies.push_back(moving);
    }
    EXPECT_EQ(refusal(m, g), "");
}

TEST(DeviceRefusal, RunsWallsInsideTheDomain) {
    FluidGeometry<2> g = tank();
    InteriorWall<2> wall;
    wall.shape = BoxOrBall<2>::box({{0.7, 0}}, {{0.8, 0.2}});
    g.interiorWalls.push_back(wall);
    wall.solid = std::make_shared<geometry::Ball<2>>(Vector<2>{{0.2, 0.8}}, 0.1);
    g.interiorWalls.push_back(wall);
    EXPECT_EQ(refusal(water(), g), "");
}

/// A solid the device cannot evaluate (as a triangle mesh): refused by its place in the scene.
class Blob : public geometry::Solid<2> {
  public:
    double signedDistance(const geometry::Point<2>& x) const override { return norm(x) - 0.1; }
    geometry::Bounds<2> bounds() const override { return {}; }
};

TEST(DeviceRefusal, RefusesASolidItCannotEvaluateByItsPlace) {
    FluidGeometry<2> g = tank();
    InteriorWall<2> wall;
    wall.solid = std::make_shared<Blob>();
    g.interiorWalls.push_back(wall);
    EXPECT_EQ(refusal(water(), g),
              "the shape of walls[0] (a mesh, or a solid flatten() does not take)");
}

}  // namespace
