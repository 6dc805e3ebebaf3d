// A Gaussian heat pulse on a periodic lattice of fixed particles, driven through the solver
// with the HeatDiffusion example; shared by the example program and the tests.
// Analytic solution in d dimensions (reference_solutions.md, sec. 5):
//     u(r, t) = (t0 / (t0 + t))^(d/2) exp(-r^2 / (4 alpha (t0 + t))).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "heat_diffusion.hpp"

namespace examples {

struct PulseSetup {
    int perSide = 32;     ///< particles per side of the periodic box [-1/2, 1/2)^d
    Float hOverDx = 1.3;  ///< smoothing length in lattice spacings
    Float alpha = 1.0;    ///< diffusivity
    Float t0 = 0.02;      ///< age of the pulse at t = 0 (its width is sqrt(2 alpha t0))
    Float tEnd = 0.02;    ///< simulated time (the 2D peak halves)
    std::string kernel = "cubic_spline";
    std::string evaluation = "symmetric";
    std::string integrator = "leapfrog";
    num::sph::Size threads = 1;
};

struct PulseResult {
    Float maxError = 0;   ///< max over particles of |u - u_exact| at tEnd (the peak is 1 at t = 0)
    Float meanError = 0;  ///< mean over particles of |u - u_exact| at tEnd
    Float energyStart = 0;   ///< sum m u at t = 0
    Float energyEnd = 0;     ///< sum m u at tEnd
    Float energyAbs = 0;     ///< sum m |u| at t = 0, the scale of the round-off in the sums
    Float exactPeakEnd = 0;  ///< analytic peak at tEnd
    num::sph::Size steps = 0;
    std::string criterion;  ///< the criterion that limited the last full step
};

/// The free-space pulse at x (reference_solutions.md, sec. 5).
template <int Dim>
Float pulseFreeSpace(const PulseSetup& s, const num::sph::Vector<Dim>& x, Float t) {
    return std::pow(s.t0 / (s.t0 + t), 0.5 * Dim) *
           std::exp(-normSqr(x) / (4 * s.alpha * (s.t0 + t)));
}

/// The pulse in the periodic unit box: by linearity, the sum of the free-space pulses centred
/// on the periodic images of the origin (images beyond two boxes add less than 1e-30 here).
template <int Dim>
Float pulseExact(const PulseSetup& s, const num::sph::Vector<Dim>& x, Float t) {
    Float sum = 0;
    std::array<int, Dim> shift;
    shift.fill(-2);
    for (;;) {
        num::sph::Vector<Dim> y = x;
        for (int k = 0; k < Dim; ++k) y[k] += shift[k];
        sum += pulseFreeSpace<Dim>(s, y, t);
        int k = 0;
        while (k < Dim && ++shift[k] > 2) shift[k++] = -2;
        if (k == Dim) break;
    }
    return sum;
}

/// The particles of the pulse: a cell-centred lattice of s.perSide per side with the exact
/// energy at t = 0; they stay where they are (no force moves them).
template <int Dim>
num::sph::Storage<Dim> pulseLattice(const PulseSetup& s, const num::Domain<Dim>& domain,
                                    num::sph::Float dx, num::sph::Float rho) {
    using namespace num::sph;
    using Vec = Vector<Dim>;
    std::size_t n = 1;
    for (int k = 0; k < Dim; ++k) n *= std::size_t(s.perSide);
    std::vector<Vec> x(n);
    std::vector<Float> u(n);
    for (std::size_t p = 0; p < n; ++p) {
        std::size_t rest = p;
        for (int k = 0; k < Dim; ++k) {
            x[p][k] = domain.min[k] + (Float(rest % s.perSide) + 0.5) * dx;
            rest /= s.perSide;
        }
        u[p] = pulseExact<Dim>(s, x[p], 0);
    }
    Storage<Dim> storage;
    storage.template insert<Vec>(QuantityId::POSITION, OrderEnum::SECOND, x);
    storage.template insert<Float>(QuantityId::MASS, OrderEnum::ZERO, rho * std::pow(dx, Dim));
    storage.template insert<Float>(QuantityId::DENSITY, OrderEnum::ZERO, rho);
    storage.template insert<Float>(QuantityId::ENERGY, OrderEnum::FIRST, u);
    return storage;
}

/// The sum of m u over the particles (of m |u| where `absolute`).
template <int Dim>
num::sph::Float pulseEnergy(const num::sph::Storage<Dim>& storage, bool absolute) {
    using namespace num::sph;
    const auto m = storage.template getValue<Float>(QuantityId::MASS);
    const auto e = storage.template getValue<Float>(QuantityId::ENERGY);
    Float sum = 0;
    for (Size i = 0; i < storage.size(); ++i) sum += m[i] * (absolute ? std::abs(e[i]) : e[i]);
    return sum;
}

template <int Dim>
PulseResult runGaussianPulse(const PulseSetup& s) {
    using namespace num::sph;
    using Vec = Vector<Dim>;
    const Float length = 1, dx = length / s.perSide, rho = 1;

    RunSettings settings;
    settings.set("kernel", s.kernel)
        .set("smoothing_length", s.hOverDx * dx)
        .set("evaluation", s.evaluation)
        .set("threads", s.threads);
    num::Domain<Dim> domain;
    for (int k = 0; k < Dim; ++k) domain.min[k] = -length / 2, domain.max[k] = length / 2;
    domain.periodic.fill(true);

    Storage<Dim> storage = pulseLattice<Dim>(s, domain, dx, rho);

    auto scheduler = makeScheduler(s.threads > 1 ? "omp" : "seq", s.threads);
    Solver<Dim> solver(*scheduler, settings, makeTerm<HeatDiffusion<Dim>>(s.alpha), domain);
    Material material;
    solver.create(storage, material);
    auto integrator = makeIntegrator<Dim>(s.integrator);
    Run<Dim> run(storage, solver, *integrator);

    PulseResult result;
    result.energyStart = pulseEnergy(storage, false);
    result.energyAbs = pulseEnergy(storage, true);
    while (run.time() < s.tEnd * (1 - 1e-14)) {
        run.step(s.tEnd);
        if (run.limitingCriterion() != "end time") result.criterion = run.limitingCriterion();
    }
    result.steps = run.steps();
    result.energyEnd = pulseEnergy(storage, false);
    const auto xs = storage.template getValue<Vec>(QuantityId::POSITION);
    const auto us = storage.template getValue<Float>(QuantityId::ENERGY);
    for (Size i = 0; i < storage.size(); ++i) {
        const Float error = std::abs(us[i] - pulseExact<Dim>(s, xs[i], run.time()));
        result.maxError = std::max(result.maxError, error);
        result.meanError += error / storage.size();
    }
    result.exactPeakEnd = pulseExact<Dim>(s, Vec{}, run.time());
    return result;
}

}  // namespace examples
