// The phases of a step: an evaluation has no side effects on the state (evaluations at any time,
// repeated, leave positions, velocities and densities as they were and give bitwise the same
// rates; the check debug builds run catches a term that changes them), the state constraints
// (periodic wrap, density floor) run before every evaluation, and what moves particles (particle
// shifting, containment) runs once per step in the post-step phase, which Run::step calls after
// the integrator.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <type_traits>

#include "numerics.hpp"
#include "sph/fluid_model.hpp"

namespace {

using namespace num::sph;

/// Every level of every quantity of a and b is bitwise the same.
template <int Dim>
::testing::AssertionResult sameState(const Storage<Dim>& a, const Storage<Dim>& b) {
    std::string diff;
    a.forEach([&](QuantityId id, const Quantity<Dim>& qa) {
        if (!b.has(id)) {
            diff += " quantity " + std::to_string(int(id)) + " missing;";
            return;
        }
        qa.visit([&](const auto& ba) {
            using T = typename std::decay_t<decltype(ba.value)>::value_type;
            const auto& bb = b.get(id).template buffers<T>();
            for (int k = 0; k < qa.levels(); ++k) {
                const auto &x = ba.level(k), &y = bb.level(k);
                if (x.size() != y.size() ||
                    std::memcmp(x.data(), y.data(), x.size() * sizeof(T)) != 0)
                    diff += " quantity " + std::to_string(int(id)) + " level " + std::to_string(k) +
                            ";";
            }
        });
    });
    if (diff.empty()) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "differ:" << diff;
}

template <class A, class B>
bool sameValues(const A& a, const B& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
}

/// A periodic box full of water on a jittered lattice with random velocities: the particle
/// concentration has gradients everywhere, no free surface (every kernel sum above 0.9) and no
/// wall, so shifting moves every particle.
struct JitteredBox {
    static constexpr double dx = 0.05;
    FluidModel<2> model;
    FluidGeometry<2> geometry;
    RunSettings settings;
    Storage<2> storage;

