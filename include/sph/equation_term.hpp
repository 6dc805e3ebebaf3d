// Equation terms: what appears on the right-hand sides of the evolution equations.
//
// Order of the hooks in one evaluation (Solver::evaluate):
//   0. the state constraints (Solver::constrain): positions on periodic axes are wrapped into
//      the domain, then constrain() of every term, in the order the terms were added (the
//      fluid model's density floor at free surfaces). They may change the state, and a second
//      call changes nothing; they run before every evaluation, so every state an integrator
//      evaluates satisfies them;
//   1. the highest time derivative of every quantity is set to zero;
//   2. the neighbour search: the neighbour lists of the positions (Verlet lists, rebuilt only
//      when particles moved far enough), used by every pass of the evaluation;
//      beginEvaluation() of every term receives them (EvaluationContext);
//   3. the passes (sph/evaluation_schedule.hpp), each:
//      a. initialize() of the pass's terms, in the order the terms were added (positions stay
//         as the lists read them until the evaluation ends);
//      b. initialize() of every derivative the pass's terms required (setDerivatives, once per
//         block when the solver is made) and the pair loop over them;
//      c. the accumulated sums go to the storage: a value target is replaced by its sum, a dt or
//         d2t target gets its sum added (the gather loop sums straight into the stored arrays,
//         a value's zeroed after the derivatives' initialize: Accumulated);
//      d. finalize() of the pass's terms, in the order the terms were added.
//   A term goes to the first pass in which what it reads is ready (access()): a term that reads
//   another's pair sums runs one pass later. Terms that declare nothing share the first pass.
// Steps 1 to 3 have no side effects on the state: no hook there moves a particle or changes an
// evolved quantity (the values of quantities of order FIRST or SECOND, and velocities), so
// evaluating twice at the same t gives the same rates (integrators may evaluate several times
// per step). Debug builds check it after every hook (sph/evaluation_purity.hpp). One exception
// is left: the free-surface flags come from the previous evaluation's kernel sum
// (terms/free_surface.hpp), a quantity of order ZERO.
// Post-step phase: postStep() of every term, in the order the terms were added, once per step
// after the integrator (Solver::postStep, called by Run::step with the step's dt and the new
// time). It reads what the step's last evaluation left in the storage and may change the
// state: particle shifting, containment, bookkeeping.
// create() runs once, from Solver::create, before the first evaluation.
// Terms add to derivatives (+=); a term never assigns a derivative another term writes.
#pragma once

#include <algorithm>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "spatial/neighbour_list.hpp"
#include "sph/derivative.hpp"
#include "sph/evaluation_schedule.hpp"
#include "sph/scheduler.hpp"
#include "sph/type_name.hpp"

namespace num::sph {

/// The time-step limits offered by terms; the step is their minimum.
class TimeStepLimits {
  public:
    /// scheduler: the threads a term's limitTimeStep may use for its reductions (reduceChunks).
    explicit TimeStepLimits(IScheduler& scheduler) : scheduler_(&scheduler) {}
    IScheduler& scheduler() const { return *scheduler_; }
    /// Offers dt for the named criterion (ignored unless positive and finite).
    void offer(const std::string& criterion, Float dt) {
        if (!(dt > 0) || dt == std::numeric_limits<Float>::infinity()) return;
        if (dt < dt_) dt_ = dt, criterion_ = criterion;
    }
    Float dt() const { return dt_; }
    const std::string& criterion() const { return criterion_; }

  private:
    IScheduler* scheduler_;
    Float dt_ = std::numeric_limits<Float>::infinity();
    std::string criterion_ = "none";
};

/// The usual time-step criteria (each with its factor from RunSettings); offer them with
/// TimeStepLimits::offer under the names "courant", "viscous", "diffusion".
/// Courant: dt <= C h / (c + |v|_max) (Monaghan 1992, sec. 10).
inline Float courantTimeStep(Float cfl, Float h, Float soundSpeed, Float maxSpeed) {
    return cfl * h / (soundSpeed + maxSpeed);
}
/// Viscous diffusion: dt <= f h^2 / nu (Morris, Fox & Zhu 1997, eq. 23 with f = 0.125).
inline Float viscousTimeStep(Float factor, Float h, Float nu) { return factor * h * h / nu; }
/// Heat diffusion: dt <= f h^2 / alpha (Cleary & Monaghan 1999).
inline Float diffusionTimeStep(Float factor, Float h, Float alpha) {
    return factor * h * h / alpha;
}

/// What the solver has prepared when an evaluation starts (IEquationTerm::beginEvaluation):
/// the neighbour lists of the storage's current positions, of radius the kernel's support
/// radius, in the solver's domain, which the pair loop uses too. Valid until the evaluation
/// ends; particle i of the storage is particle i of the lists:
/// neighbours.forEachNeighbourOf(i, f) calls f(j, dx = x_i - x_j, r2) for every j within the
/// support radius (nearest images, i itself included), in increasing j.
template <int Dim>
class IDecomposition;

/// `decomposition`: the run's processes (sph/decomposition.hpp), null on one process.
template <int Dim>
struct EvaluationContext {
    const VerletList<Dim>& neighbours;
    const IDecomposition<Dim>* decomposition = nullptr;
};

template <int Dim>
class IEquationTerm {
  public:
    static constexpr int dim = Dim;
    virtual ~IEquationTerm() = default;
    /// Requires the derivatives (pairwise sums) the term needs. Called once per block.
    virtual void setDerivatives(DerivativeHolder<Dim>& derivatives,
                                const RunSettings& settings) = 0;
    /// Holds the state within what the term allows (the fluid model's density floor at free
    /// surfaces), before every evaluation (Solver::constrain). May change evolved quantities;
    /// a second call must change nothing. Default: nothing.
    virtual void constrain(IScheduler&, Storage<Dim>&) {}
    /// Runs at the start of each evaluation, before any term's initialize, with the
    /// evaluation's neighbour lists: a term that gathers over neighbours before the pair loop
    /// keeps a reference to them for its initialize. Default: nothing.
    virtual void beginEvaluation(const EvaluationContext<Dim>&) {}
    /// Runs before the pair loop, e.g. to compute pressure from density. Changes no evolved
    /// quantity (see constrain).
    virtual void initialize(IScheduler& scheduler, Storage<Dim>& storage, Float t) = 0;
    /// Runs after the pair loop; adds the term's contribution to the derivatives. Moves no
    /// particle and changes no evolved quantity (that belongs in postStep or constrain).
    virtual void finalize(IScheduler& scheduler, Storage<Dim>& storage, Float t) = 0;
    /// Runs once per step, after the integrator has advanced the storage from t - dt to t
    /// (t the new time); may change the state, e.g. move particles. Default: nothing.
    virtual void postStep(IScheduler&, Storage<Dim>&, Float /*t*/, Float /*dt*/) {}
    /// Creates the quantities the term needs.
    virtual void create(Storage<Dim>& storage, IMaterial& material) const = 0;
    /// Offers the term's time-step limits (Courant, viscous, diffusion...).
    virtual void limitTimeStep(const Storage<Dim>&, const RunSettings&, TimeStepLimits&) const {}
    /// What the term reads, prepares and produces, from which the solver orders the terms into
    /// passes (sph/evaluation_schedule.hpp). Default: nothing declared (the first pass, in the
    /// order the terms were added).
    virtual TermAccess access() const { return {}; }
    /// The term's name in messages and in the apps' summary.json. Default: its type.
    virtual std::string name() const { return typeName(*this); }
};

/// An ordered set of terms, built with makeTerm and + / +=.
template <int Dim>
class EquationHolder {
  public:
    EquationHolder() = default;
    explicit EquationHolder(std::shared_ptr<IEquationTerm<Dim>> term) {
        terms_.push_back(std::move(term));
    }

