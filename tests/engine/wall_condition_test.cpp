// The wall condition (sph/boundary/generalized_wall.hpp) against its equations summed by brute
// force: every boundary particle's pressure, density and pair velocity, bit for bit, those with
// fluid neighbours and those without (which it gives the values of an empty sum without a
// gather), before and after the fluid moves next to walls it was far from.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "numerics.hpp"
#include "sph/fluid_model.hpp"

namespace {

using namespace num::sph;
using Vec = Vector<2>;

/// Water in the lower half of a walled box under gravity, with a sliding lid: the lid and the
/// upper side walls are far from the water.
struct HalfTank {
    static constexpr double dx = 0.05;
    FluidModel<2> model;
    FluidGeometry<2> geometry;
    RunSettings settings;
    Storage<2> storage;

    HalfTank() {
        model.maxVelocity = 1;
        model.bodyForce = [](Float) { return Vec{{0, -9.81}}; };
        geometry.spacing = dx;
        geometry.domain.max = {{1.0, 1.0}};
        for (int k = 0; k < 2; ++k) geometry.walls[k][0] = geometry.walls[k][1] = WallSide<2>{};
        geometry.walls[1][1].velocity = Vec{{0.5, 0.0}};
        geometry.fluid.push_back(
            FluidRegion<2>::filling(BoxOrBall<2>::box({{0.0, 0.0}}, {{1.0, 0.5}})));
        settings.set("smoothing_length", 1.3 * dx);
        storage = makeFluidStorage(model, geometry, settings);
        auto v = storage.getDt<Vec>(QuantityId::POSITION);
        const auto x = storage.getValue<Vec>(QuantityId::POSITION);
        for (Size i = 0; i < storage.size(); ++i) v[i] = Vec{{0.1 * x[i][1], -0.05 * x[i][0]}};
    }
};

/// Every boundary particle against eq. 22, 23, 27 and 28 of Adami et al. (2012) summed over all
/// fluid particles within the support radius, in increasing index (the gather's order).
struct WallCheck {
    std::size_t withoutFluid = 0;  // boundary particles with no fluid neighbour
    std::size_t wrong = 0;         // boundary particles whose values differ, bitwise
    std::vector<char> nearFluid;   // per particle: a boundary particle with fluid neighbours
};

WallCheck checkTheWallEquations(const Storage<2>& s, const Solver<2>& solver,
                                const HalfTank& tank) {
    const auto x = s.getValue<Vec>(QuantityId::POSITION);
    const auto v = s.getDt<Vec>(QuantityId::POSITION);
    const auto kind = s.getValue<int>(QuantityId::KIND);
    const auto p = s.getValue<Float>(QuantityId::PRESSURE);
    const auto rho = s.getValue<Float>(QuantityId::DENSITY);
    const auto vb = s.getValue<Vec>(FluidId::PAIR_VELOCITY);
    const auto wallVelocity = s.getValue<Vec>(QuantityId::WALL_VELOCITY);
    const EquationOfState eos = tank.model.equationOfState();
    const Vec g = tank.model.bodyForce(0.0);
    const double radius = solver.kernel().supportRadius();
    WallCheck check;
    check.nearFluid.assign(s.size(), 0);
    for (Size w = 0; w < s.size(); ++w) {
        if (isFluid(kind[w])) continue;
        Float sumW = 0, sumP = 0;
        Vec sumRhoR{}, sumV{};
        for (Size f = 0; f < s.size(); ++f) {
            const Vec dx = x[w] - x[f];
            const double r2 = num::normSqr(dx);
            if (!isFluid(kind[f]) || !(r2 < radius * radius)) continue;
            const Float W = solver.kernel().W(std::sqrt(r2));
            sumW += W, sumP += p[f] * W, sumRhoR += dx * (rho[f] * W), sumV += v[f] * W;
        }
        check.withoutFluid += sumW == 0;
        check.nearFluid[w] = sumW > 0;
        const Float pw = sumW > 0 ? (sumP + dot(g, sumRhoR)) / sumW : eos.backgroundPressure;
        const Vec vw = sumW > 0 ? wallVelocity[w] * 2.0 - sumV / sumW : wallVelocity[w];
        const bool same =
            p[w] == pw && rho[w] == eos.density(pw) && vb[w][0] == vw[0] && vb[w][1] == vw[1];
        if (!same && check.wrong++ == 0)
            ADD_FAILURE() << "boundary particle " << w << " (sum W " << sumW << "): p " << p[w]
                          << " against " << pw << ", v (" << vb[w][0] << ", " << vb[w][1]
                          << ") against (" << vw[0] << ", " << vw[1] << ")";
    }
    return check;
}

TEST(WallCondition, EveryBoundaryParticleHasItsEquationsValues) {
    HalfTank tank;
    Storage<2>& s = tank.storage;
    SequentialScheduler scheduler;
    Solver<2> solver(scheduler, tank.settings, makeFluidEquations(tank.model, tank.geometry),
                     tank.geometry.domain);
    solver.evaluate(s, 0.0);
    const WallCheck before = checkTheWallEquations(s, solver, tank);
    EXPECT_EQ(before.wrong, 0u);
    EXPECT_GT(before.withoutFluid, 20u) << "the lid and the upper side walls: no fluid near";

    // The water raised next to the lid: the lists are rebuilt, and the boundary particles with
    // fluid neighbours found again.
    auto x = s.getValue<Vec>(QuantityId::POSITION);
    const auto kind = s.getValue<int>(QuantityId::KIND);
    for (Size i = 0; i < s.size(); ++i)
        if (isFluid(kind[i])) x[i][1] += 0.5;
    const std::size_t builds = solver.neighbours().builds();
    solver.evaluate(s, 0.0);
    EXPECT_GT(solver.neighbours().builds(), builds);
    const WallCheck after = checkTheWallEquations(s, solver, tank);
    EXPECT_EQ(after.wrong, 0u);
    EXPECT_GT(after.withoutFluid, 20u) << "the floor and the lower side walls: no fluid near";
    EXPECT_NE(after.nearFluid, before.nearFluid) << "other boundary particles near the water";
}

}  // namespace
