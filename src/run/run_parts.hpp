// Everything a Simulation holds (internal to numerics_app): the scene and its set-up, the
// particles, the engine that steps them, and the state a checkpoint keeps.
#pragma once

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "app/emitters.hpp"
#include "app/outputs.hpp"
#include "app/progress.hpp"
#include "app/simulation.hpp"
#include "parallel/domain_decomposition.hpp"
#include "plugin/plugins.hpp"
#include "run/agreed_errors.hpp"
#include "run/checkpoint_state.hpp"
#include "run/engine.hpp"
#include "run/stop_signals.hpp"
#include "run/written_particles.hpp"
#include "sph/timestepping.hpp"

namespace num::app {

/// Whether time t has reached target, to round-off.
inline bool reached(double t, double target) {
    return t >= target - 1e-9 * std::max(1e-300, std::abs(target)) - 1e-300;
}

template <int Dim>
struct RunParts {
    /// Signals are back to their defaults when the run is gone, however it ends.
    const stop::DefaultsOnExit signalsOnExit;
    const std::chrono::steady_clock::time_point wallStart = std::chrono::steady_clock::now();
    RunOptions options;
    const parallel::Communicator single;
    const parallel::Communicator& comm;
    const SceneDocument doc;  ///< with the plugins' absolute paths (a checkpoint stores it)
    Scene<Dim> scene;
    bool onCuda = false;
    std::string cpuBackend;  ///< the backend of the CPU's threads
    int threads = 1;
    std::optional<ScenePlugins<Dim>> plugins;
    std::optional<SceneSetup<Dim>> setup;
    std::string fingerprint;
    FieldNames fieldNames;
    std::optional<Outputs<Dim>> outputs;  ///< on the root only: it writes every file
    std::size_t initialParticles = 0;

    RunState<Dim> state;  ///< what a checkpoint keeps besides the particles
    sph::Storage<Dim> storage;
    /// The CPU's threads: the CPU engine's steps, the health checks on either engine.
    std::unique_ptr<sph::IScheduler> scheduler;
    /// What steps `storage`'s particles (engine.hpp); on the CUDA back end `storage` is brought
    /// up to date when an observer or a front end needs it.
    std::unique_ptr<IEngine<Dim>> engine;
    bool hostChanged = false;       ///< a front end may have changed the particles since the step
    WrittenParticles<Dim> written;  ///< what they were when handed out, to check the writes
    /// Each process keeps its share of the particles and a halo; one process keeps them all.
    std::unique_ptr<parallel::DomainDecomposition<Dim>> decomposition;
    std::optional<Emitters<Dim>> emitters;
    std::optional<Progress> progress;

    std::uint64_t startSteps = 0;  ///< the steps before this run (a checkpoint's)
    double particleSteps = 0;      ///< particles times steps, over the processes
    std::int64_t owned = 0;        ///< this process's particles, after the last step
    std::int64_t particles = 0;    ///< over the processes, after the last step
    double lastOutput = -1;        ///< the time of the last output written; -1: none
    bool stopAsked = false;        ///< Simulation::requestStop

    /// The clock of the last step.
    const sph::StepClock& stepClock() const { return engine->clock(); }

    RunParts(const SceneDocument& document, const RunOptions& opt)
        : signalsOnExit(opt.handleSignals),
          options(opt),
          comm(opt.communicator ? *opt.communicator : single),
          doc(document) {}

    bool root() const { return comm.isRoot(); }

    /// Prints "program: warning: text" on the root, unless quiet.
    void warn(const std::string& text) const {
        if (options.quiet || !root()) return;
        if (progress) progress->clearLine();
        std::fprintf(stderr, "%s: warning: %s\n", options.program.c_str(), text.c_str());
    }

    /// Calls use(every particle): the storage itself on one process, else all of them gathered
    /// on the root (the others get an empty storage).
    template <class F>
    decltype(auto) everyParticle(const sph::Storage<Dim>& s, F&& use) const {
        if (comm.size() == 1) return use(s);
        const sph::Storage<Dim> all = decomposition->gatherToRoot(s);
        return use(all);
    }

    /// The number of particles this process owns (those not yet assigned count on the root).
    std::int64_t countOwned() const {
        std::int64_t n = 0;
        for (int owner : storage.template getValue<int>(sph::QuantityId::OWNER))
            n += owner == comm.rank() || (owner < 0 && comm.isRoot());
        return n;
    }
};

}  // namespace num::app