    JitteredBox() {
        model.maxVelocity = 1;
        model.shifting = true;
        geometry.spacing = dx;
        geometry.domain.max = {{1.0, 1.0}};
        geometry.domain.periodic = {true, true};
        geometry.fluid.push_back(
            FluidRegion<2>::filling(BoxOrBall<2>::box(geometry.domain.min, geometry.domain.max)));
        settings.set("smoothing_length", 1.3 * dx);
        storage = makeFluidStorage(model, geometry, settings);
        std::mt19937_64 rng(5);
        std::uniform_real_distribution<double> jitter(-0.1 * dx, 0.1 * dx), speed(-0.1, 0.1);
        auto x = storage.getValue<Vector<2>>(QuantityId::POSITION);
        auto v = storage.getDt<Vector<2>>(QuantityId::POSITION);
        for (Size i = 0; i < storage.size(); ++i) {
            x[i] = geometry.domain.wrap(x[i] + Vector<2>{{jitter(rng), jitter(rng)}});
            v[i] = Vector<2>{{speed(rng), speed(rng)}};
        }
    }
    Solver<2> solver(IScheduler& scheduler) const {
        return Solver<2>(scheduler, settings, makeFluidEquations(model, geometry), geometry.domain);
    }
};

TEST(Phases, EvaluationHasNoSideEffectsWithShifting) {
    JitteredBox box;
    SequentialScheduler scheduler;
    Solver<2> solver = box.solver(scheduler);
    ASSERT_NE(solver.equations().find<ParticleShifting<2>>(), nullptr);
    Storage<2>& s = box.storage;
    const Storage<2> initial = s;

    // Evaluations at several times, as an integrator makes them within and across steps.
    solver.evaluate(s, 0.0);
    const Storage<2> first = s;
    const auto c = s.getValue<Float>(FluidId::KERNEL_SUM);
    const auto m = s.getValue<Float>(QuantityId::MASS);
    const auto rho = s.getValue<Float>(QuantityId::DENSITY);
    const Float w0 = solver.kernel().W(0);
    for (Size i = 0; i < s.size(); ++i)
        ASSERT_FALSE(atFreeSurface(c[i], m[i] / rho[i], w0)) << "no free surface in the box";
    solver.evaluate(s, 1e-3);
    EXPECT_TRUE(sameState(first, s)) << "a second evaluation, later";
    solver.evaluate(s, 1e-3);
    EXPECT_TRUE(sameState(first, s)) << "a third evaluation, at the same time";

    EXPECT_TRUE(sameValues(initial.getValue<Float>(QuantityId::DENSITY),
                           s.getValue<Float>(QuantityId::DENSITY)))
        << "evaluate() changed densities";
    EXPECT_TRUE(sameValues(initial.getValue<Vector<2>>(QuantityId::POSITION),
                           s.getValue<Vector<2>>(QuantityId::POSITION)))
        << "evaluate() moved particles";
    EXPECT_TRUE(sameValues(initial.getDt<Vector<2>>(QuantityId::POSITION),
                           s.getDt<Vector<2>>(QuantityId::POSITION)))
        << "evaluate() changed velocities";
}

TEST(Phases, PostStepShiftsParticlesByTheStepsDisplacement) {
    JitteredBox box;
    SequentialScheduler scheduler;
    Solver<2> solver = box.solver(scheduler);
    Storage<2>& s = box.storage;
    solver.evaluate(s, 0.0);
    Storage<2> twice = s;
    const Storage<2> before = s;
    const double dt = 1e-4;
    solver.postStep(s, dt, dt);
    solver.postStep(twice, 2 * dt, 2 * dt);

    // dr = -A h c0 dt grad C, |dr| <= 0.1 h (terms/particle_shifting.hpp).
    const double h = 1.3 * JitteredBox::dx, A = box.model.shiftingCoefficient;
    const double c0 = box.model.c0();
    const auto x0 = before.getValue<Vector<2>>(QuantityId::POSITION);
    const auto x1 = s.getValue<Vector<2>>(QuantityId::POSITION);
    const auto x2 = twice.getValue<Vector<2>>(QuantityId::POSITION);
    const auto v0 = before.getDt<Vector<2>>(QuantityId::POSITION);
    const auto v1 = s.getDt<Vector<2>>(QuantityId::POSITION);
    const auto gradC = before.getValue<Vector<2>>(FluidId::KERNEL_SUM_GRADIENT);
    Size moved = 0, velocityChanged = 0;
    for (Size i = 0; i < s.size(); ++i) {
        const Vector<2> dr = x1[i] - x0[i], expected = gradC[i] * (-A * h * c0 * dt);
        ASSERT_LE(norm(expected), 0.1 * h) << "the cap is not reached at this dt";
        EXPECT_LT(norm(dr - expected), 1e-12) << i;
        // Linear in dt below the cap.
        EXPECT_LT(norm((x2[i] - x0[i]) - dr * 2.0), 1e-12) << i;
        moved += norm(dr) > 0;
        velocityChanged += norm(v1[i] - v0[i]) > 0;
    }
    EXPECT_EQ(moved, s.size()) << "every particle is shifted in a jittered periodic box";
    EXPECT_GT(velocityChanged, s.size() / 2) << "v follows by the Taylor correction";
}

/// A unit box with walls on every side, water up to fillHeight, spacing dx, h = 1.3 dx.
struct WalledBox {
    static constexpr double dx = 0.05;
    FluidGeometry<2> geometry;
    RunSettings settings;
    explicit WalledBox(double fillHeight) {
        geometry.spacing = dx;
        geometry.domain.max = {{1.0, 1.0}};
        geometry.fluid.push_back(
            FluidRegion<2>::filling(BoxOrBall<2>::box({{0.0, 0.0}}, {{1.0, fillHeight}})));
        settings.set("smoothing_length", 1.3 * dx);
    }
};

/// Within a kernel support of a wall, shifting moves particles along the wall only: the component
/// along n = sum over wall neighbours of V_j grad W_ij is removed (terms/particle_shifting.hpp),
/// unless shiftingNormalToWalls asks for it.
void expectShiftAlongWalls(bool normalToWalls) {
    const double dx = WalledBox::dx;
    FluidModel<2> model;
    model.maxVelocity = 1;
    model.shiftingNormalToWalls = normalToWalls;
    const auto [geometry, settings] = WalledBox(1.0);
    Storage<2> s = makeFluidStorage(model, geometry, settings);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> jitter(-0.1 * dx, 0.1 * dx);
    auto x = s.getValue<Vector<2>>(QuantityId::POSITION);
    const auto kind = s.getValue<int>(QuantityId::KIND);
    for (Size i = 0; i < s.size(); ++i)
        if (isFluid(kind[i])) x[i] += Vector<2>{{jitter(rng), jitter(rng)}};
    SequentialScheduler scheduler;
    Solver<2> solver(scheduler, settings, makeFluidEquations(model, geometry), geometry.domain);
    solver.evaluate(s, 0.0);
    const Storage<2> before = s;
    solver.postStep(s, 1e-4, 1e-4);

    // The displacement x1 - x0 carries the round-off of the positions (below 1, so 2^-53 of
    // each coordinate at most): its component along n is at most 4e-16 where dr is along the
    // wall, about 1e-6 (|dr|) where it is not.
    const auto x0 = before.getValue<Vector<2>>(QuantityId::POSITION);
    const auto x1 = s.getValue<Vector<2>>(QuantityId::POSITION);
    const auto n = before.getValue<Vector<2>>(FluidId::WALL_DIRECTION);
    const double roundOff = 4e-16;
    Size nearWall = 0, alongOnly = 0, moved = 0;
    for (Size i = 0; i < s.size(); ++i) {
        if (!isFluid(kind[i]) || normSqr(n[i]) == 0) continue;
        ++nearWall;
        const Vector<2> dr = x1[i] - x0[i];
        moved += norm(dr) > 1e3 * roundOff;
        alongOnly += std::abs(dot(dr, n[i])) <= roundOff * norm(n[i]);
    }
    ASSERT_GT(nearWall, 50u) << "the box has particles within a support of its walls";
    EXPECT_GT(moved, nearWall / 2) << "near-wall particles are still shifted";
    if (normalToWalls)
        EXPECT_LT(alongOnly, nearWall / 10) << "with the normal component kept";
    else
        EXPECT_EQ(alongOnly, nearWall) << "only along the walls";
}

TEST(Phases, ShiftingNearWallsIsAlongThemByDefault) { expectShiftAlongWalls(false); }
TEST(Phases, ShiftingNormalToWallsKeepsTheNormalComponent) { expectShiftAlongWalls(true); }

TEST(Phases, RunStepIsTheIntegratorThenThePostStepPhase) {
    SequentialScheduler scheduler;
    JitteredBox a, b;
    Solver<2> solverA = a.solver(scheduler), solverB = b.solver(scheduler);
    LeapfrogKDK<2> integratorA, integratorB;
    num::sph::Run<2> run(a.storage, solverA, integratorA);
    const double dt = run.step();
    ASSERT_GT(dt, 0);

    solverB.evaluate(b.storage, 0.0);
    integratorB.step(solverB, b.storage, 0.0, dt);
    const Storage<2> withoutPostStep = b.storage;
    solverB.postStep(b.storage, dt, dt);
    EXPECT_TRUE(sameState(a.storage, b.storage));
    EXPECT_FALSE(sameValues(withoutPostStep.getValue<Vector<2>>(QuantityId::POSITION),
                            b.storage.getValue<Vector<2>>(QuantityId::POSITION)))
        << "shifting moves particles in the post-step phase";
}

TEST(Phases, ContainmentReflectsInThePostStepPhaseOnly) {
    const double dx = WalledBox::dx;
    FluidModel<2> model;
    model.maxVelocity = 1;
    model.shifting = false;
    const auto [geometry, settings] = WalledBox(0.5);
    Storage<2> s = makeFluidStorage(model, geometry, settings);
    SequentialScheduler scheduler;
    Solver<2> solver(scheduler, settings, makeFluidEquations(model, geometry), geometry.domain);
    ASSERT_NE(solver.equations().find<ParticleContainment<2>>(), nullptr);

    // A fluid particle that has crossed the left wall by 0.3 dx, moving into it.
    auto x = s.getValue<Vector<2>>(QuantityId::POSITION);
    auto v = s.getDt<Vector<2>>(QuantityId::POSITION);
    const auto kind = s.getValue<int>(QuantityId::KIND);
    Size p = 0;
    while (!isFluid(kind[p]) || x[p][0] > 0.6 * dx || x[p][1] < 0.2) ++p;
    const double y = x[p][1];
    x[p][0] = -0.3 * dx;
    v[p] = Vector<2>{{-0.5, 0.25}};

    solver.evaluate(s, 0.0);
    solver.evaluate(s, 1e-4);
    EXPECT_EQ(s.getValue<Vector<2>>(QuantityId::POSITION)[p][0], -0.3 * dx)
        << "evaluate() moved the particle";
    EXPECT_EQ(s.getDt<Vector<2>>(QuantityId::POSITION)[p][0], -0.5);

    solver.postStep(s, 1e-4, 1e-4);
    const Vector<2> xp = s.getValue<Vector<2>>(QuantityId::POSITION)[p];
    const Vector<2> vp = s.getDt<Vector<2>>(QuantityId::POSITION)[p];
    EXPECT_NEAR(xp[0], 0.3 * dx, 1e-15);
    EXPECT_EQ(xp[1], y);
    EXPECT_EQ(vp[0], 0.0);
    EXPECT_EQ(vp[1], 0.25);
}

/// A term that changes an evolved quantity in its initialize (the density) or its finalize (the
/// positions): an impure evaluation.
template <int Dim>
class Impure : public IEquationTerm<Dim> {
  public:
    explicit Impure(bool inFinalize) : inFinalize_(inFinalize) {}
    void setDerivatives(DerivativeHolder<Dim>&, const RunSettings&) override {}
    void initialize(IScheduler&, Storage<Dim>& s, Float) override {
        if (!inFinalize_) s.template getValue<Float>(QuantityId::DENSITY)[3] *= 1.001;
    }
    void finalize(IScheduler&, Storage<Dim>& s, Float) override {
        if (inFinalize_) s.template getValue<Vector<Dim>>(QuantityId::POSITION)[5][0] += 1e-9;
    }
    void create(Storage<Dim>&, IMaterial&) const override {}
    std::string name() const override { return "Impure"; }

