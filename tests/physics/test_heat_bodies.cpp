// Heated bodies in water, conduction only (particles held on a lattice): a fixed-temperature
// body warms its neighbourhood and the heat it gives equals what the water gains; a body
// conducting with its own material (conjugate heat transfer) exchanges heat and conserves it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "test_heat_common.hpp"

using namespace num;
using namespace num::sph;
using namespace num::sph::heat_test;

namespace {

constexpr double dx = 0.02, radius = 0.15, Twater = 20, Tbody = 90;

struct BodyCase {
    std::vector<std::shared_ptr<Material>> mats;
    Storage<2> storage;
    std::shared_ptr<ThermalBoundary<2>> boundary;
};

/// A disc (BODY) in a periodic box of water [-0.5, 0.5]^2; water alpha = 1e-2 (scaled units).
double runBody(ThermalCondition condition, BodyCase& c, double tEnd) {
    c.mats = {thermalMaterial("water", 1e-2, 1, 1), thermalMaterial("copper", 4e-2, 2, 0.5)};
    const auto x = lattice<2>({-0.5, -0.5}, {0.5, 0.5}, dx);
    const auto inBody = [](const Vector<2>& p) { return norm(p) < radius; };
    c.storage = thermalStorage<2>(
        x, dx, c.mats, [&](const Vector<2>& p) { return inBody(p) ? 1 : 0; },
        [&](const Vector<2>& p) { return inBody(p) ? Tbody : Twater; },
        [&](const Vector<2>& p) { return inBody(p) ? ParticleKind::BODY : ParticleKind::FLUID; });
    Domain<2> domain;
    domain.min = {-0.5, -0.5};
    domain.max = {0.5, 0.5};
    domain.periodic = {true, true};
    c.boundary = std::make_shared<ThermalBoundary<2>>(ThermalCondition::ADIABATIC, condition);
    SequentialScheduler scheduler;
    Solver<2> solver(scheduler, heatSettings(dx, 1.3, "cubic_spline"),
                     makeTerm<HeatConduction<2>>() + EquationHolder<2>(c.boundary), domain);
    solver.create(c.storage, *c.mats[0]);
    PredictorCorrector<2> integrator;
    sph::Run<2> run(c.storage, solver, integrator);
    const double heat0 = totalHeat(c.storage);
    run.advanceTo(tEnd);
    return heat0;
}

}  // namespace

TEST(HeatBodies, FixedTemperatureBodyWarmsWaterWithEnergyBalance) {
    const double tEnd = 0.5;  // diffusion length 2 sqrt(alpha t) = 0.14
    BodyCase c;
    runBody(ThermalCondition::FIXED_TEMPERATURE, c, tEnd);
    const Storage<2>& s = c.storage;
    const auto x = s.getValue<Vector<2>>(QuantityId::POSITION);
    const auto T = s.getValue<double>(QuantityId::TEMPERATURE);
    const auto kind = s.getValue<int>(QuantityId::KIND);
    double nearMin = Tbody, farMax = Twater, waterGain = 0;
    ValidationResult result;
    result.name = "heat_fixed_body";
    for (Size i = 0; i < s.size(); ++i) {
        const double r = norm(x[i]);
        if (kind[i] == int(ParticleKind::BODY)) {
            EXPECT_EQ(T[i], Tbody) << "the body keeps its temperature";
            continue;
        }
        // Maximum principle: water stays between its initial and the body's temperature.
        EXPECT_GE(T[i], Twater - 1e-9);
        EXPECT_LE(T[i], Tbody + 1e-9);
        if (r < radius + 1.5 * dx) nearMin = std::min(nearMin, T[i]);
        if (r > 0.45) farMax = std::max(farMax, T[i]);
        waterGain += s.getValue<double>(QuantityId::MASS)[i] * 1.0 * (T[i] - Twater);
        if (std::abs(x[i][1] - 0.5 * dx) < 1e-9 && x[i][0] > 0)
            result.profile.push_back({r, T[i], 0});
    }
    // Water next to the body is well above 20 degC (the first layer sits dx from the surface,
    // diffusion length 7 dx: it is at least half-way to the body temperature), and the far
    // water has barely changed (erfc(0.3 / 0.14) = 2e-3 of the difference).
    EXPECT_GT(nearMin, Twater + 0.5 * (Tbody - Twater));
    EXPECT_LT(farMax, Twater + 0.01 * (Tbody - Twater));
    // Energy balance: the heat the body gave (trapezoidal books) is what the water gained, to
    // round-off of the sums (relative 1e-10).
    const double given = c.boundary->books().heatFromFixed();
    EXPECT_GT(given, 0);
    EXPECT_NEAR(waterGain, given, 1e-10 * given);

    // The profile has no closed form (a disc held hot in a periodic box); "analytic" holds the
    // body temperature for reference, the error is the energy balance mismatch.
    for (ProfileRow& r : result.profile) r.analytic = r.coordinate < radius ? Tbody : Twater;
    std::sort(result.profile.begin(), result.profile.end(),
              [](const ProfileRow& a, const ProfileRow& b) { return a.coordinate < b.coordinate; });
    result.resolution = "50^2, disc R = 7.5 dx";
    result.error = std::abs(waterGain - given) / given;
    result.tolerance = 1e-10;
    result.passed = result.error < result.tolerance && nearMin > Twater + 0.5 * (Tbody - Twater);
    result.notes =
        "relative mismatch of the water's heat gain and the heat given by the fixed "
        "body; profile: water temperature against distance from the centre (analytic "
        "column: initial temperatures)";
    result.write();
}

TEST(HeatBodies, ConductingBodyExchangesAndConservesHeat) {
    BodyCase c;
    const double heat0 = runBody(ThermalCondition::CONDUCTING, c, 0.5);
    const Storage<2>& s = c.storage;
    const auto T = s.getValue<double>(QuantityId::TEMPERATURE);
    const auto kind = s.getValue<int>(QuantityId::KIND);
    double bodyMax = 0, waterMax = 0;
    for (Size i = 0; i < s.size(); ++i) {
        if (kind[i] == int(ParticleKind::BODY))
            bodyMax = std::max(bodyMax, T[i]);
        else
            waterMax = std::max(waterMax, T[i]);
    }
    EXPECT_LT(bodyMax, Tbody) << "the conducting body cools";
    EXPECT_GT(waterMax, Twater + 1) << "the water warms";
    EXPECT_LE(waterMax, bodyMax);
    // Nothing fixed, no source: sum m c T is conserved to round-off.
    EXPECT_NEAR(totalHeat(s), heat0, 1e-12 * heat0);
    EXPECT_EQ(c.boundary->books().heatFromFixed(), 0.0);
}
