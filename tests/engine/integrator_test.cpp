// Integrators by their measured order of convergence, and the long-time energy of leapfrog.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "numerics.hpp"
#include "spring_force.hpp"

namespace {

using namespace num::sph;
using V2 = Vector<2>;

/// A one-particle spring (k = 4, m = 1, A = 1) in 2D, stepped with a fixed dt through the solver.
struct Oscillator {
    static constexpr double k = 4, m = 1, amplitude = 1;
    static double omega() { return std::sqrt(k / m); }

    RunSettings settings = [] {
        RunSettings s;
        s.set("smoothing_length", 1.0);
        return s;
    }();
    SequentialScheduler scheduler;
    Solver<2> solver{scheduler, settings, makeTerm<examples::SpringForce<2>>(k), num::Domain<2>{}};
    Storage<2> storage;
    double t = 0;

    Oscillator() {
        storage.insert<V2>(QuantityId::POSITION, OrderEnum::SECOND,
                           std::vector<V2>{V2{{amplitude, 0.0}}});
        storage.insert<Float>(QuantityId::MASS, OrderEnum::ZERO, m);
        Material material;
        solver.create(storage, material);
        solver.evaluate(storage, 0);
    }
    void advance(ITimeStepping<2>& integrator, double dt, long steps) {
        for (long n = 0; n < steps; ++n, t += dt) integrator.step(solver, storage, t, dt);
    }
    double x() { return storage.getValue<V2>(QuantityId::POSITION)[0][0]; }
    double v() { return storage.getDt<V2>(QuantityId::POSITION)[0][0]; }
    double energy() { return 0.5 * m * v() * v() + 0.5 * k * x() * x(); }
};

/// Phase-space error against x = A cos(omega t), v = -A omega sin(omega t) after 1.3 periods
/// with `steps` steps (both matter: Euler's amplitude error is first order, its phase error
/// second).
double springError(const std::string& integrator, long steps) {
    Oscillator osc;
    const double w = Oscillator::omega(), tEnd = 1.3 * 2 * std::numbers::pi / w;
    auto stepper = makeIntegrator<2>(integrator);
    osc.advance(*stepper, tEnd / steps, steps);
    const double ex = osc.x() - Oscillator::amplitude * std::cos(w * tEnd);
    const double ev = osc.v() + Oscillator::amplitude * w * std::sin(w * tEnd);
    return std::hypot(ex, ev / w);
}

/// log2 of the error ratio as the step halves, for the last of three halvings.
double measuredOrder(const std::function<double(long)>& error, long steps) {
    const double e1 = error(steps), e2 = error(2 * steps), e3 = error(4 * steps);
    EXPECT_GT(e2, 0.0);
    EXPECT_LT(e3, e2);
    (void)e1;
    return std::log2(e2 / e3);
}

// The order must be the scheme's to within 0.1: the next term of the error is one order
// higher, so at these step counts (omega dt <= 0.1) it shifts the measured order by less.
TEST(Integrators, LeapfrogIsSecondOrderOnTheSpring) {
    EXPECT_NEAR(measuredOrder([](long n) { return springError("leapfrog", n); }, 100), 2.0, 0.1);
}
TEST(Integrators, PredictorCorrectorIsSecondOrderOnTheSpring) {
    EXPECT_NEAR(measuredOrder([](long n) { return springError("predictor_corrector", n); }, 100),
                2.0, 0.1);
}
TEST(Integrators, EulerIsFirstOrderOnTheSpring) {
    EXPECT_NEAR(measuredOrder([](long n) { return springError("euler", n); }, 2000), 1.0, 0.1);
}

TEST(Integrators, LeapfrogEnergyStaysBoundedOver1e4Periods) {
    // Velocity Verlet conserves I = v^2/2 + omega^2 x^2 (1 - (omega dt)^2 / 4) / 2 exactly for
    // the harmonic oscillator; starting at rest at x = A this bounds the energy to
    // E0 (1 - (omega dt)^2 / 4) <= E <= E0 for all time: no drift, whatever the run length.
    Oscillator osc;
    const double period = 2 * std::numbers::pi / Oscillator::omega();
    const long perPeriod = 32;
    const double dt = period / perPeriod;
    const double bound = std::pow(Oscillator::omega() * dt, 2) / 4;
    const double e0 = osc.energy();
    LeapfrogKDK<2> leapfrog;
    double worst = 0, worstLastPeriods = 0;
    const long periods = 10000;
    for (long p = 0; p < periods; ++p) {
        for (int s = 0; s < perPeriod; ++s) {
            osc.advance(leapfrog, dt, 1);
            const double deviation = std::abs(osc.energy() - e0) / e0;
            worst = std::max(worst, deviation);
            if (p >= periods - 100) worstLastPeriods = std::max(worstLastPeriods, deviation);
        }
    }
    // Round-off adds a random walk of about sqrt(3e5) eps to I; 1e-10 is far above it.
    EXPECT_LE(worst, bound + 1e-10);
    EXPECT_GT(worstLastPeriods, 0.5 * bound);  // the bound is the real size of the oscillation
    // Same run with Euler drifts: its energy grows by (1 + (omega dt)^2) every step.
    Oscillator euler;
    ExplicitEuler<2> stepper;
    euler.advance(stepper, dt, 10 * perPeriod);
    EXPECT_GT(euler.energy() / e0, 1.5);
}

/// du/dt = -lambda u for every particle: a first-order quantity with a known solution.
class Decay : public IEquationTerm<2> {
  public:
    void setDerivatives(DerivativeHolder<2>&, const RunSettings&) override {}
    void initialize(IScheduler&, Storage<2>&, Float) override {}
    void finalize(IScheduler&, Storage<2>& s, Float) override {
        const auto u = s.getValue<Float>(QuantityId::ENERGY);
        const auto du = s.getDt<Float>(QuantityId::ENERGY);
        for (Size i = 0; i < s.size(); ++i) du[i] += -3.0 * u[i];
    }
    void create(Storage<2>& s, IMaterial&) const override {
        s.insert<Float>(QuantityId::ENERGY, OrderEnum::FIRST, 1.0);
    }
};

double decayError(const std::string& integrator, long steps) {
    RunSettings settings;
    settings.set("smoothing_length", 1.0);
    SequentialScheduler scheduler;
    Solver<2> solver(scheduler, settings, makeTerm<Decay>(), num::Domain<2>{});
    Storage<2> s;
    s.insert<V2>(QuantityId::POSITION, OrderEnum::SECOND, std::vector<V2>(1));
    Material material;
    solver.create(s, material);
    solver.evaluate(s, 0);
    auto stepper = makeIntegrator<2>(integrator);
    const double tEnd = 1.0, dt = tEnd / steps;
    for (long n = 0; n < steps; ++n) stepper->step(solver, s, n * dt, dt);
    return std::abs(s.getValue<Float>(QuantityId::ENERGY)[0] - std::exp(-3.0 * tEnd));
}

TEST(Integrators, OrderOnAFirstOrderQuantity) {
    EXPECT_NEAR(measuredOrder([](long n) { return decayError("leapfrog", n); }, 50), 2.0, 0.1);
    EXPECT_NEAR(measuredOrder([](long n) { return decayError("predictor_corrector", n); }, 50), 2.0,
                0.1);
    EXPECT_NEAR(measuredOrder([](long n) { return decayError("euler", n); }, 400), 1.0, 0.1);
}

}  // namespace
