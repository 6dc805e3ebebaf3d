// Conservation of heat by the conduction operator (reference_solutions.md section 5): the pair
// terms are antisymmetric, so with adiabatic boundaries the total sum m c T changes only by
// round-off; a flux wall adds exactly its power.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test_heat_common.hpp"

using namespace num;
using namespace num::sph;
using namespace num::sph::heat_test;

namespace {

/// Two materials in a box of particles with random temperatures and jittered positions,
/// surrounded by three layers of wall particles.
Storage<2> mixedBox(double dx, std::vector<std::shared_ptr<Material>>& mats) {
    mats = {thermalMaterial("a", 1.0, 1.0, 1.0), thermalMaterial("b", 3.0, 2.0, 0.5)};
    auto x = lattice<2>({-3 * dx, -3 * dx}, {1 + 3 * dx, 1 + 3 * dx}, dx);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> jitter(-0.2 * dx, 0.2 * dx), temp(0, 100);
    const auto inside = [](const Vector<2>& p) {
        return p[0] > 0 && p[0] < 1 && p[1] > 0 && p[1] < 1;
    };
    for (auto& p : x)
        if (inside(p)) p += Vector<2>{{jitter(rng), jitter(rng)}};
    Storage<2> s = thermalStorage<2>(
        x, dx, mats, [](const Vector<2>& p) { return p[0] < 0.5 ? 0 : 1; },
        [&](const Vector<2>&) { return temp(rng); },
        [&](const Vector<2>& p) { return inside(p) ? ParticleKind::FLUID : ParticleKind::WALL; });
    return s;
}

double driftWithAdiabaticWalls(const std::string& evaluation) {
    const double dx = 0.025;
    std::vector<std::shared_ptr<Material>> mats;
    Storage<2> s = mixedBox(dx, mats);
    RunSettings rs = heatSettings(dx);
    rs.set("evaluation", evaluation);
    Domain<2> domain;
    SequentialScheduler scheduler;
    Solver<2> solver(
        scheduler, rs,
        makeTerm<HeatConduction<2>>() + makeTerm<ThermalBoundary<2>>(ThermalCondition::ADIABATIC),
        domain);
    solver.create(s, *mats[0]);
    const std::vector<double> T0(s.getValue<double>(QuantityId::TEMPERATURE).begin(),
                                 s.getValue<double>(QuantityId::TEMPERATURE).end());
    const double heat0 = totalHeat(s);
    LeapfrogKDK<2> integrator;
    sph::Run<2> run(s, solver, integrator);
    for (int k = 0; k < 200; ++k) run.step();
    const auto T = s.getValue<double>(QuantityId::TEMPERATURE);
    const auto kind = s.getValue<int>(QuantityId::KIND);
    double change = 0;
    for (Size i = 0; i < s.size(); ++i) {
        if (kind[i] == int(ParticleKind::WALL))
            EXPECT_EQ(T[i], T0[i]) << "adiabatic walls";
        else
            change = std::max(change, std::abs(T[i] - T0[i]));
    }
    EXPECT_GT(change, 10.0) << "the temperatures must have evolved";
    return std::abs(totalHeat(s) - heat0) / heat0;
}

}  // namespace

TEST(HeatConservation, TotalHeatToRoundOffWithAdiabaticWalls) {
    // 200 steps of a few additions of O(1e-16) relative each: 1e-12 bounds round-off and
    // nothing else (one lost pair term would be ~1e-5).
    const double symmetric = driftWithAdiabaticWalls("symmetric");
    const double asymmetric = driftWithAdiabaticWalls("asymmetric");
    EXPECT_LT(symmetric, 1e-12);
    EXPECT_LT(asymmetric, 1e-12);

    ValidationResult result;
    result.name = "heat_conservation";
    result.resolution = "40^2 jittered, two materials, adiabatic walls, 200 steps";
    result.error = std::max(symmetric, asymmetric);
    result.tolerance = 1e-12;
    result.passed = result.error < result.tolerance;
    std::ostringstream notes;
    notes << "relative change of sum m c T; symmetric evaluation " << symmetric << ", asymmetric "
          << asymmetric;
    result.notes = notes.str();
    result.profile = {{0, symmetric, 0}, {1, asymmetric, 0}};
    result.write();
}

TEST(HeatConservation, FluxWallAddsExactlyItsPower) {
    const double dx = 0.025, flux = 50.0, t = 0.02;
    std::vector<std::shared_ptr<Material>> mats;
    Storage<2> s = mixedBox(dx, mats);
    Domain<2> domain;
    SequentialScheduler scheduler;
    auto boundary = std::make_shared<ThermalBoundary<2>>(ThermalCondition::ADIABATIC);
    Solver<2> solver(scheduler, heatSettings(dx),
                     makeTerm<HeatConduction<2>>() + EquationHolder<2>(boundary), domain);
    solver.create(s, *mats[0]);
    // The innermost wall layer under the bottom side heats the box through its length 1.
    const auto x = s.getValue<Vector<2>>(QuantityId::POSITION);
    ThermalBoundary<2>::setHeatFlux(s, flux, 1.0, [&](Size i) {
        return x[i][1] < 0 && x[i][1] > -dx && x[i][0] > 0 && x[i][0] < 1;
    });
    const double heat0 = totalHeat(s);
    PredictorCorrector<2> integrator;
    sph::Run<2> run(s, solver, integrator);
    run.advanceTo(t);
    const double added = totalHeat(s) - heat0;
    // Exact power q'' A = 50 W over t: the books and the particles agree to round-off.
    EXPECT_NEAR(added, flux * 1.0 * t, 1e-9 * heat0);
    EXPECT_NEAR(boundary->books().heatFromSources(), flux * 1.0 * t, 1e-12 * flux * t);
}
