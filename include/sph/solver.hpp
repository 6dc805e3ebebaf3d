// The solver: the state constraints (constrain: the periodic wrap and the terms' constrain,
// such as the density floor at free surfaces), then one evaluation of all derivatives
// (neighbour search, terms' beginEvaluation, then the passes of sph/evaluation_schedule.hpp,
// each: its terms' initialize, the pair loop over blocks, the sum of the blocks' buffers, its
// terms' finalize), the post-step phase (terms' postStep, once per step after the integrator)
// and the time-step limits. The constraints run at the start of every evaluate, so that every
// state an integrator evaluates (its predicted ones too) satisfies them; the evaluation after
// them has no side effects on the state (what moves particles runs in postStep), which debug
// builds check (sph/evaluation_purity.hpp).
//
// One neighbour structure for every pass: Verlet lists (spatial/neighbour_list.hpp), updated
// after the periodic wrap and before the terms' initialize, rebuilt only when a particle has
// moved more than half the skin since the last build (the skin adapts to the flow's speed
// between the settings "neighbour_skin" and "neighbour_skin_max") or when the particles were
// renumbered (invalidateNeighbours). They serve the gathers terms run before the
// pair loop (the wall condition, density by summation: EvaluationContext, NeighbourGather) and
// the pair loop itself. Neighbours are filtered by the current distance and come in increasing
// index, so results do not depend on the skin or on when the lists were built.
//
// Several processes (sph/decomposition.hpp, setDecomposition): the pair loops run over the
// particles this process owns; halo copies are refreshed from their owners after each term's
// initialize (what it prepares), after all of them, after each pass's finalize and after the
// post-step phase; the time-step limits are combined over the processes.
//
// Reproducibility: particles are split into blocks, each evaluated by one thread in particle
// order with its own derivative objects. Symmetric mode: a fixed number of blocks (setting
// "blocks"), each with its own buffers, summed in block order. Asymmetric mode: each particle
// gathers its own sum into its own entry, whatever the split. Either way the result is bitwise
// the same for any number of threads.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <span>
#include <stdexcept>
#include <vector>

#include "spatial/neighbour_list.hpp"
#include "sph/decomposition.hpp"
#include "sph/defaults.hpp"
#include "sph/equation_term.hpp"
#include "sph/evaluation_purity.hpp"
#include "sph/formulas/pair_geometry.hpp"
#include "sph/formulas/time_step.hpp"
#include "sph/kernel_choice.hpp"

namespace num::sph {

/// Thrown by Solver::evaluate when its abandon check asked to stop part-way (a Ctrl-C during a
/// step that would take long): the storage is left part-way through the step.
struct EvaluationAbandoned : std::runtime_error {
    EvaluationAbandoned() : std::runtime_error("evaluation abandoned") {}
};

template <int Dim>
class Solver {
  public:
    using Vec = Vector<Dim>;

    Solver(IScheduler& scheduler, const RunSettings& settings, EquationHolder<Dim> equations,
           Domain<Dim> domain)
        : scheduler_(scheduler),
          settings_(settings),
          equations_(std::move(equations)),
          domain_(domain),
          kernel_(settings),
          symmetric_(settings.get<std::string>("evaluation") == "symmetric"),
          schedule_(equations_.schedule()),
          passes_(schedule_.passes.size()),
          scratch_(blockCount(settings, symmetric_, scheduler.threadCount())) {
        for (std::size_t p = 0; p < passes_.size(); ++p) {
            PairPass& pass = passes_[p];
            pass.holders.resize(scratch_.size());
            pass.accumulated.resize(symmetric_ ? scratch_.size() : 1);
            if (!symmetric_) pass.accumulated[0].sumInStorage();
            for (std::size_t b = 0; b < pass.holders.size(); ++b) {
                equations_.setDerivatives(pass.holders[b], settings_,
                                          schedule_.passes[p].derivatives);
                pass.holders[b].create(pass.accumulated[symmetric_ ? b : 0]);
            }
            pass.needsW = pass.holders[0].needsKernelValues();
        }
        neighbours_.configure(kernel_.supportRadius(), settings_.get<double>("neighbour_skin"),
                              domain_, settings_.get<double>("neighbour_skin_max"));
    }

