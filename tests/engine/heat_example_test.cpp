// The heat diffusion example through the solver: a Gaussian pulse on a periodic lattice against
// the analytic solution of reference_solutions.md, sec. 5, in 2D and 3D.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gaussian_pulse.hpp"

namespace {

// Gates of reference_solutions.md, sec. 5: max error below 1% of the temperature jump (here the
// initial peak, 1), mean below 0.3%.
constexpr double maxErrorGate = 0.01, meanErrorGate = 0.003;

void expectPulse(const examples::PulseResult& r) {
    EXPECT_LT(r.maxError, maxErrorGate);
    EXPECT_LT(r.meanError, meanErrorGate);
    EXPECT_EQ(r.criterion, "diffusion");
    // The symmetric pair terms cancel, so the total energy changes only by the round-off of
    // the sums: per step, about a neighbour count of eps relative to sum m |u|.
    EXPECT_LE(std::abs(r.energyEnd - r.energyStart), r.steps * 100 * 2.2e-16 * r.energyAbs)
        << r.energyEnd - r.energyStart;
}

TEST(HeatExample, GaussianPulse2D) {
    examples::PulseSetup s;  // 32 x 32, cubic spline, h = 1.3 dx (consistent Laplacian)
    for (const char* mode : {"symmetric", "asymmetric"}) {
        SCOPED_TRACE(mode);
        s.evaluation = mode;
        expectPulse(examples::runGaussianPulse<2>(s));
    }
}

TEST(HeatExample, GaussianPulse3D) {
    examples::PulseSetup s;
    s.perSide = 20;
    s.hOverDx = 1.5;  // where the cubic spline's lattice Laplacian is consistent (sec. 1)
    expectPulse(examples::runGaussianPulse<3>(s));
}

/// du/dt at the centre of a lattice (spacing 1, h = hOverDx) where u = |x|^2: the exact
/// Laplacian is 2 Dim, and du/dt = +alpha * Laplacian with alpha = 0.5 (the seed's minus sign
/// would make it negative).
template <int Dim>
double centreRate(double hOverDx) {
    using namespace num::sph;
    const int side = 11;  // the support (2h <= 3) stays far from the lattice edges
    std::vector<Vector<Dim>> x;
    std::vector<Float> u;
    for (int p = 0; p < int(std::pow(side, Dim)); ++p) {
        Vector<Dim> y;
        for (int k = 0, rest = p; k < Dim; ++k, rest /= side) y[k] = rest % side - side / 2;
        x.push_back(y);
        u.push_back(normSqr(y));
    }
    Storage<Dim> s;
    s.template insert<Vector<Dim>>(QuantityId::POSITION, OrderEnum::SECOND, x);
    s.template insert<Float>(QuantityId::MASS, OrderEnum::ZERO, 1.0);
    s.template insert<Float>(QuantityId::DENSITY, OrderEnum::ZERO, 1.0);
    s.template insert<Float>(QuantityId::ENERGY, OrderEnum::FIRST, u);
    RunSettings settings;
    settings.set("kernel", "cubic_spline").set("smoothing_length", hOverDx);
    SequentialScheduler scheduler;
    Solver<Dim> solver(scheduler, settings, makeTerm<examples::HeatDiffusion<Dim>>(0.5),
                       num::Domain<Dim>{});
    Material material;
    solver.create(s, material);
    solver.evaluate(s, 0);
    for (Size i = 0; i < s.size(); ++i)
        if (normSqr(s.template getValue<Vector<Dim>>(QuantityId::POSITION)[i]) == 0)
            return s.template getDt<Float>(QuantityId::ENERGY)[i];
    return 0;
}

TEST(HeatExample, LaplacianHasThePhysicalSignAndLatticeValue) {
    // reference_solutions.md, sec. 1: the Brookshaw Laplacian of |x|^2 over its exact value 2d with
    // eta^2 = 0.01 h^2 is 1.000 (cubic, 2D, h = 1.3 dx) and 1.001 (3D, h = 1.5 dx); the
    // tolerance 0.002 covers the rounding of those table entries.
    EXPECT_NEAR(centreRate<2>(1.3) / (0.5 * 4), 1.000, 0.002);
    EXPECT_NEAR(centreRate<3>(1.5) / (0.5 * 6), 1.001, 0.002);
}

}  // namespace
