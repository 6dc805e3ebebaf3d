// Couette flow in 2D (Morris, Fox & Zhu 1997, sec. 4.1): fluid at rest between two no-slip
// plates; the plate y = L slides at V0 from t = 0 (a moving wall: prescribed surface velocity
// seen by the fluid through the wall condition). Transient and steady profiles.
#include <gtest/gtest.h>

#include "fluid_test_support.hpp"

using namespace num::sph;
using namespace num::sph::fluid_test;

TEST(FluidCouette, TransientAndSteadyProfiles2D) {
    ChannelSpec spec;  // L = 1e-3, nu = 1e-6, rho = 1000 (reference_solutions.md sec. 3)
    spec.wallVelocity = 2.5e-5;
    spec.velocityScale = spec.wallVelocity;
    spec.cells = fullResolution() ? 60 : 30;
    ChannelFlow<2> flow(spec);
    const double V0 = spec.wallVelocity;
    auto exact = [&](double y, double t) { return couette(y, t, V0, spec.nu, spec.L); };

    // Issue 4 / reference_solutions.md sec. 3: transient within 2 % of V0, steady within 1 % of V0.
    const double transientTolerance = 0.02, steadyTolerance = 0.01;
    ValidationResult result;
    result.name = "couette_2d";
    result.resolution = std::to_string(spec.cells) + " particles across";
    result.tolerance = steadyTolerance;
    double transientError = 0;
    for (double t : {0.0225, 0.045, 0.1125, 0.225}) {
        const ChannelSample s = flow.sampleAt(t, exact, V0);
        EXPECT_LT(s.maxError, transientTolerance) << "t = " << t;
        transientError = std::max(transientError, s.maxError);
        result.profile.insert(result.profile.end(), s.rows.begin(), s.rows.end());
    }
    // t = 1 s: the slowest mode has decayed to exp(-pi^2) ~ 5e-5 of V0, i.e. steady.
    const ChannelSample steady = flow.sampleAt(1.0, exact, V0);
    EXPECT_LT(steady.maxError, steadyTolerance);
    result.profile.insert(result.profile.end(), steady.rows.begin(), steady.rows.end());
    result.error = steady.maxError;
    result.passed = steady.maxError < steadyTolerance && transientError < transientTolerance;
    result.notes = "steady (t = 1 s) max |u - u_exact| / V0 = " + std::to_string(steady.maxError) +
                   " (tolerance 0.01); transient max = " + std::to_string(transientError) +
                   " (tolerance 0.02)";
    result.write();
}
