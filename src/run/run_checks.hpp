// The observers that watch the particles and change their number (internal to numerics_app):
// health checks, open boundaries and emitters, progress, and the test hook that raises a signal
// at a given step.
#pragma once

#include <csignal>
#include <string>

#include "run/body_check.hpp"
#include "run/physical_check.hpp"
#include "run/run_parts.hpp"
#include "run/run_state.hpp"

namespace num::app {

/// The id of the next particle made during the run: after the initial particles, those emitted
/// and those the inlets made, so that ids are never reused.
template <int Dim>
std::int64_t nextParticleId(const RunParts<Dim>& p) {
    const auto& flow = p.setup->model.flowBoundaries;
    return std::int64_t(p.initialParticles + p.emitters->emitted()) +
           (flow ? std::int64_t(flow->books.created) : 0);
}

/// Emits the particles due at time t; they come last in the particle order, with ids after the
/// initial particles' (the same on every process: each emits every particle, and keeps its own).
/// A nozzle point is left out where water is, every process agreeing (app/emitters.hpp).
template <int Dim>
std::size_t emitParticles(RunParts<Dim>& p, double t) {
    const sph::RunKernel<Dim> kernel(p.setup->settings);
    auto occupied = [&](const std::vector<sph::Vector<Dim>>& points) {
        return occupiedPoints(p.storage, p.setup->geometry.domain, kernel, points, p.scene.spacing,
                              p.comm);
    };
    const std::int64_t first = nextParticleId(p);
    const std::size_t added = p.emitters->emit(p.storage, t, occupied);
    auto id = p.storage.template getValue<int>(sph::QuantityId::PARTICLE_ID);
    auto key = p.storage.template getValue<int>(sph::QuantityId::ORDER_KEY);
    for (std::size_t k = 0; k < added; ++k) {
        const std::size_t i = p.storage.size() - added + k;
        id[i] = int(first + std::int64_t(k)), key[i] = sph::kNewParticleKey;
    }
    return added;
}

/// Inlets and outlets exchange particles with the fluid after a step (FlowBoundaries::exchange,
/// each process its own particles); returns whether any particle of any process changed.
template <int Dim>
bool exchangeFlow(RunParts<Dim>& p, double t) {
    const auto& flow = p.setup->model.flowBoundaries;
    if (!flow) return false;
    const sph::IDecomposition<Dim>* processes = p.comm.size() > 1 ? p.decomposition.get() : nullptr;
    return p.comm.any(flow->exchange(p.storage, t, nextParticleId(p), processes));
}

/// Non-finite values, collapsed steps and fluid beyond walls stop the run (checkHealth); so do
/// states outside the physical ranges, which warn first (PhysicalCheck). Both look at the
/// particles whenever they are on the host: every step on the CPU, when copied back on the GPU.
template <int Dim>
class HealthObserver final : public IStepObserver<Dim> {
  public:
    explicit HealthObserver(const RunParts<Dim>& p)
        : physical_(p.setup->velocityScale, p.setup->model.c0(), p.setup->model.restDensity) {
        for (const auto& r : p.plugins->ranges)
            physical_.addRange({r.id, r.name, r.unit, r.lo, r.hi,
                                "the range the plugin " + r.library + " declares for it"});
    }
    void afterStep(Simulation<Dim>& sim) override {
        RunParts<Dim>& p = sim.parts();
        if (!p.engine->hostCurrent()) return;
        const std::string criterion = p.stepClock().limitingCriterion();
        agreed(p.comm, [&] {
            checkHealth(*p.scheduler, p.storage, p.scene, sim.time(), sim.steps(), lastDt(p),
                        criterion, p.fieldNames);
            if (const auto& bodies = p.setup->model.movingBodies)
                checkBodiesInside(p.storage, p.scene, *bodies, sim.time());
        });
        if (const std::string w = physical_.check(p.storage, sim.time(), p.comm, *p.scheduler);
            !w.empty())
            p.warn(w);
    }
    void summarize(Simulation<Dim>&, RunEnd& end) override {
        end.warnings.insert(end.warnings.end(), physical_.warnings().begin(),
                            physical_.warnings().end());
    }

