// The pair loop: conservation, symmetric against asymmetric evaluation, reproducibility for any
// number of threads, and the adaptive time step.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <vector>

#include "heat_diffusion.hpp"
#include "numerics.hpp"
#include "sph/terms/neighbour_gather.hpp"
#include "spring_force.hpp"
#include "test_physics.hpp"

namespace {

using namespace num::sph;
constexpr double eps = 2.220446049250313e-16;

template <int Dim>
num::Domain<Dim> unitBox(bool periodic) {
    num::Domain<Dim> d;
    d.max = Vector<Dim>::filled(1.0);
    d.periodic.fill(periodic);
    return d;
}

template <int Dim>
Storage<Dim> evaluate(const std::string& mode, bool periodic, Size n, double h) {
    RunSettings settings;
    settings.set("smoothing_length", h).set("evaluation", mode);
    Storage<Dim> s = enginetest::randomParticles<Dim>(n, 17);
    SequentialScheduler scheduler;
    Solver<Dim> solver(scheduler, settings, makeTerm<enginetest::PairForceTerm<Dim>>(),
                       unitBox<Dim>(periodic));
    Material material;
    solver.create(s, material);
    solver.evaluate(s, 0);
    EXPECT_GT(solver.meanNeighbours(), 5.0);
    return s;
}

template <int Dim>
void checkMomentumAndModes(Size n, double h) {
    for (bool periodic : {false, true}) {
        SCOPED_TRACE(periodic ? "periodic" : "open");
        Storage<Dim> sym = evaluate<Dim>("symmetric", periodic, n, h);
        Storage<Dim> asym = evaluate<Dim>("asymmetric", periodic, n, h);
        for (const Storage<Dim>* s : {&sym, &asym}) {
            const auto m = s->template getValue<Float>(QuantityId::MASS);
            const auto a = s->template getD2t<Vector<Dim>>(QuantityId::POSITION);
            Vector<Dim> total{};
            double scale = 0;
            for (Size i = 0; i < s->size(); ++i) total += a[i] * m[i], scale += norm(a[i]) * m[i];
            // Pair terms cancel exactly; what is left is the round-off of summing N forces
            // of about a neighbour count of terms each: a few hundred eps of sum |m a|.
            EXPECT_LT(norm(total), 500 * eps * scale) << "scale " << scale;
        }
        // The two modes sum the same pair terms in a different order: they agree to round-off
        // relative to the largest acceleration.
        const auto as = sym.template getD2t<Vector<Dim>>(QuantityId::POSITION);
        const auto aa = asym.template getD2t<Vector<Dim>>(QuantityId::POSITION);
        double largest = 0, diff = 0;
        for (Size i = 0; i < sym.size(); ++i)
            largest = std::max(largest, norm(as[i])), diff = std::max(diff, norm(as[i] - aa[i]));
        EXPECT_GT(largest, 0.0);
        EXPECT_LT(diff, 100 * eps * largest);
    }
}

TEST(Solver, PairForceConservesMomentumAndModesAgree2D) { checkMomentumAndModes<2>(800, 0.04); }
TEST(Solver, PairForceConservesMomentumAndModesAgree3D) { checkMomentumAndModes<3>(1500, 0.07); }

/// Several leapfrog steps of moving particles (pair force, heat diffusion, reordering every
/// second step) on `threads` threads; returns the final storage.
template <int Dim>
Storage<Dim> runSteps(const std::string& mode, Size threads, const std::string& backend = "omp") {
    RunSettings settings;
    settings.set("smoothing_length", 0.05)
        .set("evaluation", mode)
        .set("threads", threads)
        .set("blocks", 7)
        .set("dt_fixed", 1e-3)
        .set("reorder_every", 2);
    Storage<Dim> s = enginetest::randomParticles<Dim>(1200, 99);
    const auto scheduler = makeScheduler(backend, threads);
    Solver<Dim> solver(
        *scheduler, settings,
        makeTerm<enginetest::PairForceTerm<Dim>>() + makeTerm<examples::HeatDiffusion<Dim>>(0.01),
        unitBox<Dim>(true));
    Material material;
    solver.create(s, material);
    LeapfrogKDK<Dim> leapfrog;
    Run<Dim> run(s, solver, leapfrog);
    for (int k = 0; k < 6; ++k) run.step();
    return s;
}

template <int Dim>
void expectBitwiseEqual(const Storage<Dim>& a, const Storage<Dim>& b) {
    ASSERT_EQ(a.size(), b.size());
    a.forEach([&](QuantityId id, const Quantity<Dim>& qa) {
        const Quantity<Dim>& qb = b.get(id);
        qa.visit([&](const auto& ba) {
            using T = typename std::decay_t<decltype(ba.value)>::value_type;
            const auto& bb = qb.template buffers<T>();
            for (int k = 0; k < qa.levels(); ++k)
                EXPECT_TRUE(ba.level(k) == bb.level(k)) << "quantity " << int(id) << " level " << k;
        });
    });
}

TEST(Solver, BitwiseReproducibleForAnyThreadCount) {
    for (const std::string mode : {"symmetric", "asymmetric"}) {
        SCOPED_TRACE(mode);
        const Storage<2> one = runSteps<2>(mode, 1);
        const Storage<2> two = runSteps<2>(mode, 2);
        const Storage<2> four = runSteps<2>(mode, 4);
        expectBitwiseEqual(one, two);
        expectBitwiseEqual(one, four);
        // The particles did move and exchange heat (the comparison is not of untouched data).
        const Storage<2> start = enginetest::randomParticles<2>(1200, 99);
        EXPECT_NE(one.getValue<Float>(QuantityId::ENERGY)[0],
                  start.getValue<Float>(QuantityId::ENERGY)[0]);
    }
    expectBitwiseEqual(runSteps<3>("symmetric", 1), runSteps<3>("symmetric", 4));
}

TEST(Solver, ThreadPoolBackendIsBitwiseTheSame) {
    for (const std::string mode : {"symmetric", "asymmetric"}) {
        SCOPED_TRACE(mode);
        const Storage<2> one = runSteps<2>(mode, 1);
        expectBitwiseEqual(one, runSteps<2>(mode, 2, "threads"));
        expectBitwiseEqual(one, runSteps<2>(mode, 3, "threads"));
    }
}

TEST(Scheduler, ThreadPoolRunsEveryChunkOnceAndPassesErrorsOn) {
    ThreadPoolScheduler pool(3);
    for (Size n : {0u, 1u, 7u, 1000u}) {
        std::vector<std::atomic<int>> hits(n);
        pool.parallelFor(n, 3, [&](Size b, Size e) {
            EXPECT_LE(e - b, 3u);
            for (Size i = b; i < e; ++i) hits[i]++;
            // A nested call runs inline on the calling thread.
            pool.parallelFor(4, 1, [](Size, Size) {});
        });
        for (Size i = 0; i < n; ++i) EXPECT_EQ(hits[i].load(), 1) << i;
    }
    EXPECT_THROW(pool.parallelFor(100, 1,
                                  [](Size b, Size) {
                                      if (b == 57) throw std::runtime_error("chunk 57");
                                  }),
                 std::runtime_error);
}

// The chunked reduction the time-step limits and the apps' checks use: on any scheduler the
// result is the serial scan's, ties included (the first particle of the largest value wins, as
// a scan with a strict comparison keeps it), and an empty range gives the initial value.
TEST(Scheduler, ReduceChunksGivesTheSerialScanOnEveryBackend) {
    struct Largest {
        double value;
        Size at;
    };
    const Size n = 100003;
    std::vector<double> x(n);
    for (Size i = 0; i < n; ++i) x[i] = double((i * 7919u) % 1009u);  // 1008 is hit 99 times
    Largest serial{-1, n};
    for (Size i = 0; i < n; ++i)
        if (x[i] > serial.value) serial = {x[i], i};
    const auto chunk = [&](Size b, Size e, Largest& l) {
        for (Size i = b; i < e; ++i)
            if (x[i] > l.value) l = {x[i], i};
    };
    const auto combine = [](Largest& l, const Largest& p) {
        if (p.value > l.value) l = p;
    };
    SequentialScheduler sequential;
    ParallelScheduler omp(3);
    ThreadPoolScheduler pool(3);
    for (IScheduler* s : std::initializer_list<IScheduler*>{&sequential, &omp, &pool})
        for (Size grain : {1u, 97u, 8192u, 200000u}) {
            const Largest l = reduceChunks(*s, n, grain, Largest{-1, n}, chunk, combine);
            EXPECT_EQ(l.value, serial.value);
            EXPECT_EQ(l.at, serial.at) << "grain " << grain;
        }
    EXPECT_EQ(reduceChunks(pool, 0, 8, Largest{-1, n}, chunk, combine).at, n);
    // largestOf, the usual reduction: a NaN is passed over, as a serial std::max scan does.
    x[70000] = std::nan("");
    EXPECT_EQ(largestOf(pool, n, [&](Size i) { return x[i]; }), serial.value);
}

/// A term that gathers over neighbours before the pair loop, as the wall condition does: it
/// records the neighbour lists beginEvaluation gave it and, in initialize, every particle's
/// neighbours as the shared gather finds them, in the order it finds them.
template <int Dim>
class GatherProbe : public IEquationTerm<Dim> {
  public:
    explicit GatherProbe(std::shared_ptr<const NeighbourGather<Dim>> gather)
        : gather_(std::move(gather)) {}
    void setDerivatives(DerivativeHolder<Dim>&, const RunSettings&) override {}
    void beginEvaluation(const EvaluationContext<Dim>& context) override {
        neighbours = &context.neighbours;
        ++begun;
    }
    void initialize(IScheduler& scheduler, Storage<Dim>& s, Float) override {
        EXPECT_EQ(begun, ++initialized) << "beginEvaluation runs before initialize";
        std::vector<Size> all(s.size());
        for (Size i = 0; i < s.size(); ++i) all[i] = i;
        found.assign(s.size(), {});
        gather_->forEach(scheduler, all, [&](Size i, auto&& visit) {
            visit([&](Size j, const Vector<Dim>&, Float, Float) { found[i].push_back(j); });
        });
    }
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}
    void create(Storage<Dim>&, IMaterial&) const override {}