    /// Creates the quantities every term needs (once, before the first evaluation).
    void create(Storage<Dim>& storage, IMaterial& material) {
        storage.template insert<Vec>(QuantityId::POSITION, OrderEnum::SECOND, Vec{});
        equations_.create(storage, material);
    }

    /// A test the pair loop asks every kAbandonCheckEvery particles of a block (never per pair);
    /// when it returns true, evaluate() stops and throws EvaluationAbandoned.
    void setAbandonCheck(std::function<bool()> check) { abandonCheck_ = std::move(check); }
    static constexpr Size kAbandonCheckEvery = 64;

    /// The state constraints, before every evaluation: positions on periodic axes wrapped into
    /// the domain, then every term's constrain (the fluid model's density floor at free
    /// surfaces). They change the state; a second call changes nothing.
    void constrain(Storage<Dim>& storage) {
        if (domain_.anyPeriodic())
            for (Vec& p : storage.template getValue<Vec>(QuantityId::POSITION)) p = domain_.wrap(p);
        equations_.forTerms([&](auto& term) { term.constrain(scheduler_, storage); });
    }

    /// Constrains the state (constrain), then evaluates every derivative at time t, which has
    /// no side effects on the state: debug builds check it (evaluateCheckingPurity).
    void evaluate(Storage<Dim>& storage, Float t) {
#ifndef NDEBUG
        evaluateCheckingPurity(storage, t);
#else
        constrain(storage);
        evaluateDerivatives(storage, t, nullptr);
#endif
    }

    /// evaluate, checking after every term's initialize and finalize and every pair loop that
    /// the evolved state is still the one constrain left (sph/evaluation_purity.hpp): throws
    /// ImpureEvaluation naming the quantity and the term otherwise.
    void evaluateCheckingPurity(Storage<Dim>& storage, Float t) {
        constrain(storage);
        EvaluationPurity<Dim> purity(storage);
        evaluateDerivatives(storage, t, &purity);
    }

    /// The post-step phase: every term's postStep, in term order, once per step after the
    /// integrator advanced the storage by dt to time t (sph::Run::step calls it).
    void postStep(Storage<Dim>& storage, Float t, Float dt) {
        equations_.forTerms([&](auto& term) { term.postStep(scheduler_, storage, t, dt); });
        if (decomposition_) decomposition_->exchangeHalo(storage);
    }

    /// The time-step limits at the current state (after an evaluation).
    TimeStepLimits timeStepLimits(const Storage<Dim>& storage) const {
        TimeStepLimits limits(scheduler_);
        if (const double fixed = settings_.get<double>("dt_fixed"); fixed > 0) {
            limits.offer("fixed", fixed);
            return limits;
        }
        limits.offer("dt_max", settings_.get<double>("dt_max"));
        const auto acc = storage.template getD2t<Vec>(QuantityId::POSITION);
        const Float a2max =
            largestOf(scheduler_, Size(acc.size()), [&](Size i) { return normSqr(acc[i]); });
        if (a2max > 0)
            limits.offer("acceleration",
                         formulas::accelerationStep(settings_.get<double>("acceleration_factor"),
                                                    kernel_.h, a2max));
        equations_.forTerms(
            [&](const auto& term) { term.limitTimeStep(storage, settings_, limits); });
        if (decomposition_) decomposition_->combine(limits);
        return limits;
    }

    /// Mean number of neighbours per particle the last evaluation gathered for (each pair
    /// counted twice).
    double meanNeighbours() const { return meanNeighbours_; }
    /// The neighbour lists of the last evaluation.
    const VerletList<Dim>& neighbours() const { return neighbours_; }
    /// Forces the neighbour lists to be rebuilt at the next evaluation: call it after
    /// reordering, adding or removing particles (reorderByCell does).
    void invalidateNeighbours() { neighbours_.invalidate(); }
    const EquationHolder<Dim>& equations() const { return equations_; }
    /// The passes of an evaluation (EvaluationSchedule::describe names their terms).
    const EvaluationSchedule& schedule() const { return schedule_; }
    const Domain<Dim>& domain() const { return domain_; }
    const RunSettings& settings() const { return settings_; }
    const RunKernel<Dim>& kernel() const { return kernel_; }
    IScheduler& scheduler() { return scheduler_; }
    /// Runs on the particles a domain decomposition gives this process (nullptr: all of them).
    /// Only the gather evaluation can: symmetric pairs would add into halo copies.
    void setDecomposition(IDecomposition<Dim>* decomposition) {
        if (decomposition && symmetric_)
            throw std::invalid_argument(
                "evaluation \"symmetric\" cannot run on several processes: use \"gather\"");
        decomposition_ = decomposition;
    }
    IDecomposition<Dim>* decomposition() const { return decomposition_; }