  private:
    static double lastDt(const RunParts<Dim>& p) { return p.stepClock().lastDt(); }
    PhysicalCheck physical_;
};

/// Open sides remove the fluid that leaves the domain; inlets and outlets exchange particles
/// with the fluid; emitters add particles; either way the engine takes the new set. An engine
/// whose particles are elsewhere (the GPU) copies them back only after a step that needs it:
/// fluid beyond an open side, an emitter's layer due, inlets and outlets (every step).
template <int Dim>
class ParticleFlowObserver final : public IStepObserver<Dim> {
  public:
    explicit ParticleFlowObserver(const RunParts<Dim>& p)
        : active_(!p.scene.emitters.empty() || bool(p.setup->model.flowBoundaries) ||
                  anySideLetsFluidOut(p.scene)) {}
    bool needsParticles(const Simulation<Dim>& sim) const override {
        const RunParts<Dim>& p = sim.parts();
        if (!active_ || p.engine->hostCurrent() || p.setup->model.flowBoundaries) return active_;
        return p.emitters->anyDue(sim.time()) ||
               (anySideLetsFluidOut(p.scene) && fluidLeaves(p.scene, p.engine->fluidExtent()));
    }
    void afterStep(Simulation<Dim>& sim) override {
        RunParts<Dim>& p = sim.parts();
        if (!active_ || !p.engine->hostCurrent()) return;
        bool changed = false;
        if (p.comm.any(removeOutflow(p.storage, p.scene) > 0)) {
            p.state.removed += std::uint64_t(p.comm.sum(p.owned - p.countOwned()));
            changed = true;
        }
        changed = exchangeFlow(p, sim.time()) || changed;
        changed = emitParticles(p, sim.time()) > 0 || changed;
        if (changed)
            p.engine->takeNewParticleSet();
        else if (p.setup->model.flowBoundaries)
            p.engine->takeImposedValues();  // the inlets' velocity and temperature of the time
        const auto& warnings = p.emitters->warnings();
        for (; printed_ < warnings.size(); ++printed_) p.warn(warnings[printed_]);
    }
    void summarize(Simulation<Dim>& sim, RunEnd& end) override {
        const auto& warnings = sim.parts().emitters->warnings();
        end.warnings.insert(end.warnings.end(), warnings.begin(), warnings.end());
    }

  private:
    bool active_;              ///< whether the scene has emitters, open sides, inlets or outlets
    std::size_t printed_ = 0;  ///< of the emitters' warnings
};

/// The progress line (terminal) or a line every 10 s (a log).
template <int Dim>
class ProgressObserver final : public IStepObserver<Dim> {
  public:
    void afterStep(Simulation<Dim>& sim) override {
        RunParts<Dim>& p = sim.parts();
        p.progress->update(sim.time(), p.stepClock().lastDt(), sph::Size(p.particles), sim.steps());
    }
};

/// Raises the signal NUMERICS_TEST_SIGNAL names after the step it names (stop_signals.hpp):
/// the tests' way to stop a run at a known step.
template <int Dim>
class TestSignalObserver final : public IStepObserver<Dim> {
  public:
    explicit TestSignalObserver(stop::TestSignal s) : signal_(s) {}
    bool needsParticles(const Simulation<Dim>& sim) const override { return due(sim); }
    void afterStep(Simulation<Dim>& sim) override {
        if (due(sim)) std::raise(signal_.signal);
    }

  private:
    bool due(const Simulation<Dim>& sim) const {
        return signal_.signal && sim.steps() == signal_.step;
    }
    stop::TestSignal signal_;
};

}  // namespace num::app