    EquationHolder& operator+=(const EquationHolder& other) {
        terms_.insert(terms_.end(), other.terms_.begin(), other.terms_.end());
        return *this;
    }
    friend EquationHolder operator+(EquationHolder a, const EquationHolder& b) { return a += b; }

    /// Requires the derivatives of the terms listed (indices in the order added), in that order.
    void setDerivatives(DerivativeHolder<Dim>& d, const RunSettings& s,
                        std::span<const std::size_t> which) const {
        for (std::size_t k : which) {
            d.setRequester("the term " + terms_[k]->name());
            terms_[k]->setDerivatives(d, s);
        }
        d.setRequester("");
    }
    /// Requires the derivatives of every term, in the order added.
    void setDerivatives(DerivativeHolder<Dim>& d, const RunSettings& s) const {
        std::vector<std::size_t> all(terms_.size());
        for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
        setDerivatives(d, s, all);
    }
    /// Calls hook(term) for the terms listed, in that order; a quantity missing from the
    /// storage names the term that needs it.
    template <class Hook>
    void forTerms(std::span<const std::size_t> which, Hook&& hook) const {
        for (std::size_t k : which) named(*terms_[k], [&] { hook(*terms_[k]); });
    }
    /// Calls hook(term) for every term, in the order added.
    template <class Hook>
    void forTerms(Hook&& hook) const {
        for (auto& term : terms_) named(*term, [&] { hook(*term); });
    }
    /// The passes of an evaluation, from the terms' declarations (throws std::logic_error
    /// when they cannot be satisfied).
    EvaluationSchedule schedule() const {
        std::vector<TermAccess> access;
        for (auto& t : terms_) access.push_back(t->access());
        return scheduleEvaluation(access, names());
    }
    /// The terms' type names, in the order added.
    std::vector<std::string> names() const {
        std::vector<std::string> out;
        for (auto& t : terms_) out.push_back(t->name());
        return out;
    }
    void create(Storage<Dim>& s, IMaterial& m) const {
        for (auto& t : terms_) t->create(s, m);
    }

    Size size() const { return Size(terms_.size()); }
    /// The first term of type T, or nullptr.
    template <class T>
    T* find() const {
        for (auto& t : terms_)
            if (auto* p = dynamic_cast<T*>(t.get())) return p;
        return nullptr;
    }

  private:
    /// A quantity missing from the storage names the term that needs it (and what to call).
    template <class F>
    static void named(const IEquationTerm<Dim>& term, F&& f) {
        attributingMissingQuantity(f, [&] { return "the term " + term.name(); });
    }

    std::vector<std::shared_ptr<IEquationTerm<Dim>>> terms_;
};

/// A term that only fuses the pair sums other terms required (DerivativeHolder::fuse), in every
/// pass: place it after them. Built-in and user derivatives fuse the same way, e.g.
///     eq += makeTerm<FuseDerivatives<2, MyForce<2>, MyHeating<2>>>();
template <int Dim, class... Parts>
class FuseDerivatives : public IEquationTerm<Dim> {
  public:
    void setDerivatives(DerivativeHolder<Dim>& d, const RunSettings&) override {
        d.template fuse<Parts...>();
    }
    void initialize(IScheduler&, Storage<Dim>&, Float) override {}
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}
    void create(Storage<Dim>&, IMaterial&) const override {}
    TermAccess access() const override { return {.placement = PassPlacement::EVERY}; }
};

/// An EquationHolder with one term of type T made from args.
template <class T, class... Args>
auto makeTerm(Args&&... args) {
    constexpr int Dim = T::dim;
    return EquationHolder<Dim>(std::make_shared<T>(std::forward<Args>(args)...));
}

}  // namespace num::sph