  private:
    /// Symmetric mode: the "blocks" setting (each block has buffers of every particle, and the
    /// results depend on the split). Asymmetric mode: every particle gathers its own sum, so
    /// the split never changes a result; at least 8 blocks per thread balance the load.
    static std::size_t blockCount(const RunSettings& s, bool symmetric, Size threads) {
        const auto blocks = std::size_t(s.get<std::int64_t>("blocks"));
        return symmetric ? blocks : std::max<std::size_t>(blocks, 8 * std::size_t(threads));
    }

    /// One pair loop of an evaluation: the derivatives of each block and the buffers they sum
    /// into (one set per block in symmetric mode; in asymmetric mode one shared set, which sums
    /// into the storage's arrays: Accumulated::sumInStorage).
    struct PairPass {
        std::vector<DerivativeHolder<Dim>> holders;
        std::vector<Accumulated<Dim>> accumulated;
        bool needsW = false;
    };

    /// A block's buffers, written for every particle: on cache lines of their own, so that
    /// threads on neighbouring blocks do not invalidate each other's (false sharing).
    struct alignas(64) Scratch {
        typename VerletList<Dim>::Neighbours found;
        std::vector<Vec> grads;
        std::vector<Float> r, gradientFactor, w, laplacian, inverseR2;
        std::size_t pairs = 0, evaluated = 0;
    };

    static void zeroHighestDerivatives(Storage<Dim>& storage) {
        storage.forEach([](QuantityId, Quantity<Dim>& q) {
            if (q.order() == OrderEnum::ZERO) return;
            q.visit([&](auto& b) {
                auto& top = b.level(int(q.order()));
                std::fill(top.begin(), top.end(),
                          typename std::decay_t<decltype(top)>::value_type{});
            });
        });
    }

    /// The evaluation after the constraints; purity (may be null) checks it.
    void evaluateDerivatives(Storage<Dim>& storage, Float t, EvaluationPurity<Dim>* purity) {
        zeroHighestDerivatives(storage);
        neighbours_.update(
            storage.template getValue<Vec>(QuantityId::POSITION),
            [&](std::size_t n, const auto& body) { scheduler_.parallelFor(Size(n), 1, body); });
        const EvaluationContext<Dim> context{neighbours_, decomposition_};
        equations_.forTerms([&](auto& term) { term.beginEvaluation(context); });
        for (std::size_t p = 0; p < passes_.size(); ++p) evaluatePass(storage, t, p, purity);
    }

    /// One pass: its terms' initialize, its pair loop, its terms' finalize.
    void evaluatePass(Storage<Dim>& storage, Float t, std::size_t p,
                      EvaluationPurity<Dim>* purity) {
        const EvaluationSchedule::Pass& order = schedule_.passes[p];
        equations_.forTerms(order.terms, [&](auto& term) {
            term.initialize(scheduler_, storage, t);
            if (purity)
                purity->verify(storage, "the term " + term.name() + " (initialize)",
                               term.access().prepares);
            // What a term prepares, later terms of the pass may read of a halo neighbour.
            if (!decomposition_) return;
            if (const TermAccess access = term.access(); !access.prepares.empty())
                exchangeHalo(storage, purity, access.prepares);
        });
        exchangeHalo(storage, purity);
        PairPass& pass = passes_[p];
        if (p == 0 || pass.holders[0].size() > 0) {
            sumPairs(storage, pass);
            if (purity)
                purity->verify(storage, "the pair sums of pass " + std::to_string(p + 1) +
                                            " (the derivatives its terms required)");
        }
        equations_.forTerms(order.terms, [&](auto& term) {
            term.finalize(scheduler_, storage, t);
            if (purity) purity->verify(storage, "the term " + term.name() + " (finalize)");
        });
        exchangeHalo(storage, purity);
    }