    const num::VerletList<Dim>* neighbours = nullptr;
    int begun = 0, initialized = 0;
    std::vector<std::vector<Size>> found;

  private:
    std::shared_ptr<const NeighbourGather<Dim>> gather_;
};

/// One neighbour structure for every pass: the gathers before the pair loop read the solver's
/// own neighbour lists, valid for the positions of this evaluation, and find exactly the
/// neighbours of a brute-force search (nearest periodic images, the particle itself included),
/// in increasing index.
template <int Dim>
void checkGatherSharesTheSolversNeighbours(bool periodic) {
    SCOPED_TRACE(periodic ? "periodic" : "open");
    RunSettings settings;
    settings.set("smoothing_length", 0.06);
    Storage<Dim> s = enginetest::randomParticles<Dim>(Dim == 2 ? 400 : 1500, 23);
    ParallelScheduler scheduler(3);
    const num::Domain<Dim> domain = unitBox<Dim>(periodic);
    auto gather = std::make_shared<NeighbourGather<Dim>>();
    Solver<Dim> solver(scheduler, settings,
                       makeTerm<NeighbourRefresh<Dim>>(gather) + makeTerm<GatherProbe<Dim>>(gather),
                       domain);
    Material material;
    solver.create(s, material);
    const auto* probe = solver.equations().template find<GatherProbe<Dim>>();
    ASSERT_NE(probe, nullptr);
    const double R = solver.kernel().supportRadius();
    for (int evaluation = 0; evaluation < 2; ++evaluation) {
        solver.evaluate(s, 0);
        EXPECT_EQ(probe->neighbours, &solver.neighbours())
            << "the pair loop's lists, not a second structure";
        EXPECT_EQ(probe->begun, evaluation + 1);
        const auto x = s.template getValue<Vector<Dim>>(QuantityId::POSITION);
        std::size_t pairs = 0;
        for (Size i = 0; i < s.size(); ++i) {
            std::vector<Size> expected;
            for (Size j = 0; j < s.size(); ++j) {
                const auto dx = periodic ? domain.minimumImage(x[i] - x[j]) : x[i] - x[j];
                if (normSqr(dx) < R * R) expected.push_back(j);
            }
            pairs += expected.size();
            ASSERT_EQ(probe->found[i], expected) << "particle " << i;
        }
        EXPECT_GT(pairs, 5 * std::size_t(s.size()));
        // The next evaluation sees moved particles (beyond the skin: the lists are rebuilt).
        auto xm = s.template getValue<Vector<Dim>>(QuantityId::POSITION);
        for (Size i = 0; i < s.size(); ++i)
            xm[i] = domain.wrap(xm[i] + Vector<Dim>::filled(0.3 * R * ((i % 7) - 3.0)));
        if (!periodic)
            for (Size i = 0; i < s.size(); ++i)
                for (int k = 0; k < Dim; ++k) xm[i][k] = std::clamp(xm[i][k], 0.0, 1.0);
    }
}

