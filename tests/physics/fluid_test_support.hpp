// Shared set-up of the fluid validation tests: running a case built from FluidModel and
// FluidGeometry, and analytic channel solutions (output: tests/validation_output.hpp).
#pragma once

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "../validation_output.hpp"
#include "sph/fluid_model.hpp"
#include "sph/timestepping.hpp"

namespace num::sph::fluid_test {

using validation::fullResolution;
using validation::ProfileRow;
using validation::ValidationResult;

/// A fluid case ready to run: storage, solver and the leapfrog run loop.
template <int Dim>
struct FluidCase {
    RunSettings settings;
    SequentialScheduler scheduler;
    Storage<Dim> storage;
    std::unique_ptr<Solver<Dim>> solver;
    LeapfrogKDK<Dim> integrator;
    std::unique_ptr<Run<Dim>> run;

    FluidCase(const FluidModel<Dim>& model, const FluidGeometry<Dim>& geometry,
              const RunSettings& s)
        : settings(s) {
        storage = makeFluidStorage(model, geometry, settings);
        solver = std::make_unique<Solver<Dim>>(
            scheduler, settings, makeFluidEquations(model, geometry), geometry.domain);
        run = std::make_unique<Run<Dim>>(storage, *solver, integrator);
    }

    ArrayView<const Vector<Dim>> x() const {
        return storage.template getValue<Vector<Dim>>(QuantityId::POSITION);
    }
    ArrayView<const Vector<Dim>> v() const {
        return storage.template getDt<Vector<Dim>>(QuantityId::POSITION);
    }
    ArrayView<const int> kind() const { return storage.template getValue<int>(QuantityId::KIND); }
};

/// Run settings with the given kernel and h = factor dx. The cubic spline at h = 1.3 dx is
/// the default of the fluid tests: its lattice Laplacian is within 0.1 % (reference_solutions.md
/// sec. 1), while Wendland C2 at h = 1.3 dx makes the Morris viscous force 4 % too weak (measured
/// with the Poiseuille case: 4.1 % of u_max at h = 1.3 dx, 1.7 % at 2 dx; cubic spline 0.3 %).
inline RunSettings settingsFor(double dx, double hFactor = 1.3,
                               const std::string& kernel = "cubic_spline") {
    RunSettings s;
    s.set("kernel", kernel).set("smoothing_length", hFactor * dx);
    return s;
}

/// Start-up Poiseuille flow between plates y = 0 and y = L (Morris et al. 1997, eq. 21).
inline double poiseuille(double y, double t, double F, double nu, double L) {
    double u = F / (2 * nu) * y * (L - y);
    const double pi = std::numbers::pi;
    for (int n = 0; n < 200; ++n) {
        const double k = 2 * n + 1;
        u -= 4 * F * L * L / (nu * pi * pi * pi * k * k * k) * std::sin(k * pi * y / L) *
             std::exp(-k * k * pi * pi * nu * t / (L * L));
    }
    return u;
}

/// Start-up Couette flow, wall y = L moving at V0 (Morris et al. 1997, eq. 22).
inline double couette(double y, double t, double V0, double nu, double L) {
    double u = V0 * y / L;
    const double pi = std::numbers::pi;
    for (int n = 1; n < 400; ++n)
        u += 2 * V0 / (n * pi) * (n % 2 ? -1.0 : 1.0) * std::sin(n * pi * y / L) *
             std::exp(-nu * n * n * pi * pi * t / (L * L));
    return u;
}

}  // namespace num::sph::fluid_test

namespace num::sph::fluid_test {

/// A plane channel between no-slip plates y = 0 and y = L, periodic along the other axes
/// (length `periodicCells` dx each), fluid at rest at t = 0: Poiseuille (body force F along x)
/// or Couette (wall y = L sliding at V0 along x). Morris et al. (1997), sec. 4.
struct ChannelSpec {
    double L = 1e-3, nu = 1e-6, rho0 = 1000;
    double force = 0;          // F [m/s^2] along x
    double wallVelocity = 0;   // V0 [m/s] of the plate y = L
    double velocityScale = 0;  // u_max for c0 = 10 u_max
    int cells = 30;            // particles across the channel
    int periodicCells = 8;
    double hFactor = 1.3;  // h / dx (cubic spline)
};

/// Largest error |u_x - u_exact| over fluid particles, and the row-averaged profile.
struct ChannelSample {
    double maxError = 0;
    std::vector<ProfileRow> rows;
};

template <int Dim>
class ChannelFlow {
  public:
    explicit ChannelFlow(const ChannelSpec& spec) : spec_(spec), dx_(spec.L / spec.cells) {
        FluidModel<Dim> model;
        model.restDensity = spec.rho0;
        model.viscosity = spec.nu;
        model.maxVelocity = spec.velocityScale;
        Vector<Dim> f{};
        f[0] = spec.force;
        if (spec.force != 0) model.bodyForce = constantForce(f);
        FluidGeometry<Dim> g;
        g.spacing = dx_;
        for (int k = 0; k < Dim; ++k) {
            g.domain.periodic[k] = k != 1;
            g.domain.max[k] = k == 1 ? spec.L : spec.periodicCells * dx_;
        }
        g.walls[1][1].velocity[0] = spec.wallVelocity;
        g.fluid.push_back(
            FluidRegion<Dim>::filling(BoxOrBall<Dim>::box(g.domain.min, g.domain.max)));
        case_ = std::make_unique<FluidCase<Dim>>(model, g, settingsFor(dx_, spec.hFactor));
    }

    /// Advances to t and compares u_x with `exact(y, t)`, errors relative to `scale`.
    template <class Exact>
    ChannelSample sampleAt(double t, Exact&& exact, double scale) {
        case_->run->advanceTo(t);
        const auto x = case_->x();
        const auto v = case_->v();
        const auto kind = case_->kind();
        ChannelSample s;
        std::vector<double> sum(spec_.cells, 0.0), y(spec_.cells, 0.0);
        std::vector<int> count(spec_.cells, 0);
        for (Size i = 0; i < case_->storage.size(); ++i) {
            if (!isFluid(kind[i])) continue;
            const double yi = x[i][1];
            s.maxError = std::max(s.maxError, std::abs(v[i][0] - exact(yi, t)) / scale);
            const int row = std::clamp(int(yi / dx_), 0, spec_.cells - 1);
            sum[row] += v[i][0], y[row] += yi, ++count[row];
        }
        for (int r = 0; r < spec_.cells; ++r) {
            if (!count[r]) continue;
            const double yr = y[r] / count[r];
            s.rows.push_back({yr / spec_.L, sum[r] / count[r] / scale, exact(yr, t) / scale, t});
        }
        return s;
    }

    FluidCase<Dim>& fluidCase() { return *case_; }
    double spacing() const { return dx_; }

  private:
    ChannelSpec spec_;
    double dx_;
    std::unique_ptr<FluidCase<Dim>> case_;
};

}  // namespace num::sph::fluid_test