    /// Refreshes the halo copies (several processes), whose values are their owners'.
    void exchangeHalo(Storage<Dim>& storage, EvaluationPurity<Dim>* purity,
                      std::span<const QuantityId> only = {}) {
        if (!decomposition_) return;
        decomposition_->exchangeHalo(storage, only);
        if (purity) purity->keep(storage);
    }

    /// The pair loop of a pass and the sum of its blocks' buffers into the storage.
    void sumPairs(Storage<Dim>& storage, PairPass& pass) {
        const auto forRanges = [&](Size n, const auto& range) {
            scheduler_.parallelFor(n, 8192, range);
        };
        for (auto& a : pass.accumulated) a.reset(storage);
        pass.holders[0].initialize(storage, pass.accumulated[0]);
        for (std::size_t b = 1; b < pass.holders.size(); ++b)
            pass.holders[b].initializeLike(pass.holders[0], storage,
                                           pass.accumulated[symmetric_ ? b : 0]);
        for (auto& a : pass.accumulated) a.startSums(forRanges);
        withKernel<Dim>(kernel_.type, [&](auto k) { pairLoop(storage, k, pass); });
        if (abandoned_.exchange(false)) throw EvaluationAbandoned();
        Accumulated<Dim>::addInto(storage, std::span<const Accumulated<Dim>>(pass.accumulated),
                                  forRanges);
    }

    /// The constants of a pass's pair geometry.
    template <class Kernel>
    struct PairConstants {
        GradientFactor<Kernel> gradient;
        KernelValue<Kernel> kernelValue;
        Float laplacianEta2, inverseR2Eta2;
        bool needsW;
    };

    template <class Kernel>
    void pairLoop(Storage<Dim>& storage, Kernel, PairPass& pass) {
        const std::uint64_t n = storage.size();
        const std::uint64_t blocks = pass.holders.size();
        const Float h = kernel_.h;
        const PairConstants<Kernel> constants{GradientFactor<Kernel>(h), KernelValue<Kernel>(h),
                                              defaults::laplacianEta2 * h * h,
                                              defaults::inverseR2Eta2 * h * h, pass.needsW};
        const char* owned = decomposition_ ? decomposition_->owned().data() : nullptr;
        // Gathering, a boundary particle is skipped unless a derivative adds anything for it.
        const int* kind = !symmetric_ && storage.has(QuantityId::KIND)
                              ? storage.template getValue<int>(QuantityId::KIND).data()
                              : nullptr;
        scheduler_.parallelFor(Size(blocks), 1, [&](Size b0, Size b1) {
            for (Size b = b0; b < b1; ++b)
                pairBlock(b, Size(n * b / blocks), Size(n * (b + 1) / blocks), constants, owned,
                          kind, pass);
        });
        countNeighbours(owned != nullptr);
    }

    /// Evaluates block b's particles [begin, end) with their neighbours. The constants are a copy
    /// local to the function (as in neighbourGeometry): no store of the loops may alias them.
    template <class Kernel>
    void pairBlock(Size b, Size begin, Size end, const PairConstants<Kernel> constants,
                   const char* owned, const int* kind, PairPass& pass) {
        Scratch& sc = scratch_[b];
        sc.pairs = 0, sc.evaluated = 0;
        DerivativeHolder<Dim>& holder = pass.holders[b];
        for (Size i = begin; i < end; ++i) {
            if ((i - begin) % kAbandonCheckEvery == 0 && abandonRequested()) break;
            if (owned && !owned[i]) continue;  // a halo copy: its owner evaluates it
            if (kind && !isFluid(kind[i]) && !holder.gathersAtBoundary(i)) continue;
            ++sc.evaluated;
            const Size m = symmetric_ ? neighbours_.collectAfter(i, sc.found)
                                      : neighbours_.collect(i, sc.found);
            sc.pairs += m;
            const NeighbourGeometry<Dim> geo = neighbourGeometry(sc, m, constants);
            const ArrayView<const Size> neighs(sc.found.j.data(), m);
            const ArrayView<const Vec> g(sc.grads.data(), m);
            if (symmetric_)
                holder.evalSymmetric(i, neighs, g, geo);
            else
                holder.evalAsymmetric(i, neighs, g, geo);
        }
    }

