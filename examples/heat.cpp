// Heat diffusion example: a Gaussian pulse spreads on a periodic lattice in 2D and 3D, compared
// with the analytic solution. Exits with 1 if the error exceeds 1% of the initial peak
// or the mean error 0.3% (the gates of reference_solutions.md, sec. 5).
#include <cstdio>

#include "gaussian_pulse.hpp"

int main() {
    examples::PulseSetup setup;  // 2D: 32 x 32 particles, cubic spline, h = 1.3 dx
    bool ok = true;
    const auto report = [&](int dim, const examples::PulseResult& r) {
        const double drift = (r.energyEnd - r.energyStart) / r.energyAbs;
        std::printf(
            "%dD: %u steps (limited by %s), error of the initial peak: max %.3e, mean %.3e; "
            "relative change of total energy %.1e\n",
            dim, r.steps, r.criterion.c_str(), r.maxError, r.meanError, drift);
        ok = ok && r.maxError < 0.01 && r.meanError < 0.003;
    };
    report(2, examples::runGaussianPulse<2>(setup));
    // 3D: fewer particles per side; cubic spline with h = 1.5 dx, where its Laplacian on a
    // lattice is consistent to 0.1% (reference_solutions.md, sec. 1).
    setup.perSide = 20;
    setup.hOverDx = 1.5;
    report(3, examples::runGaussianPulse<3>(setup));
    return ok ? 0 : 1;
}
