// Validation: two semi-infinite slabs in contact (reference_solutions.md section 5). Particles
// fixed on a lattice, 1D-like in 2D (periodic in y). T = T_L for x < 0 and T_R for x > 0 at t = 0;
// the exact solution keeps the interface at T_c = (e_L T_L + e_R T_R) / (e_L + e_R), e = sqrt(k rho
// c), with an erf profile on each side. Gate (reference_solutions.md section 5): max error below 1
// % of the jump |T_L - T_R|, mean below 0.3 %.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "test_heat_common.hpp"

using namespace num;
using namespace num::sph;
using namespace num::sph::heat_test;

namespace {

struct Slab {
    double k, rho, c;
    double alpha() const { return k / (rho * c); }
    double effusivity() const { return std::sqrt(k * rho * c); }
};

/// The exact two-slab solution at time t > 0.
double slabExact(double x, double t, const Slab& L, const Slab& R, double TL, double TR) {
    const double eL = L.effusivity(), eR = R.effusivity();
    const double Tc = (eL * TL + eR * TR) / (eL + eR);
    if (x < 0) return Tc + (TL - Tc) * std::erf(-x / (2 * std::sqrt(L.alpha() * t)));
    return Tc + (TR - Tc) * std::erf(x / (2 * std::sqrt(R.alpha() * t)));
}

struct SlabErrors {
    double maxError, meanError, interface;
};

/// Runs the slabs to t = 0.01 at spacing dx and returns errors relative to the jump.
/// Kernel: the cubic spline with h = 1.3 dx, whose lattice Brookshaw Laplacian is exact to
/// 1e-3 (reference_solutions.md section 1 table); Wendland C2 is checked at h = 2 dx.
SlabErrors runSlabs(const std::string& name, const Slab& L, const Slab& R, double dx,
                    const std::string& kernel = "cubic_spline", double hOverDx = 1.3) {
    const double TL = 1, TR = 0, tEnd = 0.01, halfWidth = 0.6;
    const int ny = 8;  // periodic y: at least twice the support radius 2.6 dx
    const auto x = lattice<2>({-halfWidth, 0}, {halfWidth, ny * dx}, dx);
    std::vector<std::shared_ptr<Material>> mats = {thermalMaterial("left", L.k, L.rho, L.c),
                                                   thermalMaterial("right", R.k, R.rho, R.c)};
    Storage<2> s = thermalStorage<2>(
        x, dx, mats, [](const Vector<2>& p) { return p[0] < 0 ? 0 : 1; },
        [&](const Vector<2>& p) { return p[0] < 0 ? TL : TR; });

    Domain<2> domain;
    domain.min = {-halfWidth, 0};
    domain.max = {halfWidth, ny * dx};
    domain.periodic = {false, true};
    SequentialScheduler scheduler;
    Solver<2> solver(scheduler, heatSettings(dx, hOverDx, kernel), makeTerm<HeatConduction<2>>(),
                     domain);
    solver.create(s, *mats[0]);
    PredictorCorrector<2> integrator;
    Run<2> run(s, solver, integrator);
    run.advanceTo(tEnd);

    // Profile along x, averaged over the particles of one column (all equal by symmetry).
    const auto xs = s.getValue<Vector<2>>(QuantityId::POSITION);
    const auto T = s.getValue<double>(QuantityId::TEMPERATURE);
    std::map<long, std::pair<double, int>> columns;
    for (Size i = 0; i < s.size(); ++i) {
        auto& col = columns[std::lround(xs[i][0] / dx * 2)];
        col.first += T[i], col.second += 1;
    }
    ValidationResult result;
    result.name = name;
    double maxErr = 0, sumErr = 0, interface = 0;
    for (const auto& [key, col] : columns) {
        const double xc = key * dx / 2, Tn = col.first / col.second;
        const double Ta = slabExact(xc, tEnd, L, R, TL, TR);
        const double err = std::abs(Tn - Ta) / std::abs(TL - TR);
        maxErr = std::max(maxErr, err);
        sumErr += err;
        if (std::abs(xc) < dx) interface += 0.5 * Tn;  // the two columns at x = -dx/2, +dx/2
        result.profile.push_back({xc, Tn, Ta, tEnd});
    }
    const double meanErr = sumErr / double(columns.size());
    result.resolution = std::to_string(int(std::lround(2 * halfWidth / dx))) + " x " +
                        std::to_string(ny) + " (dx = " + std::to_string(dx) + ")";
    result.error = maxErr;
    result.tolerance = 0.01;
    result.passed = maxErr < 0.01 && meanErr < 0.003;
    std::ostringstream notes;
    notes << "max error / |T_L - T_R| at t = " << tEnd << "; mean error " << meanErr
          << " (gate 0.003); k_R / k_L = " << R.k / L.k << "; " << run.steps() << " steps; kernel "
          << kernel << ", h = " << hOverDx << " dx";
    result.notes = notes.str();
    result.write();
    return {maxErr, meanErr, interface};
}

}  // namespace

