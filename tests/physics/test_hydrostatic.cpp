// Hydrostatic tank (reference_solutions.md sec. 6): water at rest in a 2D tank with no-slip walls
// on three sides and a free surface, gravity ramped in over the first second. The generalised wall
// condition (Adami, Hu & Adams 2012) must hold p = rho0 g (H - y) in the interior, with no drift of
// the surface, kinetic energy settling, and no particle crossing a wall. The containment safety net
// is switched off here, so the wall condition alone keeps the fluid in.
#include <gtest/gtest.h>

#include "fluid_test_support.hpp"

using namespace num::sph;
using namespace num::sph::fluid_test;

namespace {

constexpr double H = 1.0, width = 1.0, g = 9.81, rho0 = 1000, ramp = 1.0;
constexpr double pScale = rho0 * g * H;

/// Water at rest, gravity ramped in, no containment: the wall condition alone keeps it in.
FluidModel<2> tankModel() {
    FluidModel<2> model;
    model.restDensity = rho0;
    model.maxVelocity = std::sqrt(2 * g * H);  // c0 = 10 sqrt(2 g H)
    model.artificialViscosity = 0.02;          // damps the sloshing of the start-up
    model.bodyForce = rampedForce(Vector<2>{{0, -g}}, ramp);
    model.containParticles = false;
    return model;
}

/// A tank open at the top, filled to the brim at spacing dx.
FluidGeometry<2> tankGeometry(double dx) {
    FluidGeometry<2> geo;
    geo.spacing = dx;
    geo.domain.max = Vector<2>{{width, H}};
    geo.walls[1][1].present = false;  // open top: free surface
    geo.fluid.push_back(FluidRegion<2>::filling(BoxOrBall<2>::box(geo.domain.min, geo.domain.max)));
    return geo;
}

/// What the gate reads: the interior pressure's errors and the speed at the last sample, the
/// largest surface drift and the smallest wall gap over all samples.
struct TankState {
    double maxError = 0, meanError = 0, surfaceDrift = 0, vmax = 0, minWallGap = 1e300;
};

/// Runs the tank to the given samples after the ramp; each sample's largest interior error goes
/// to result.profile.
TankState sampleTank(FluidCase<2>& c, double dx, double tEnd, int samples,
                     ValidationResult& result) {
    TankState state;
    for (int k = 1; k <= samples; ++k) {
        const double t = ramp + (tEnd - ramp) * k / samples;
        c.run->advanceTo(t);
        const auto x = c.x();
        const auto v = c.v();
        const auto kind = c.kind();
        const auto p = c.storage.getValue<Float>(QuantityId::PRESSURE);
        double sum = 0, top = 0, worst = 0;
        int count = 0;
        state.vmax = 0;
        for (Size i = 0; i < c.storage.size(); ++i) {
            if (!isFluid(kind[i])) continue;
            top = std::max(top, x[i][1]);
            state.vmax = std::max(state.vmax, norm(v[i]));
            state.minWallGap = std::min({state.minWallGap, x[i][0], width - x[i][0], x[i][1]});
            // Interior: below the top three rows, where the kernel support is full.
            if (x[i][1] > H - 3 * dx) continue;
            const double err = (p[i] - rho0 * g * (H - x[i][1])) / pScale;
            worst = std::max(worst, std::abs(err));
            sum += err;
            ++count;
        }
        state.maxError = worst;
        state.meanError = sum / count;
        // The top particle row starts at H - dx/2; its drift over the run.
        state.surfaceDrift = std::max(state.surfaceDrift, std::abs(top - (H - dx / 2)) / H);
        result.profile.push_back({t, worst, 0.0, t});
    }
    return state;
}

/// Pressure along the vertical centre line, bottom to top, against rho0 g (H - y).
std::vector<ProfileRow> centreLinePressure(const FluidCase<2>& c, double dx) {
    const auto x = c.x();
    const auto kind = c.kind();
    const auto p = c.storage.getValue<Float>(QuantityId::PRESSURE);
    std::vector<ProfileRow> line;
    for (Size i = 0; i < c.storage.size(); ++i)
        if (isFluid(kind[i]) && std::abs(x[i][0] - width / 2) < dx)
            line.push_back({x[i][1] / H, p[i] / pScale, (H - x[i][1]) / H});
    std::sort(line.begin(), line.end(),
              [](const ProfileRow& a, const ProfileRow& b) { return a.coordinate < b.coordinate; });
    return line;
}

}  // namespace

TEST(FluidHydrostatic, TankPressureAfterGravityRamp) {
    const bool full = fullResolution();
    const int n = full ? 40 : 30;  // particles over the depth
    const double tEnd = full ? 10.0 : 3.0;
    const double dx = H / n;
    FluidCase<2> c(tankModel(), tankGeometry(dx),
                   settingsFor(dx, defaults::hOverSpacing, defaults::kernel));

    ValidationResult result;
    const TankState s = sampleTank(c, dx, tEnd, full ? 20 : 4, result);
    // Pressure along the vertical centre line at the end.
    result.profile = centreLinePressure(c, dx);

    // reference_solutions.md sec. 6: interior pressure within 3 % of rho0 g H, mean within 1 %,
    // surface drift below 1 % of H, no particle crossing a wall (x = 0, x = width, y = 0).
    EXPECT_LT(s.maxError, 0.03);
    EXPECT_LT(std::abs(s.meanError), 0.01);
    EXPECT_LT(s.surfaceDrift, 0.01);
    EXPECT_GT(s.minWallGap, 0.0);
    // Settled: the largest speed is below 1 % of the free-fall speed sqrt(2 g H).
    EXPECT_LT(s.vmax, 0.01 * std::sqrt(2 * g * H));

    result.name = "hydrostatic_tank_2d";
    result.resolution =
        std::to_string(n) + " particles over the depth, t = " + std::to_string(int(tEnd)) + " s";
    result.error = s.maxError;
    result.tolerance = 0.03;
    result.passed = s.maxError < 0.03 && std::abs(s.meanError) < 0.01 && s.surfaceDrift < 0.01 &&
                    s.minWallGap > 0;
    result.notes = "max interior |p - rho0 g (H - y)| / (rho0 g H) at the end; mean " +
                   std::to_string(s.meanError) + ", surface drift " +
                   std::to_string(s.surfaceDrift) + " H, max speed " + std::to_string(s.vmax) +
                   " m/s, closest wall gap " + std::to_string(s.minWallGap) + " m";
    result.write();
}
