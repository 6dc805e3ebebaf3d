// One run of a scene, from its start (or a checkpoint) to its end time: the object every front
// end drives (the apps through runSimulation, the tests). A step is the engine's (sph::Run, or
// the CUDA back end's), then the observers in the order added: health checks, open boundaries
// and emitters, progress, outputs, checkpoints. Each observer owns its trigger and its
// reductions over the processes of an MPI run.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "app/errors.hpp"
#include "app/fields.hpp"
#include "app/scene_loader.hpp"
#include "parallel/communicator.hpp"
#include "sph/bodies/moving_bodies.hpp"
#include "sph/storage.hpp"

namespace num::app {

struct RunOptions {
    std::string program = "fluid_sim";
    std::optional<std::string> outDir;   ///< overrides output.directory
    int threads = 0;                     ///< 0: all hardware threads
    std::string backend = "threads";     ///< seq, omp, threads, cpu (= threads) or cuda
    bool backendGiven = false;           ///< --backend given: it overrides numerics.backend
    std::optional<double> endTime;       ///< overrides time.end
    std::optional<std::string> restart;  ///< checkpoint to continue from
    double checkpointEvery = 0;          ///< simulated seconds between checkpoints (0: none)
    bool quiet = false;
    /// The live progress line on standard output (off: a front end draws its own).
    bool progressLine = true;
    /// The run handles SIGINT, SIGTERM and SIGHUP (the apps); false: the caller handles them
    /// and calls Simulation::requestStop (the Python module).
    bool handleSignals = true;
    FieldNames fieldNames;  ///< names of user quantities in the outputs
    /// The processes of the run (mpirun); nullptr: this process alone.
    const parallel::Communicator* communicator = nullptr;
};

template <int Dim>
class Simulation;
/// Everything a run holds (internal to numerics_app: src/run/run_parts.hpp).
template <int Dim>
struct RunParts;

/// How a run ended, as summary.json and the exit code tell it.
struct RunEnd {
    std::string status = "completed";  ///< completed, interrupted, unstable or failed
    std::string message;
    ExitCode failure = ExitCode::OK;  ///< of an unstable or failed run
    bool abandoned = false;           ///< a signal stopped the run in the middle of a step
    nlohmann::json summary;
    std::vector<std::string> warnings;  ///< those of the run, after the scene's
};

/// Acts after steps, each on its own trigger.
template <int Dim>
class IStepObserver {
  public:
    virtual ~IStepObserver() = default;
    /// A time the steps land on exactly (an output time); infinity: none.
    virtual double landingTime() const { return std::numeric_limits<double>::infinity(); }
    /// Whether afterStep needs the particles on the host (the CUDA back end copies them back).
    virtual bool needsParticles(const Simulation<Dim>&) const { return false; }
    /// Before a step; `endStep`: the step is cut short to land on an end time that is not a
    /// landing time (a longer run would not take it).
    virtual void beforeStep(Simulation<Dim>&, bool /*endStep*/) {}
    virtual void afterStep(Simulation<Dim>&) = 0;
    /// When the steps are over (the run completed or was interrupted, not failed).
    virtual void afterRun(Simulation<Dim>&, const RunEnd&) {}
    /// Adds to summary.json and its warnings.
    virtual void summarize(Simulation<Dim>&, RunEnd&) {}
};

template <int Dim>
class Simulation {
  public:
    /// Reads the scene, sets up the particles (or reads the checkpoint of options.restart) and
    /// writes the first output. Errors are AppErrors (app/errors.hpp).
    Simulation(const SceneDocument& doc, const RunOptions& options);
    ~Simulation();
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;

    /// One step towards the end time, landing on the observers' times; returns its dt.
    double step();
    /// Steps until time t (landing on it), the end time or a stop request (Ctrl-C).
    void advanceTo(double t);
    /// The whole run: advanceTo(end time), the last output, summary.json and the report.
    /// Returns the exit code (0 or INTERRUPTED); a failed run throws its AppError.
    int run();

    double time() const;
    double endTime() const;
    std::uint64_t steps() const;
    /// This process's particles, up to date (copied back from the GPU when needed).
    const sph::Storage<Dim>& particles();
    /// This process's particles for a front end to change between steps (on the CUDA back end
    /// they are copied to the device before the next step).
    sph::Storage<Dim>& particlesToChange();
    /// Whether a process asked to stop (a signal on any process stops all of them).
    bool stopRequested() const;
    /// Asks the run to stop after the step in progress, as a signal does.
    void requestStop();
    /// The scene as read, with the options applied (end time, output directory).
    const Scene<Dim>& scene() const;
    /// The names of the user and plugin quantities in the outputs.
    const FieldNames& fieldNames() const;
    /// The scene's bodies with their motions and states (bodies[i].motion), or nullptr when
    /// every body is fixed. A front end may change a prescribed body's velocity between steps.
    sph::MovingBodies<Dim>* movingBodies();

    void addObserver(std::unique_ptr<IStepObserver<Dim>> observer);
    RunParts<Dim>& parts() { return *parts_; }
    const RunParts<Dim>& parts() const { return *parts_; }

  private:
    /// One step towards limit (at most the end time), landing on the observers' times.
    double stepTowards(double limit);
    void copyParticlesToHost();
    void acceptChangedParticles();
    void reportAbandonedStep(RunEnd& end);
    /// summary.json, the report and the exit code.
    int finishRun(RunEnd end);

    std::unique_ptr<RunParts<Dim>> parts_;
    std::vector<std::unique_ptr<IStepObserver<Dim>>> observers_;
};

/// Runs the scene through a Simulation; returns the exit code (0, INTERRUPTED). Errors are
/// AppErrors.
template <int Dim>
int runSimulation(const SceneDocument& doc, const RunOptions& options);

/// Reads the scene document stored in a checkpoint (for --restart without a scene file).
SceneDocument sceneOfCheckpoint(const std::string& path, int dimension);

}  // namespace num::app
