// Particle set-up and boundary bookkeeping of the fluid model: wall layers cover the kernel
// support, kinds and normals are right, bodies displace fluid, periodic lengths are checked,
// summation density of a full lattice is rho0 times the lattice sum, and boundary particles
// stay fixed.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "fluid_test_support.hpp"

using namespace num::sph;
using namespace num::sph::fluid_test;

namespace {
FluidGeometry<2> boxWithBody(double dx) {
    FluidGeometry<2> g;
    g.spacing = dx;
    g.domain.max = Vector<2>{{1, 1}};
    g.fluid.push_back(FluidRegion<2>::filling(BoxOrBall<2>::box(g.domain.min, g.domain.max)));
    SolidBody<2> body;
    body.shape = BoxOrBall<2>::ball(Vector<2>{{0.5, 0.5}}, 0.2);
    g.bodies.push_back(body);
    return g;
}
}  // namespace

TEST(FluidSetup, WallLayersAndKinds) {
    const double dx = 0.05;
    const FluidGeometry<2> g = boxWithBody(dx);
    const RunSettings s = settingsFor(dx);  // cubic spline, support 2.6 dx -> 3 layers
    FluidModel<2> model;
    const Storage<2> st = makeFluidStorage(model, g, s);
    const auto x = st.getValue<Vector<2>>(QuantityId::POSITION);
    const auto kind = st.getValue<int>(QuantityId::KIND);
    int fluid = 0, wall = 0, body = 0;
    for (Size i = 0; i < st.size(); ++i) {
        if (kind[i] == int(ParticleKind::FLUID)) {
            ++fluid;
            EXPECT_GE(norm(x[i] - Vector<2>{{0.5, 0.5}}), 0.2);
        } else if (kind[i] == int(ParticleKind::WALL)) {
            ++wall;
            EXPECT_TRUE(x[i][0] < 0 || x[i][0] > 1 || x[i][1] < 0 || x[i][1] > 1);
        } else {
            ++body;
            EXPECT_LT(norm(x[i] - Vector<2>{{0.5, 0.5}}), 0.2);
        }
    }
    // (20 + 2 * 3)^2 - 20^2 wall particles; body and fluid share the 400 interior points.
    EXPECT_EQ(wall, 26 * 26 - 400);
    EXPECT_EQ(fluid + body, 400);
    EXPECT_GT(body, 0);
}

TEST(FluidSetup, PeriodicLengthMustBeMultipleOfSpacing) {
    FluidGeometry<2> g;
    g.spacing = 0.3;
    g.domain.max = Vector<2>{{1, 1}};
    g.domain.periodic = {true, false};
    EXPECT_THROW(generateParticles(g, 3), std::invalid_argument);
}

TEST(FluidSetup, SummationDensityOfFullLatticeAndFixedBoundaries) {
    const double dx = 0.05;
    FluidGeometry<2> g = boxWithBody(dx);
    FluidModel<2> model;
    model.density = DensityMode::SUMMATION;
    model.maxVelocity = 1;
    model.bodyForce = constantForce(Vector<2>{{0, -9.81}});
    FluidCase<2> c(model, g, settingsFor(dx));
    // Boundary positions, sorted (the run reorders particles by cell).
    auto boundaryPositions = [&] {
        std::vector<std::array<double, 2>> out;
        for (Size i = 0; i < c.storage.size(); ++i)
            if (!isFluid(c.kind()[i])) out.push_back({c.x()[i][0], c.x()[i][1]});
        std::sort(out.begin(), out.end());
        return out;
    };
    const auto start = boundaryPositions();
    c.run->prime();
    const auto rho = c.storage.getValue<Float>(QuantityId::DENSITY);
    const auto kind = c.kind();
    // Every fluid particle has a full support (walls and body fill it): rho = rho0 times the
    // cubic spline's 2D lattice sum at h = 1.3 dx, 0.999947 (reference_solutions.md sec. 1).
    for (Size i = 0; i < c.storage.size(); ++i) {
        if (isFluid(kind[i])) {
            EXPECT_NEAR(rho[i] / 1000.0, 0.999947, 1e-5);
        }
    }
    c.run->advanceTo(0.05);
    EXPECT_GT(c.run->steps(), 25u);  // at least one reordering happened
    EXPECT_EQ(boundaryPositions(), start);
}

TEST(FluidSetup, SlidingLidIsNoMassSource) {
    // Lid-driven cavity with the fluid at rest: the lid's sliding velocity is a no-slip
    // condition, not a motion of its particles, so no fluid density changes. When the
    // continuity equation saw the lid's velocity, the wall corners (split along the diagonal
    // between lid and side walls) made the top corners a source and a sink of mass:
    // drho/dt = -0.45 and +2.5 rho0 U / L at 25 x 25 (continuity_density.hpp).
    const double dx = 0.04;
    FluidGeometry<2> g;
    g.spacing = dx;
    g.domain.max = Vector<2>{{1, 1}};
    g.walls[1][1].velocity = Vector<2>{{1, 0}};
    g.fluid.push_back(FluidRegion<2>::filling(BoxOrBall<2>::box(g.domain.min, g.domain.max)));
    FluidModel<2> model;
    model.restDensity = 1;
    model.maxVelocity = 1;
    model.viscosity = 0.001;
    FluidCase<2> c(model, g, settingsFor(dx, 1.5, "wendland_c2"));
    c.run->prime();
    const auto drho = c.storage.getDt<Float>(QuantityId::DENSITY);
    const auto kind = c.kind();
    double largest = 0;
    for (Size i = 0; i < c.storage.size(); ++i)
        if (isFluid(kind[i])) largest = std::max(largest, std::abs(drho[i]));
    EXPECT_LT(largest, 1e-12);
}

TEST(EquationOfState, TaitPowerBySquaringAgreesWithPow) {
    // power() multiplies for whole exponents: within a few units in the last place of std::pow
    // (four roundings for gamma = 7), exactly pow otherwise.
    const double ulp = std::numeric_limits<double>::epsilon();
    for (double x = 0.5; x < 1.5; x += 0.0137)
        for (double gamma : {1.0, 2.0, 7.0, 16.0})
            EXPECT_NEAR(num::sph::power(x, gamma) / std::pow(x, gamma), 1.0, 8 * ulp)
                << "x " << x << ", gamma " << gamma;
    for (double gamma : {1.4, 7.5, 17.0})
        EXPECT_EQ(num::sph::power(1.1, gamma), std::pow(1.1, gamma));
    num::sph::EquationOfState tait;
    EXPECT_EQ(tait.pressure(tait.rho0), 0.0);
    EXPECT_NEAR(tait.pressure(1.01 * tait.rho0) / (tait.stiffness() * (std::pow(1.01, 7) - 1)), 1.0,
                1e-13);
}