// The analytic reference itself reproduces the values of reference_solutions.md section 5.
TEST(HeatSlabs, ExactSolutionMatchesReferenceValues) {
    const Slab unit{1, 1, 1}, doubled{2, 1, 1};
    EXPECT_NEAR(slabExact(-0.1, 0.01, unit, unit, 1, 0), 0.76025, 1e-5);
    EXPECT_NEAR(slabExact(0.05, 0.01, unit, unit, 1, 0), 0.361837, 1e-6);
    EXPECT_NEAR(slabExact(0.2, 0.01, unit, unit, 1, 0), 0.07865, 1e-5);
    EXPECT_NEAR(slabExact(-0.1, 0.01, unit, doubled, 1, 0), 0.719115, 1e-6);
    EXPECT_NEAR(slabExact(0.1, 0.01, unit, doubled, 1, 0), 0.255601, 1e-6);
    EXPECT_NEAR(slabExact(1e-12, 0.01, unit, doubled, 1, 0), 0.414214, 1e-6);
}

TEST(HeatSlabs, EqualMaterialsFollowErfProfile) {
    const double dx = fullResolution() ? 0.005 : 0.01;
    const Slab unit{1, 1, 1};
    const SlabErrors e = runSlabs("heat_slabs_equal", unit, unit, dx);
    // Gate of reference_solutions.md section 5: max below 1 % of the jump, mean below 0.3 %.
    EXPECT_LT(e.maxError, 0.01);
    EXPECT_LT(e.meanError, 0.003);
    // The interface stays at T_c = 1/2 (mean of the two columns beside it, which the erf
    // profile puts within 1 % of the jump of T_c at this resolution).
    EXPECT_NEAR(e.interface, 0.5, 0.01);
}

TEST(HeatSlabs, DoubleConductivityKeepsInterfaceTemperature) {
    const double dx = fullResolution() ? 0.005 : 0.01;
    const Slab left{1, 1, 1}, right{2, 1, 1};
    const SlabErrors e = runSlabs("heat_slabs_k2", left, right, dx);
    // Same gate; the harmonic-mean conductivity is what keeps the interface at
    // T_c = 1 / (1 + sqrt 2) = 0.414214 (an arithmetic mean would not).
    EXPECT_LT(e.maxError, 0.01);
    EXPECT_LT(e.meanError, 0.003);
    EXPECT_NEAR(e.interface, 1 / (1 + std::sqrt(2.0)), 0.01);
}

// The engine's default kernel, Wendland C2, needs a wider support for the same accuracy: at
// h = 1.3 dx its lattice Laplacian underestimates the diffusivity by about 1 % (max error near
// 0.5 % of the jump, not converging with dx at fixed h/dx); at h = 2 dx it is well inside the gate.
TEST(HeatSlabs, WendlandKernelMeetsGate) {
    const double dx = fullResolution() ? 0.005 : 0.01;
    const Slab unit{1, 1, 1};
    const SlabErrors e = runSlabs("heat_slabs_equal_wendland", unit, unit, dx, "wendland_c2", 2.0);
    // Gate of reference_solutions.md section 5.
    EXPECT_LT(e.maxError, 0.01);
    EXPECT_LT(e.meanError, 0.003);
}
