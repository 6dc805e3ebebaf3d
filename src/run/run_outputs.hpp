// The observers that write the run's files (internal to numerics_app): the outputs every
// output.every simulated seconds, the probes every output.probes_every, and checkpoints every
// --checkpoint-every seconds and on Ctrl-C. The root writes every file, from the particles of every
// process gathered.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "app/formatted.hpp"
#include "run/run_parts.hpp"

namespace num::app {

/// Outputs fall on multiples of output.every, and the steps land on them. The slot is the next
/// multiple, the file index (RunState::outputIndex) counts the files written: they differ only
/// after a restart with another output.every, whose outputs go on from the first multiple after
/// the checkpoint's time and whose files from the next free index, so no file is overwritten.
template <int Dim>
class OutputObserver final : public IStepObserver<Dim> {
  public:
    explicit OutputObserver(const RunParts<Dim>& p) : every_(p.scene.output.every) {
        if (!p.options.restart) return;  // a new run writes its output at t = 0 first
        const double t = p.state.time;
        slot_ = std::max<std::int64_t>(0, std::int64_t(t / every_) - 1);
        while (reached(t, double(slot_) * every_)) ++slot_;
    }
    double landingTime() const override { return double(slot_) * every_; }
    bool needsParticles(const Simulation<Dim>& sim) const override { return due(sim); }
    void afterStep(Simulation<Dim>& sim) override {
        if (due(sim)) write(sim);
    }
    void afterRun(Simulation<Dim>& sim, const RunEnd& end) override {
        if (!end.abandoned && sim.time() != sim.parts().lastOutput) write(sim);
    }

    /// Writes the particles at the present time.
    void write(Simulation<Dim>& sim) {
        RunParts<Dim>& p = sim.parts();
        p.everyParticle(p.storage, [&](const sph::Storage<Dim>& all) {
            onRoot(p.comm, [&] { p.outputs->write(all, sim.time(), int(p.state.outputIndex)); });
        });
        ++p.state.outputIndex, ++slot_;
        p.lastOutput = sim.time();
    }

  private:
    bool due(const Simulation<Dim>& sim) const { return reached(sim.time(), landingTime()); }
    double every_;
    std::int64_t slot_ = 0;
};

/// Probes sample every output.probes_every simulated seconds (Scene::probeInterval), at the
/// first step that reaches each multiple: they do not shorten the steps, so a run's steps are
/// the same with or without probes, at any rate. After a restart they go on from the first
/// multiple after the checkpoint's time, as they would have.
template <int Dim>
class ProbeObserver final : public IStepObserver<Dim> {
  public:
    explicit ProbeObserver(const RunParts<Dim>& p) : every_(p.scene.output.probeInterval()) {
        if (!p.options.restart) return;  // a new run samples at t = 0 first
        last_ = p.state.time;
        passSlotsUpTo(last_);
    }
    bool needsParticles(const Simulation<Dim>& sim) const override { return due(sim); }
    void afterStep(Simulation<Dim>& sim) override {
        if (due(sim)) write(sim);
    }
    /// And at the end (or where the run stopped), as the outputs.
    void afterRun(Simulation<Dim>& sim, const RunEnd& end) override {
        if (!end.abandoned && sim.time() != last_) write(sim);
    }

    /// Writes the probes' row of the present time, from every particle.
    void write(Simulation<Dim>& sim) {
        RunParts<Dim>& p = sim.parts();
        p.everyParticle(p.storage, [&](const sph::Storage<Dim>& all) {
            onRoot(p.comm, [&] { p.outputs->writeProbes(all, sim.time()); });
        });
        last_ = sim.time();
        passSlotsUpTo(last_);
    }

  private:
    bool due(const Simulation<Dim>& sim) const {
        return reached(sim.time(), double(slot_) * every_);
    }
    /// The next slot is the first multiple of every_ that time t has not reached.
    void passSlotsUpTo(double t) {
        slot_ = std::max<std::int64_t>(slot_, std::int64_t(t / every_) - 1);
        while (reached(t, double(slot_) * every_)) ++slot_;
    }

    double every_;
    std::int64_t slot_ = 0;
    double last_ = -1;  ///< the time of the last row; -1: none
};

/// A checkpoint holds the scene, the run's fingerprint, its state and every particle, so that a
/// restart continues bitwise.
template <int Dim>
class CheckpointObserver final : public IStepObserver<Dim> {
  public:
    explicit CheckpointObserver(double every) : every_(every) {}
    bool needsParticles(const Simulation<Dim>& sim) const override { return due(sim); }
    /// A step cut short by an unaligned end time leaves the trajectory a longer run follows: a
    /// checkpoint then holds the state before that step.
    void beforeStep(Simulation<Dim>& sim, bool endStep) override {
        if (endStep) beforeEndStep_.emplace(resumable(sim), sim.particles());
    }
    void afterStep(Simulation<Dim>& sim) override {
        if (!due(sim)) return;
        std::int64_t& count = sim.parts().state.checkpointCount;
        while (reached(sim.time(), double(count + 1) * every_)) ++count;
        write(sim, formatted("checkpoint_%04.0f.chk", double(count)));
    }
    void afterRun(Simulation<Dim>& sim, const RunEnd& end) override {
        if (end.status == "interrupted" && !end.abandoned) write(sim, "checkpoint_interrupted.chk");
    }
    void summarize(Simulation<Dim>&, RunEnd& end) override {
        for (const auto& [t, f] : written_)
            end.summary["checkpoints"].push_back({{"time", t}, {"file", f}});
    }

  private:
    bool due(const Simulation<Dim>& sim) const {
        return every_ > 0 &&
               reached(sim.time(), double(sim.parts().state.checkpointCount + 1) * every_);
    }
    /// The run's state as a restart needs it.
    static RunState<Dim> resumable(Simulation<Dim>& sim) {
        RunParts<Dim>& p = sim.parts();
        RunState<Dim> r = p.state;
        r.time = sim.time(), r.steps = sim.steps();
        r.emitterLayers = p.emitters->layers(), r.emitted = p.emitters->emitted();
        r.emitterBlocked = p.emitters->blocked();
        if (const auto& bodies = p.setup->model.movingBodies) r.bodies = bodies->save();
        if (const auto& flow = p.setup->model.flowBoundaries) r.flow = flow->books.save();
        if (const auto* walls = p.engine->wallHeat()) r.wallHeat = walls->save();
        if (p.root()) r.series = p.outputs->series().entries();
        return r;
    }
    void write(Simulation<Dim>& sim, const std::string& name) {
        RunParts<Dim>& p = sim.parts();
        const RunState<Dim> r = beforeEndStep_ ? beforeEndStep_->first : resumable(sim);
        const sph::Storage<Dim>& s = beforeEndStep_ ? beforeEndStep_->second : sim.particles();
        p.everyParticle(s, [&](const sph::Storage<Dim>& all) {
            onRoot(p.comm, [&] {
                ByteWriter w;
                w.putString(p.doc.dumpWithAbsolutePaths());
                w.putString(p.fingerprint);
                r.write(w);
                writeStorage(w, all);
                writeCheckpointFile(p.outputs->path(name), Dim, w.bytes());
            });
        });
        written_.emplace_back(r.time, name);
    }

    double every_;  ///< simulated seconds between checkpoints; 0: only on Ctrl-C
    std::optional<std::pair<RunState<Dim>, sph::Storage<Dim>>> beforeEndStep_;
    std::vector<std::pair<double, std::string>> written_;
};

}  // namespace num::app