TEST(Solver, GathersBeforeThePairLoopReadTheSolversOneNeighbourStructure) {
    for (bool periodic : {false, true}) {
        checkGatherSharesTheSolversNeighbours<2>(periodic);
        checkGatherSharesTheSolversNeighbours<3>(periodic);
    }
}

TEST(Solver, GatherWithoutNeighbourListsSaysSo) {
    NeighbourGather<2> gather;
    RunSettings settings;
    settings.set("smoothing_length", 0.1);
    gather.setKernel(settings);
    SequentialScheduler scheduler;
    const std::vector<Size> targets{0};
    EXPECT_THROW(gather.forEach(scheduler, targets, [](Size, auto&&) {}), std::logic_error);
}

/// A term that offers the given limits.
class OfferLimits : public IEquationTerm<2> {
  public:
    OfferLimits(double courant, double viscous) : courant_(courant), viscous_(viscous) {}
    void setDerivatives(DerivativeHolder<2>&, const RunSettings&) override {}
    void initialize(IScheduler&, Storage<2>&, Float) override {}
    void finalize(IScheduler&, Storage<2>&, Float) override {}
    void create(Storage<2>&, IMaterial&) const override {}
    void limitTimeStep(const Storage<2>&, const RunSettings& s,
                       TimeStepLimits& limits) const override {
        limits.offer("courant", courantTimeStep(s.get<double>("cfl"), 1.0, courant_, 0.0));
        limits.offer("viscous", viscousTimeStep(s.get<double>("viscous_factor"), 1.0, viscous_));
    }

