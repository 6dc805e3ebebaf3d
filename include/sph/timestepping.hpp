// Integrators, generic over every quantity and its order, and the run loop that picks the
// adaptive step. Quantities of order SECOND (positions) are kicked and drifted; quantities of
// order FIRST (density, temperature...) are advanced with their dt.
#pragma once

#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "sph/particle_order.hpp"
#include "sph/solver.hpp"

namespace num::sph {

namespace detail {
/// Calls f(buffers, order) for every quantity of order FIRST or SECOND.
template <int Dim, class F>
void forEachEvolved(Storage<Dim>& s, F&& f) {
    s.forEach([&](QuantityId, Quantity<Dim>& q) {
        if (q.order() == OrderEnum::ZERO) return;
        q.visit([&](auto& b) {
            using T = typename std::decay_t<decltype(b.value)>::value_type;
            if constexpr (!std::is_same_v<T, int>) f(b, q.order());
        });
    });
}
}  // namespace detail

template <int Dim>
class ITimeStepping {
  public:
    virtual ~ITimeStepping() = default;
    /// Advances the storage from t to t + dt. Derivatives at t must be current (see prime()).
    /// The post-step phase is not part of it: Run::step calls Solver::postStep afterwards.
    virtual void step(Solver<Dim>& solver, Storage<Dim>& storage, Float t, Float dt) = 0;
    virtual std::string name() const = 0;
};

/// Kick-drift-kick leapfrog (velocity Verlet) for second-order quantities: symplectic and
/// second order (Hairer, Lubich & Wanner 2003, sec. I.1.4):
///     v += dt/2 a_n;  x += dt v;  evaluate;  v += dt/2 a_{n+1}.
/// First-order quantities (density, energy...) are advanced with Heun's rule, also second
/// order: predicted q* = q_n + dt dq_n at evaluation, then q_{n+1} = q_n + dt/2 (dq_n + dq*).
template <int Dim>
class LeapfrogKDK final : public ITimeStepping<Dim> {
  public:
    void step(Solver<Dim>& solver, Storage<Dim>& s, Float t, Float dt) override {
        const Float half = 0.5 * dt;
        IScheduler& sch = solver.scheduler();
        const Size grain = 8192;
        std::size_t k = 0;
        detail::forEachEvolved(s, [&](auto& b, OrderEnum o) {
            const Size n = Size(b.value.size());
            if (o == OrderEnum::SECOND) {
                sch.parallelFor(n, grain, [&](Size i0, Size i1) {
                    for (Size i = i0; i < i1; ++i) {
                        b.dt[i] += b.d2t[i] * half;
                        b.value[i] += b.dt[i] * dt;
                    }
                });
            } else {
                using V = std::decay_t<decltype(b.dt)>;
                if (k == saved_.size()) saved_.emplace_back(V{});
                if (!std::holds_alternative<V>(saved_[k])) saved_[k] = V{};
                V& old = std::get<V>(saved_[k++]);
                old.resize(n);
                sch.parallelFor(n, grain, [&](Size i0, Size i1) {
                    for (Size i = i0; i < i1; ++i) {
                        old[i] = b.dt[i];
                        b.value[i] += b.dt[i] * dt;
                    }
                });
            }
        });
        solver.evaluate(s, t + dt);
        k = 0;
        detail::forEachEvolved(s, [&](auto& b, OrderEnum o) {
            const Size n = Size(b.value.size());
            if (o == OrderEnum::SECOND) {
                sch.parallelFor(n, grain, [&](Size i0, Size i1) {
                    for (Size i = i0; i < i1; ++i) b.dt[i] += b.d2t[i] * half;
                });
            } else {
                const auto& old = std::get<std::decay_t<decltype(b.dt)>>(saved_[k++]);
                sch.parallelFor(n, grain, [&](Size i0, Size i1) {
                    for (Size i = i0; i < i1; ++i) b.value[i] += (b.dt[i] - old[i]) * half;
                });
            }
        });
    }
    std::string name() const override { return "leapfrog"; }