  private:
    bool inFinalize_;
};

TEST(Phases, TheCheckNamesTheTermAndTheQuantityAnEvaluationChanged) {
    for (const bool inFinalize : {false, true}) {
        JitteredBox box;
        box.model.extraTerms += makeTerm<Impure<2>>(inFinalize);
        SequentialScheduler scheduler;
        Solver<2> solver = box.solver(scheduler);
        try {
            solver.evaluateCheckingPurity(box.storage, 0.0);
            ADD_FAILURE() << "the impure term was not caught";
        } catch (const ImpureEvaluation& e) {
            const std::string message = e.what();
            const std::string expected =
                inFinalize ? "the term Impure (finalize) changed the values of quantity 0 "
                             "(particle 5)"
                           : "the term Impure (initialize) changed the values of quantity 2 "
                             "(particle 3)";
            EXPECT_EQ(message.find(expected), 0u) << message;
        }
    }
#ifndef NDEBUG
    JitteredBox box;  // this build checks every evaluation
    box.model.extraTerms += makeTerm<Impure<2>>(false);
    SequentialScheduler scheduler;
    Solver<2> solver = box.solver(scheduler);
    EXPECT_THROW(solver.evaluate(box.storage, 0.0), ImpureEvaluation);
#endif
}

TEST(Phases, TheFluidModelPassesTheCheckWithWallsAndAFreeSurface) {
    FluidModel<2> model;
    model.maxVelocity = 1;
    model.bodyForce = constantForce(Vector<2>{{0.0, -9.81}});
    const auto [geometry, settings] = WalledBox(0.5);
    Storage<2> s = makeFluidStorage(model, geometry, settings);
    SequentialScheduler scheduler;
    Solver<2> solver(scheduler, settings, makeFluidEquations(model, geometry), geometry.domain);
    LeapfrogKDK<2> integrator;
    num::sph::Run<2> run(s, solver, integrator);
    for (int k = 0; k < 5; ++k) run.step();
    const auto c = s.getValue<Float>(FluidId::KERNEL_SUM);
    const auto m = s.getValue<Float>(QuantityId::MASS);
    const auto rho = s.getValue<Float>(QuantityId::DENSITY);
    const auto kind = s.getValue<int>(QuantityId::KIND);
    Size atSurface = 0;
    for (Size i = 0; i < s.size(); ++i)
        atSurface += isFluid(kind[i]) && atFreeSurface(c[i], m[i] / rho[i], solver.kernel().W(0));
    ASSERT_GT(atSurface, 10u) << "the water's top is a free surface";
    // The wall condition rewrites the boundary particles' density: allowed (it prepares it).
    EXPECT_NO_THROW(solver.evaluateCheckingPurity(s, run.time()));
}

/// The constraints run before every evaluation: a particle that left the periodic box is
/// wrapped back before the neighbour search, and a second evaluation changes nothing.
TEST(Phases, EvaluateWrapsPeriodicPositionsFirst) {
    JitteredBox box;
    SequentialScheduler scheduler;
    Solver<2> solver = box.solver(scheduler);
    auto x = box.storage.getValue<Vector<2>>(QuantityId::POSITION);
    const Vector<2> inside = x[7];
    x[7][0] += 1.0;  // one period to the right
    solver.evaluate(box.storage, 0.0);
    EXPECT_NEAR(x[7][0], inside[0], 1e-15);
    EXPECT_EQ(x[7][1], inside[1]);
    const Storage<2> first = box.storage;
    solver.evaluateCheckingPurity(box.storage, 0.0);
    EXPECT_TRUE(sameState(first, box.storage));
}

}  // namespace