    /// Whether the evaluation is to be abandoned (asked of abandonCheck_ and remembered).
    bool abandonRequested() {
        if (!abandonCheck_ || !(abandoned_.load(std::memory_order_relaxed) || abandonCheck_()))
            return false;
        abandoned_.store(true, std::memory_order_relaxed);
        return true;
    }

    /// The geometry of PairGeometry for the m neighbours in sc.found, in loops the compiler
    /// vectorises (the scalar factors apart from the vectors they scale); the constants are a
    /// copy local to the function, so that no store of the loops may alias them (else they are
    /// reloaded every pair).
    template <class Kernel>
    static NeighbourGeometry<Dim> neighbourGeometry(Scratch& sc, Size m,
                                                    const PairConstants<Kernel> c) {
        if (sc.r.size() < m) {
            sc.r.resize(2 * m), sc.gradientFactor.resize(2 * m), sc.grads.resize(2 * m);
            sc.laplacian.resize(2 * m), sc.inverseR2.resize(2 * m);
        }
        if (c.needsW && sc.w.size() < m) sc.w.resize(2 * m);  // passes differ in W
        const Vec* dx = sc.found.dx.data();
        const double* r2 = sc.found.r2.data();
        Float* r = sc.r.data();
        Float* gradientFactor = sc.gradientFactor.data();
        Vec* grads = sc.grads.data();
        Float* laplacian = sc.laplacian.data();
        Float* inverseR2 = sc.inverseR2.data();
        for (Size k = 0; k < m; ++k) r[k] = std::sqrt(r2[k]);
        for (Size k = 0; k < m; ++k) gradientFactor[k] = c.gradient.factor(r[k]);
        for (Size k = 0; k < m; ++k) grads[k] = dx[k] * gradientFactor[k];
        for (Size k = 0; k < m; ++k)
            laplacian[k] = formulas::pairLaplacian(dx[k], grads[k], r[k], c.laplacianEta2);
        for (Size k = 0; k < m; ++k) inverseR2[k] = formulas::pairInverseR2(r[k], c.inverseR2Eta2);
        if (c.needsW) {
            Float* w = sc.w.data();
            for (Size k = 0; k < m; ++k) w[k] = c.kernelValue.value(r[k]);
        }
        return {ArrayView<const Vec>(dx, m), ArrayView<const Float>(r, m),
                ArrayView<const Float>(sc.w.data(), c.needsW ? m : 0),
                ArrayView<const Float>(laplacian, m), ArrayView<const Float>(inverseR2, m)};
    }

    /// The mean number of neighbours of the particles evaluated (over every process).
    void countNeighbours(bool decomposed) {
        std::int64_t pairs = 0, evaluated = 0;
        for (const Scratch& sc : scratch_)
            pairs += std::int64_t(sc.pairs), evaluated += std::int64_t(sc.evaluated);
        if (decomposed)
            pairs = decomposition_->sum(pairs), evaluated = decomposition_->sum(evaluated);
        meanNeighbours_ =
            evaluated ? double(pairs) * (symmetric_ ? 2.0 : 1.0) / double(evaluated) : 0.0;
    }

    IScheduler& scheduler_;
    RunSettings settings_;
    EquationHolder<Dim> equations_;
    Domain<Dim> domain_;
    RunKernel<Dim> kernel_;
    bool symmetric_;
    EvaluationSchedule schedule_;
    std::vector<PairPass> passes_;
    std::vector<Scratch> scratch_;  // per block, shared by the passes
    VerletList<Dim> neighbours_;
    double meanNeighbours_ = 0;
    IDecomposition<Dim>* decomposition_ = nullptr;
    std::function<bool()> abandonCheck_;
    std::atomic<bool> abandoned_{false};
};

}  // namespace num::sph