  private:
    std::vector<std::variant<std::vector<Float>, std::vector<Vector<Dim>>>> saved_;
};

/// Predictor-corrector: predict with the derivatives at t, evaluate, correct with the change
/// of the highest derivative (v += dt/2 da, x += dt^2/6 da; first order q += dt/2 dq).
template <int Dim>
class PredictorCorrector final : public ITimeStepping<Dim> {
  public:
    void step(Solver<Dim>& solver, Storage<Dim>& s, Float t, Float dt) override {
        saved_.clear();
        detail::forEachEvolved(s, [&](auto& b, OrderEnum o) {
            saved_.emplace_back(o == OrderEnum::SECOND ? b.d2t : b.dt);
            for (std::size_t i = 0; i < b.value.size(); ++i) {
                if (o == OrderEnum::SECOND) {
                    b.value[i] += b.dt[i] * dt + b.d2t[i] * (0.5 * dt * dt);
                    b.dt[i] += b.d2t[i] * dt;
                } else {
                    b.value[i] += b.dt[i] * dt;
                }
            }
        });
        solver.evaluate(s, t + dt);
        std::size_t k = 0;
        detail::forEachEvolved(s, [&](auto& b, OrderEnum o) {
            const auto& top = o == OrderEnum::SECOND ? b.d2t : b.dt;
            const auto& old = std::get<std::decay_t<decltype(top)>>(saved_[k++]);
            for (std::size_t i = 0; i < top.size(); ++i) {
                const auto change = top[i] - old[i];
                if (o == OrderEnum::SECOND) {
                    b.dt[i] += change * (0.5 * dt);
                    b.value[i] += change * (dt * dt / 6.0);
                } else {
                    b.value[i] += change * (0.5 * dt);
                }
            }
        });
    }
    std::string name() const override { return "predictor_corrector"; }

  private:
    std::vector<std::variant<std::vector<Float>, std::vector<Vector<Dim>>>> saved_;
};

/// Explicit Euler: x += v dt, v += a dt, q += dq dt with every derivative at t. First order;
/// for tests and comparisons.
template <int Dim>
class ExplicitEuler final : public ITimeStepping<Dim> {
  public:
    void step(Solver<Dim>& solver, Storage<Dim>& s, Float t, Float dt) override {
        detail::forEachEvolved(s, [&](auto& b, OrderEnum o) {
            for (std::size_t i = 0; i < b.value.size(); ++i) {
                b.value[i] += b.dt[i] * dt;
                if (o == OrderEnum::SECOND) b.dt[i] += b.d2t[i] * dt;
            }
        });
        solver.evaluate(s, t + dt);
    }
    std::string name() const override { return "euler"; }
};

template <int Dim>
std::unique_ptr<ITimeStepping<Dim>> makeIntegrator(const std::string& name) {
    if (name == "leapfrog") return std::make_unique<LeapfrogKDK<Dim>>();
    if (name == "predictor_corrector") return std::make_unique<PredictorCorrector<Dim>>();
    if (name == "euler") return std::make_unique<ExplicitEuler<Dim>>();
    throw SettingsError("unknown integrator '" + name +
                        "' (expected leapfrog, predictor_corrector or euler)");
}

/// Reorders the particles by their cell now (sph/particle_order.hpp), so neighbours are near in
/// memory. Depends on positions and ids only (not on the last evaluation's grid, which the
/// post-step phase has moved away from), so a restarted run reorders as the uninterrupted one.
/// The solver's neighbour lists are invalidated: they index particles by their old order.
template <int Dim>
void reorderByCell(Storage<Dim>& s, Solver<Dim>& solver) {
    ensureParticleIds(s);
    reorderByKey(s, solver.domain(), solver.kernel().supportRadius());
    solver.invalidateNeighbours();
}

/// The run loop: adaptive step from the solver's limits, reordering by cell every few steps
/// (setting "reorder_every"). The apps drive it too: the step, the reorder and the restart
/// (setTime, markPrimed) exist once.
/// A step is: the integrator (each of its evaluations constrains the state first, Solver::
/// constrain, and has no side effects after that), then the post-step phase (Solver::postStep:
/// particle shifting, containment, bookkeeping) once.
/// The step a run takes from time t towards tEnd: the limits' dt, shortened to land on tEnd
/// ("end time"); last when it reaches tEnd. Shared by sph::Run and the device run.
struct PlannedStep {
    Float dt;
    bool last;
    std::string criterion;
};
inline PlannedStep planStep(const TimeStepLimits& limits, Float t, Float tEnd) {
    PlannedStep p{limits.dt(), false, limits.criterion()};
    if (!(p.dt < std::numeric_limits<Float>::infinity()))
        throw std::runtime_error(
            "no time-step criterion applies (no forces, no sound speed): set dt_fixed or "
            "dt_max");
    p.last = t + p.dt >= tEnd;
    if (t + p.dt > tEnd) p.dt = tEnd - t, p.criterion = "end time";
    return p;
}

template <int Dim>
class Run {
  public:
    Run(Storage<Dim>& storage, Solver<Dim>& solver, ITimeStepping<Dim>& integrator, Float t0 = 0)
        : storage_(storage), solver_(solver), integrator_(integrator), time_(t0) {
        reorderEvery_ = Size(solver.settings().template get<std::int64_t>("reorder_every"));
    }

