// The run loop that picks the adaptive step, and the integrators it may run
// (sph/integrator_choice.hpp: makeIntegrator by name).
#pragma once

#include <limits>
#include <stdexcept>
#include <string>

#include "sph/integrator_choice.hpp"
#include "sph/particle_order.hpp"
#include "sph/solver.hpp"

namespace num::sph {

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

/// The clock of a run: its time, its steps and the last one's dt and limiting criterion. A step
/// is planned from the limits (planStep), taken, then counted. Shared by sph::Run and the device
/// run.
class StepClock {
  public:
    explicit StepClock(Float t0 = 0) : time_(t0) {}

    Float time() const { return time_; }
    Size steps() const { return steps_; }
    Float lastDt() const { return lastDt_; }
    const std::string& limitingCriterion() const { return criterion_; }
    void setTime(Float t, Size steps) { time_ = t, steps_ = steps; }

  protected:
    PlannedStep plan(const TimeStepLimits& limits, Float tEnd) {
        PlannedStep planned = planStep(limits, time_, tEnd);
        criterion_ = planned.criterion;
        return planned;
    }
    /// The step is taken: the time moves on (landing exactly on tEnd when it was the last).
    void count(const PlannedStep& planned, Float tEnd) {
        time_ = planned.last ? tEnd : time_ + planned.dt;
        ++steps_;
        lastDt_ = planned.dt;
    }

  private:
    Float time_;
    Size steps_ = 0;
    Float lastDt_ = 0;
    std::string criterion_ = "none";
};

template <int Dim>
class Run : public StepClock {
  public:
    Run(Storage<Dim>& storage, Solver<Dim>& solver, ITimeStepping<Dim>& integrator, Float t0 = 0)
        : StepClock(t0), storage_(storage), solver_(solver), integrator_(integrator) {
        reorderEvery_ = Size(solver.settings().template get<std::int64_t>("reorder_every"));
    }

    /// Evaluates the derivatives at the current time (before the first step, after a restart
    /// that did not store them, or after particles were added or removed).
    void prime() {
        solver_.evaluate(storage_, time());
        primed_ = true;
    }

    /// One step, at most up to tEnd: the integrator, then the post-step phase with the step's
    /// dt at the new time. Returns the step taken.
    Float step(Float tEnd = std::numeric_limits<Float>::infinity()) {
        if (!primed_) prime();
        const bool reorder = reorderEvery_ > 0 && steps() > 0 && steps() % reorderEvery_ == 0;
        if (IDecomposition<Dim>* d = solver_.decomposition()) {
            if (d->beforeStep(storage_, reorder, particlesChanged_)) solver_.invalidateNeighbours();
        } else if (reorder) {
            reorderByCell(storage_, solver_);
        }
        particlesChanged_ = false;
        const PlannedStep planned = plan(solver_.timeStepLimits(storage_), tEnd);
        integrator_.step(solver_, storage_, time(), planned.dt);
        count(planned, tEnd);
        solver_.postStep(storage_, time(), planned.dt);
        return planned.dt;
    }

    /// Steps until tEnd.
    void advanceTo(Float tEnd) {
        while (time() < tEnd * (1 - 1e-14)) step(tEnd);
    }

    void markPrimed(bool p) { primed_ = p; }
    /// Tells the run that particles were added or removed since the last step (emitters, open
    /// sides): a domain decomposition then rebuilds its halos before the next step.
    void particlesChanged() { particlesChanged_ = true; }

  private:
    Storage<Dim>& storage_;
    Solver<Dim>& solver_;
    ITimeStepping<Dim>& integrator_;
    Size reorderEvery_ = 0;
    bool primed_ = false, particlesChanged_ = false;
};

}  // namespace num::sph
