// The per-particle inputs of the pair terms (terms/pair_inputs.hpp): prepared once per
// evaluation, after the wall condition, and read by every term that needs them; a set of terms
// without PairInputs is refused with a message that names it.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "numerics.hpp"
#include "sph/fluid_model.hpp"

namespace {

using namespace num::sph;

/// Water filling a walled box with a moving lid (unless lidSpeed is 0), so that wall particles
/// show a velocity of their own (2 v_wall - v~) and the volumes of wall particles come from the
/// wall condition's densities.
struct LidTank {
    static constexpr double dx = 0.05;
    FluidModel<2> model;
    FluidGeometry<2> geometry;
    RunSettings settings;
    Storage<2> storage;

    explicit LidTank(double lidSpeed = 1.0) {
        model.maxVelocity = 1;
        model.viscosity = 1e-2;
        model.bodyForce = [](Float) { return Vector<2>{{0, -9.81}}; };
        geometry.spacing = dx;
        geometry.domain.max = {{1.0, 1.0}};
        for (int k = 0; k < 2; ++k) geometry.walls[k][0] = geometry.walls[k][1] = WallSide<2>{};
        geometry.walls[1][1].velocity = Vector<2>{{lidSpeed, 0.0}};
        geometry.fluid.push_back(
            FluidRegion<2>::filling(BoxOrBall<2>::box({{0.0, 0.0}}, {{1.0, 1.0}})));
        settings.set("smoothing_length", 1.5 * dx);
        storage = makeFluidStorage(model, geometry, settings);
        auto v = storage.getDt<Vector<2>>(QuantityId::POSITION);
        const auto x = storage.getValue<Vector<2>>(QuantityId::POSITION);
        for (Size i = 0; i < storage.size(); ++i)
            v[i] = Vector<2>{{0.1 * x[i][1], -0.05 * x[i][0]}};
    }
};

TEST(PairInputs, VolumesAndPairVelocitiesAreThoseOfTheWallCondition) {
    LidTank tank;
    SequentialScheduler scheduler;
    Solver<2> solver(scheduler, tank.settings, makeFluidEquations(tank.model, tank.geometry),
                     tank.geometry.domain);
    Storage<2>& s = tank.storage;
    solver.evaluate(s, 0.0);

    // The passes: the wall condition, then PairInputs, then the terms that read what it prepares.
    const std::string passes = solver.schedule().describe(solver.equations().names());
    const auto wall = passes.find("GeneralizedWall"), inputs = passes.find("PairInputs");
    ASSERT_NE(wall, std::string::npos) << passes;
    ASSERT_NE(inputs, std::string::npos) << passes;
    EXPECT_LT(wall, inputs) << passes;
    for (const char* reader : {"ContinuityDensity", "DeltaSph", "LaminarViscosity",
                               "ArtificialViscosity", "ParticleShifting"})
        EXPECT_LT(inputs, passes.find(reader)) << reader << " before PairInputs:\n" << passes;

    const auto m = s.getValue<Float>(QuantityId::MASS);
    const auto rho = s.getValue<Float>(QuantityId::DENSITY);
    const auto v = s.getDt<Vector<2>>(QuantityId::POSITION);
    const auto kind = s.getValue<int>(QuantityId::KIND);
    const auto volume = s.getValue<Float>(FluidId::VOLUME);
    const auto velocity = s.getValue<Vector<2>>(FluidId::PAIR_VELOCITY);
    const auto x = s.getValue<Vector<2>>(QuantityId::POSITION);
    const auto wallVelocity = s.getValue<Vector<2>>(QuantityId::WALL_VELOCITY);
    const RunKernel<2> kernel(tank.settings);
    Size walls = 0, lid = 0;
    for (Size i = 0; i < s.size(); ++i) {
        ASSERT_EQ(volume[i], m[i] / rho[i]) << i;  // bitwise: the same division
        if (isFluid(kind[i])) {
            ASSERT_EQ(std::memcmp(&velocity[i], &v[i], sizeof v[i]), 0) << i;
            continue;
        }
        // Brute-force oracle of the wall condition's no-slip velocity, 2 v_wall - v~ with v~
        // the Shepard mean of the fluid velocities (Adami et al. 2012, eq. 22-23); v_wall where
        // no fluid is within reach. 1e-12: the sums' order differs from the neighbour list's.
        Float sumW = 0;
        Vector<2> sumV{};
        for (Size f = 0; f < s.size(); ++f) {
            const Float r = num::norm(x[i] - x[f]);
            if (!isFluid(kind[f]) || r >= kernel.supportRadius()) continue;
            sumW += kernel.W(r), sumV += v[f] * kernel.W(r);
        }
        const Vector<2> expected = sumW > 0 ? wallVelocity[i] * 2.0 - sumV / sumW : wallVelocity[i];
        for (int k = 0; k < 2; ++k) ASSERT_NEAR(velocity[i][k], expected[k], 1e-12) << i;
        ++walls, lid += velocity[i][0] > 1.5;  // under the lid (v_wall = 1)
    }
    EXPECT_GT(walls, 0u);
    EXPECT_GT(lid, 0u) << "no wall particle shows the lid's velocity";
}

// With every wall held, the storage keeps no wall velocities (WALL_VELOCITY is absent) and the
// wall particles' pair velocities are -v~, bitwise 2 * 0 - v~ as with an array of zeros.
TEST(PairInputs, HeldWallsNeedNoWallVelocities) {
    LidTank held(0.0), sliding;
    EXPECT_FALSE(held.storage.has(QuantityId::WALL_VELOCITY));
    EXPECT_TRUE(sliding.storage.has(QuantityId::WALL_VELOCITY));
    LidTank zeros(0.0);  // the same tank with an explicit array of zero wall velocities
    zeros.storage.insert<Vector<2>>(QuantityId::WALL_VELOCITY, OrderEnum::ZERO, Vector<2>{});
    SequentialScheduler scheduler;
    for (LidTank* t : {&held, &zeros}) {
        Solver<2> solver(scheduler, t->settings, makeFluidEquations(t->model, t->geometry),
                         t->geometry.domain);
        solver.evaluate(t->storage, 0.0);
    }
    const auto a = held.storage.getValue<Vector<2>>(FluidId::PAIR_VELOCITY);
    const auto b = zeros.storage.getValue<Vector<2>>(FluidId::PAIR_VELOCITY);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof a[0]), 0);
    const auto kind = held.storage.getValue<int>(QuantityId::KIND);
    Size moving = 0;
    for (Size i = 0; i < a.size(); ++i) moving += !isFluid(kind[i]) && normSqr(a[i]) > 0;
    EXPECT_GT(moving, 0u) << "no wall particle mirrors the fluid's velocity";
}

TEST(PairInputs, TermsThatReadThemWithoutItAreRefusedByName) {
    LidTank tank;
    SequentialScheduler scheduler;
    const EquationOfState eos = tank.model.equationOfState();
    EquationHolder<2> eq = makeTerm<EquationOfStateTerm<2>>(eos);
    eq += makeTerm<ArtificialViscosity<2>>(0.1, eos.c0);
    try {
        Solver<2> solver(scheduler, tank.settings, std::move(eq), tank.geometry.domain);
        FAIL() << "a solver without PairInputs";
    } catch (const std::logic_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("ArtificialViscosity"), std::string::npos) << what;
        EXPECT_NE(what.find("PairInputs"), std::string::npos) << what;
    }
    // With it, added before the term, the same set is accepted.
    EquationHolder<2> fixed = makeTerm<EquationOfStateTerm<2>>(eos);
    fixed += makeTerm<PairInputs<2>>();
    fixed += makeTerm<ArtificialViscosity<2>>(0.1, eos.c0);
    EXPECT_NO_THROW(Solver<2>(scheduler, tank.settings, std::move(fixed), tank.geometry.domain));
}

}  // namespace