  private:
    double courant_, viscous_;
};

struct StepResult {
    double dt;
    std::string criterion;
};

StepResult oneStep(double soundSpeed, double nu, double k, RunSettings settings = {}) {
    settings.set("smoothing_length", 1.0);
    Storage<2> s;
    s.insert<Vector<2>>(QuantityId::POSITION, OrderEnum::SECOND,
                        std::vector<Vector<2>>{Vector<2>{{1.0, 0.0}}});
    s.insert<Float>(QuantityId::MASS, OrderEnum::ZERO, 1.0);
    SequentialScheduler scheduler;
    Solver<2> solver(
        scheduler, settings,
        makeTerm<OfferLimits>(soundSpeed, nu) + makeTerm<examples::SpringForce<2>>(k, 1e-9),
        num::Domain<2>{});
    Material material;
    solver.create(s, material);
    LeapfrogKDK<2> leapfrog;
    num::sph::Run<2> run(s, solver, leapfrog);
    run.step();
    return {run.lastDt(), run.limitingCriterion()};
}

TEST(RunLoop, AdaptiveStepIsTheSmallestCriterionAndNamesIt) {
    // Courant 0.25 * 1 / c, viscous 0.125 * 1 / nu, acceleration 0.25 sqrt(h / |a|) with
    // |a| = k |x| / m = k (the spring offers 1e9 sqrt(m/k), never the smallest).
    StepResult r = oneStep(10.0, 1.0, 1e-6);
    EXPECT_EQ(r.criterion, "courant");
    EXPECT_DOUBLE_EQ(r.dt, 0.25 / 10.0);
    r = oneStep(1.0, 10.0, 1e-6);
    EXPECT_EQ(r.criterion, "viscous");
    EXPECT_DOUBLE_EQ(r.dt, 0.125 / 10.0);
    r = oneStep(1.0, 1.0, 1e4);
    EXPECT_EQ(r.criterion, "acceleration");
    EXPECT_DOUBLE_EQ(r.dt, 0.25 * std::sqrt(1.0 / 1e4));
    RunSettings capped;
    capped.set("dt_max", 1e-3);
    r = oneStep(1.0, 1.0, 1e-6, capped);
    EXPECT_EQ(r.criterion, "dt_max");
    EXPECT_DOUBLE_EQ(r.dt, 1e-3);
    RunSettings fixed;
    fixed.set("dt_fixed", 0.5);
    r = oneStep(10.0, 10.0, 1e4, fixed);
    EXPECT_EQ(r.criterion, "fixed");
    EXPECT_DOUBLE_EQ(r.dt, 0.5);
}

TEST(RunLoop, StopsExactlyAtTheEndTime) {
    RunSettings settings;
    settings.set("smoothing_length", 1.0).set("dt_fixed", 0.3);
    Storage<2> s;
    s.insert<Vector<2>>(QuantityId::POSITION, OrderEnum::SECOND, std::vector<Vector<2>>(1));
    s.insert<Float>(QuantityId::MASS, OrderEnum::ZERO, 1.0);
    SequentialScheduler scheduler;
    Solver<2> solver(scheduler, settings, makeTerm<examples::SpringForce<2>>(1.0), {});
    Material material;
    solver.create(s, material);
    LeapfrogKDK<2> leapfrog;
    num::sph::Run<2> run(s, solver, leapfrog);
    run.advanceTo(1.0);
    EXPECT_EQ(run.time(), 1.0);
    EXPECT_EQ(run.steps(), 4u);  // 0.3, 0.3, 0.3, then 0.1 to the end
    EXPECT_EQ(run.limitingCriterion(), "end time");
}

}  // namespace