    /// Evaluates the derivatives at the current time (before the first step, after a restart
    /// that did not store them, or after particles were added or removed).
    void prime() {
        solver_.evaluate(storage_, time_);
        primed_ = true;
    }

    /// One step, at most up to tEnd: the integrator, then the post-step phase with the step's
    /// dt at the new time. Returns the step taken.
    Float step(Float tEnd = std::numeric_limits<Float>::infinity()) {
        if (!primed_) prime();
        const bool reorder = reorderEvery_ > 0 && steps_ > 0 && steps_ % reorderEvery_ == 0;
        if (IDecomposition<Dim>* d = solver_.decomposition()) {
            if (d->beforeStep(storage_, reorder, particlesChanged_)) solver_.invalidateNeighbours();
        } else if (reorder) {
            reorderByCell(storage_, solver_);
        }
        particlesChanged_ = false;
        const PlannedStep planned = planStep(solver_.timeStepLimits(storage_), time_, tEnd);
        const Float dt = planned.dt;
        criterion_ = planned.criterion;
        integrator_.step(solver_, storage_, time_, dt);
        time_ = planned.last ? tEnd : time_ + dt;
        solver_.postStep(storage_, time_, dt);
        ++steps_;
        lastDt_ = dt;
        return dt;
    }

    /// Steps until tEnd.
    void advanceTo(Float tEnd) {
        while (time_ < tEnd * (1 - 1e-14)) step(tEnd);
    }

    Float time() const { return time_; }
    Size steps() const { return steps_; }
    Float lastDt() const { return lastDt_; }
    const std::string& limitingCriterion() const { return criterion_; }
    void setTime(Float t, Size steps) { time_ = t, steps_ = steps; }
    void markPrimed(bool p) { primed_ = p; }
    /// Tells the run that particles were added or removed since the last step (emitters, open
    /// sides): a domain decomposition then rebuilds its halos before the next step.
    void particlesChanged() { particlesChanged_ = true; }

  private:
    Storage<Dim>& storage_;
    Solver<Dim>& solver_;
    ITimeStepping<Dim>& integrator_;
    Float time_;
    Size steps_ = 0;
    Size reorderEvery_ = 0;
    bool primed_ = false, particlesChanged_ = false;
    Float lastDt_ = 0;
    std::string criterion_ = "none";
};

}  // namespace num::sph
