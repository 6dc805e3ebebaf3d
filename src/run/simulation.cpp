// Simulation: the set-up of a run from its scene (or checkpoint), its steps and their
// observers. The end of a run (summary.json, the report) is in simulation_end.cpp.
#include "app/simulation.hpp"

#include <thread>

#include "run/cpu_engine.hpp"
#include "run/device_backend.hpp"
#include "run/run_checks.hpp"
#include "run/run_outputs.hpp"
#include "scene/fingerprint.hpp"
#include "scene/initial_state.hpp"
#include "scene/run_limits.hpp"
#include "sph/evaluation_mode.hpp"
#include "sph/setup/set_up_interrupt.hpp"

namespace num::app {

using sph::QuantityId;
using sph::Size;

SceneDocument sceneOfCheckpoint(const std::string& path, int dimension) {
    const std::string payload = readCheckpointFile(path, dimension);
    ByteReader r(payload, path);
    try {
        return SceneDocument::fromText(r.getString(), path + " (scene stored in the checkpoint)");
    } catch (const AppError& e) {
        // The checksum matched: the file was edited and its checksum written again.
        throw AppError(ExitCode::CHECKPOINT,
                       std::string(e.what()) + "; it cannot be used for --restart");
    }
}

namespace {

/// The scene with the options applied, and the back end and threads it runs on.
template <int Dim>
void readRunScene(RunParts<Dim>& p) {
    const RunOptions& opt = p.options;
    p.scene = readScene<Dim>(p.doc);
    if (opt.endTime) p.scene.endTime = *opt.endTime;
    if (opt.outDir) p.scene.output.directory = *opt.outDir;
    for (const std::string& w : p.scene.warnings) p.warn(w);
    // The CUDA back end runs the steps on the GPU; the CPU backend's threads do the rest.
    p.onCuda = runsOnCuda(p.scene, opt);
    p.cpuBackend = opt.backend == "cuda" || opt.backend == "cpu" ? "threads" : opt.backend;
    p.threads = p.cpuBackend == "seq" ? 1
                : opt.threads > 0     ? opt.threads
                                      : int(std::max(1u, std::thread::hardware_concurrency()));
    checkGravity(p.scene);
}

/// The particles at t = 0, checked, with the set-up that made them and the outputs' writer.
template <int Dim>
sph::Storage<Dim> setUpParticles(RunParts<Dim>& p) {
    p.plugins.emplace(loadPlugins<Dim>(p.doc));  // before set-up, in scene order
    p.plugins->failure->keepUntilStepEnd = p.comm.size() > 1;
    p.setup.emplace(makeSceneSetup(p.scene, p.threads, p.plugins->terms));
    SceneSetup<Dim>& setup = *p.setup;
    if (p.onCuda) checkCudaRun(p.scene, setup, p.options, p.comm.size());
    checkRunLimits(p.scene, setup, p.options.checkpointEvery);
    sph::Storage<Dim> initial = makeInitialStorage(p.scene, setup);
    checkInitialState(p.scene, setup, initial);
    for (const std::string& w : setUpWarnings(p.scene, setup, initial)) {
        p.warn(w);
        p.scene.warnings.push_back(w);  // and in summary.json
    }
    if (p.comm.size() > 1 && sph::evaluationFromName(setup.settings.template get<std::string>(
                                 "evaluation")) == sph::Evaluation::SYMMETRIC)
        throw AppError(ExitCode::USAGE,
                       "particles.evaluation \"symmetric\" cannot run on several processes: "
                       "remove it (the default gathers) or run without mpirun");
    // The process that owns each particle (parallel/domain_decomposition.hpp); -1 until the
    // particles are distributed.
    initial.template insert<int>(QuantityId::OWNER, sph::OrderEnum::ZERO, -1);
    for (auto& t : p.setup->emitterTemplates)
        t.template insert<int>(QuantityId::OWNER, sph::OrderEnum::ZERO, -1);
    p.fingerprint = runFingerprint(p.doc, setup, initial) + p.plugins->fingerprint;
    p.fieldNames = pluginFieldNames(*p.plugins, initial, p.options.fieldNames, p.doc.file());
    onRoot(p.comm, [&] {
        p.outputs.emplace(p.scene, setup, p.scene.output.directory, initial, p.fieldNames,
                          p.plugins->writers);
    });
    p.initialParticles = initial.size();
    return initial;
}

/// Restores a part of the state a checkpoint keeps besides the particles (`saved`, empty where
/// it had none): `present`, whether the scene has that part (`what`, for the message), and
/// `restore`, which throws std::invalid_argument on values that do not fit it.
template <class Restore>
void restorePart(bool present, const std::vector<double>& saved, const char* what,
                 const std::string& file, Restore&& restore) {
    if (!present && saved.empty()) return;
    try {
        if (!present)
            throw std::invalid_argument(std::string("holds ") + what + ", the scene has none");
        restore(saved);
    } catch (const std::invalid_argument& e) {
        throw AppError(ExitCode::CHECKPOINT, file + ": the checkpoint " + e.what());
    }
}

/// The moving bodies' states and the inlets' and outlets' books at the checkpoint's time.
template <int Dim>
void restoreBodiesAndFlow(RunParts<Dim>& p, const std::string& file) {
    const auto& bodies = p.setup->model.movingBodies;
    restorePart(bool(bodies), p.state.bodies, "moving bodies", file,
                [&](const std::vector<double>& v) { bodies->restore(v); });
    const auto& flow = p.setup->model.flowBoundaries;
    restorePart(bool(flow), p.state.flow, "inlets or outlets", file,
                [&](const std::vector<double>& v) { flow->books.restore(v); });
}

/// The walls' heat books at the checkpoint's time (once the engine is made); a checkpoint of a
/// run with conduction that holds none starts them at zero.
template <int Dim>
void restoreWallHeat(RunParts<Dim>& p, const std::string& file) {
    auto* walls = p.engine->wallHeat();
    const bool conduction = p.setup->model.heat.conduction;
    if (conduction && (!walls || p.state.wallHeat.empty())) return;
    restorePart(walls != nullptr, p.state.wallHeat, "heat books of walls", file,
                [&](const std::vector<double>& v) { walls->restore(v); });
}

/// The state and particles of the checkpoint options.restart names.
template <int Dim>
void readRestart(RunParts<Dim>& p, const sph::Storage<Dim>& initial) {
    const std::string& file = *p.options.restart;
    const std::string payload = readCheckpointFile(file, Dim);
    ByteReader r(payload, file);
    r.getString();  // the scene, read by the caller
    checkFingerprint(r.getString(), p.fingerprint, file);
    p.state.read(r);
    if (p.state.emitterLayers.size() != p.scene.emitters.size())
        throw AppError(ExitCode::CHECKPOINT, file + ": the checkpoint has " +
                                                 std::to_string(p.state.emitterLayers.size()) +
                                                 " emitters, the scene " +
                                                 std::to_string(p.scene.emitters.size()));
    p.storage = readStorage<Dim>(r, initial);
    restoreBodiesAndFlow(p, file);
    if (p.state.time >= p.scene.endTime)
        throw AppError(ExitCode::USAGE,
                       file + ": the checkpoint is at t = " + formatted("%g", p.state.time) +
                           " s, at or after the end time " + formatted("%g", p.scene.endTime) +
                           " s (raise it with --end-time)");
}

/// The engine that steps the particles: the CPU's or the GPU's (engine.hpp).
template <int Dim>
void makeEngine(RunParts<Dim>& p) {
    const SceneSetup<Dim>& setup = *p.setup;
    p.emitters.emplace(p.scene, setup);
    if (!p.state.emitterLayers.empty()) p.emitters->layers() = p.state.emitterLayers;
    p.emitters->setEmitted(p.state.emitted);
    p.emitters->setBlocked(p.state.emitterBlocked);
    p.scheduler = sph::makeScheduler(p.cpuBackend, Size(p.threads));
    if (p.onCuda)
        p.engine = std::make_unique<DeviceEngine<Dim>>(p.storage, setup, p.state.time);
    else
        p.engine = std::make_unique<CpuEngine<Dim>>(p.storage, *p.scheduler, setup,
                                                    p.scene.integrator, p.cpuBackend, p.state.time);
    p.decomposition = std::make_unique<parallel::DomainDecomposition<Dim>>(
        p.comm, setup.geometry.domain, sph::RunKernel<Dim>(setup.settings).supportRadius());
}

/// Continues from the checkpoint: it holds the derivatives at its time, and terms keep no time
/// of their own (a step's post-step phase gets its dt from Run), so the run goes on as it would
/// have.
template <int Dim>
void resumeRun(RunParts<Dim>& p) {
    restoreWallHeat(p, *p.options.restart);
    p.decomposition->distribute(p.storage);
    if (p.comm.size() > 1) p.engine->setDecomposition(p.decomposition.get());
    p.engine->resume(p.state.time, Size(p.state.steps));
    onRoot(p.comm, [&] { p.outputs->resume(p.state.time, p.state.series); });
}

/// A new run: its folder, the particles emitted at t = 0, the first evaluation.
template <int Dim>
void startRun(RunParts<Dim>& p) {
    onRoot(p.comm, [&] { p.outputs->start(); });
    if (p.root() && !p.outputs->earlierRunNote().empty()) {
        p.warn(p.outputs->earlierRunNote());
        p.scene.warnings.push_back(p.outputs->earlierRunNote());  // and in summary.json
    }
    emitParticles(p, 0.0);
    p.decomposition->distribute(p.storage);
    if (p.comm.size() > 1) p.engine->setDecomposition(p.decomposition.get());
    p.engine->prime();
    p.everyParticle(p.storage, [&](const sph::Storage<Dim>& all) {
        if (p.root()) p.state.start = conservationVector(all, p.setup->gravity(1e300));
    });
}

/// The observers of the apps' runs, in the order they act after a step; then a new run's first
/// output, at t = 0.
template <int Dim>
void addRunObservers(Simulation<Dim>& sim) {
    RunParts<Dim>& p = sim.parts();
    sim.addObserver(std::make_unique<HealthObserver<Dim>>(p));
    sim.addObserver(std::make_unique<ParticleFlowObserver<Dim>>(p));
    sim.addObserver(std::make_unique<ProgressObserver<Dim>>());
    sim.addObserver(std::make_unique<TestSignalObserver<Dim>>(stop::testSignal()));
    auto output = std::make_unique<OutputObserver<Dim>>(p);
    OutputObserver<Dim>& first = *output;
    sim.addObserver(std::move(output));
    ProbeObserver<Dim>* probes = nullptr;
    if (!p.scene.probes.empty()) {  // the same on every process: sampling gathers particles
        auto observer = std::make_unique<ProbeObserver<Dim>>(p);
        probes = observer.get();
        sim.addObserver(std::move(observer));
    }
    // After the probes: a checkpoint at a probe time holds its row.
    sim.addObserver(std::make_unique<CheckpointObserver<Dim>>(p.options.checkpointEvery));
    if (p.options.restart) return;
    first.write(sim);
    if (probes) probes->write(sim);
}

}  // namespace

template <int Dim>
Simulation<Dim>::Simulation(const SceneDocument& doc, const RunOptions& options)
    // Plugin libraries by absolute path: the scene a checkpoint stores finds them anywhere.
    : parts_(std::make_unique<RunParts<Dim>>(withAbsolutePluginPaths(doc), options)) {
    RunParts<Dim>& p = *parts_;
    // A signal ends the program at once until the loop.
    if (options.handleSignals) stop::duringSetUp(options.program);
    readRunScene(p);
    sph::Storage<Dim> initial = setUpParticles(p);
    sph::pollSetUpInterrupt();
    if (options.restart)
        readRestart(p, initial);
    else
        p.storage = std::move(initial);
    // Not needed any more: a copy of every particle for the whole run (a third of its memory).
    initial = sph::Storage<Dim>();
    makeEngine(p);
    sph::pollSetUpInterrupt();
    if (options.restart)
        resumeRun(p);
    else
        startRun(p);
    sph::pollSetUpInterrupt();
    p.startSteps = steps();
    // From here a signal asks for a stop (stop_signals.hpp): after the step in progress, or at
    // once when that step is still running half a second later. Several processes finish the
    // step in progress together: one alone cannot abandon it.
    if (options.handleSignals) stop::duringRun();
    if (p.comm.size() == 1)
        p.engine->setAbandonCheck([&p] { return stop::abandonStep(p.stepClock().steps() + 1); });
    p.progress.emplace(options.quiet || !options.progressLine || !p.root() ? Progress::Mode::QUIET
                       : ::isatty(fileno(stdout)) ? Progress::Mode::TERMINAL
                                                  : Progress::Mode::PLAIN,
                       time(), p.scene.endTime);
    addRunObservers(*this);
}

template <int Dim>
Simulation<Dim>::~Simulation() = default;

template <int Dim>
double Simulation<Dim>::time() const {
    return parts_->stepClock().time();
}
template <int Dim>
double Simulation<Dim>::endTime() const {
    return parts_->scene.endTime;
}
template <int Dim>
std::uint64_t Simulation<Dim>::steps() const {
    return parts_->stepClock().steps();
}

template <int Dim>
bool Simulation<Dim>::stopRequested() const {
    return parts_->comm.any(stop::requested() != 0 || parts_->stopAsked);
}

template <int Dim>
void Simulation<Dim>::requestStop() {
    parts_->stopAsked = true;
}

template <int Dim>
const Scene<Dim>& Simulation<Dim>::scene() const {
    return parts_->scene;
}

template <int Dim>
sph::MovingBodies<Dim>* Simulation<Dim>::movingBodies() {
    return parts_->setup->model.movingBodies.get();
}

template <int Dim>
const FieldNames& Simulation<Dim>::fieldNames() const {
    return parts_->fieldNames;
}

template <int Dim>
void Simulation<Dim>::addObserver(std::unique_ptr<IStepObserver<Dim>> observer) {
    observers_.push_back(std::move(observer));
}

template <int Dim>
void Simulation<Dim>::copyParticlesToHost() {
    parts_->engine->copyToHost();
}

template <int Dim>
const sph::Storage<Dim>& Simulation<Dim>::particles() {
    copyParticlesToHost();
    return parts_->storage;
}

template <int Dim>
sph::Storage<Dim>& Simulation<Dim>::particlesToChange() {
    copyParticlesToHost();
    if (!parts_->hostChanged) parts_->written.remember(parts_->storage);
    parts_->hostChanged = true;
    return parts_->storage;
}

/// Particles a front end wrote between steps: every written quantity is checked
/// (written_particles.hpp); on the CUDA back end they go up to the GPU again.
template <int Dim>
void Simulation<Dim>::acceptChangedParticles() {
    RunParts<Dim>& p = *parts_;
    p.written.check(p.storage, p.fieldNames, p.setup->geometry.domain);
    p.hostChanged = false;
    p.engine->takeWrittenParticles();
}

template <int Dim>
double Simulation<Dim>::step() {
    return stepTowards(endTime());
}

template <int Dim>
void Simulation<Dim>::advanceTo(double t) {
    const double limit = std::min(t, endTime());
    while (!reached(time(), limit) && !stopRequested()) stepTowards(limit);
}

template <int Dim>
double Simulation<Dim>::stepTowards(double limit) {
    RunParts<Dim>& p = *parts_;
    if (p.hostChanged) acceptChangedParticles();
    double landing = std::numeric_limits<double>::infinity();
    for (const auto& o : observers_) landing = std::min(landing, o->landingTime());
    // A limit on a landing time (to round-off) steps to that time exactly, as a longer run does.
    const double target = reached(limit, landing) ? landing : limit;
    const bool endStep = target < landing && time() + p.engine->allowedStep() > target;
    for (auto& o : observers_) o->beforeStep(*this, endStep);
    double dt = 0;
    try {
        dt = p.engine->step(target);
    } catch (const AppError& e) {
        // An error this process met alone, mid-step.
        if (p.comm.size() > 1) throw LoneFailure(e);
        throw;
    }
    // A plugin's term that failed on any process, reported once (plugin_term.hpp).
    if (p.comm.size() > 1 && !p.plugins->empty())
        agreed(p.comm, [&] { p.plugins->failure->rethrow(); });
    p.owned = p.countOwned();
    p.particles = p.comm.sum(p.owned);
    p.particleSteps += double(p.particles);
    bool wanted = reached(time(), endTime());
    for (const auto& o : observers_) wanted = wanted || o->needsParticles(*this);
    if (wanted) copyParticlesToHost();
    for (auto& o : observers_) o->afterStep(*this);
    return dt;
}

template <int Dim>
int Simulation<Dim>::run() {
    RunEnd end;
    try {
        try {
            advanceTo(endTime());
        } catch (const sph::EvaluationAbandoned&) {
            end.abandoned = true;
        }
        if (stopRequested()) end.status = "interrupted";
        copyParticlesToHost();
        if (end.abandoned)
            reportAbandonedStep(end);
        else
            for (auto& o : observers_) o->afterRun(*this, end);
    } catch (const LoneFailure&) {
        throw;  // the other processes wait mid-step: no summary, every process ends at once
    } catch (const AppError& e) {
        // A plugin term that failed in a step stops the run as an instability does.
        if (e.code() != ExitCode::UNSTABLE && e.code() != ExitCode::PLUGIN) throw;
        end.status = e.code() == ExitCode::UNSTABLE ? "unstable" : "failed";
        end.message = e.what(), end.failure = e.code();
        // The first step from a checkpoint: the checkpoint may hold a state no run reached.
        if (parts_->options.restart && e.code() == ExitCode::UNSTABLE &&
            steps() <= parts_->startSteps + 1)
            end.message += "; this was the first step from " + *parts_->options.restart +
                           ": if that checkpoint was edited, restart from one that was not";
    }
    return finishRun(std::move(end));
}

/// The storage is part-way through the abandoned step: no output or checkpoint of it.
template <int Dim>
void Simulation<Dim>::reportAbandonedStep(RunEnd& end) {
    const RunParts<Dim>& p = *parts_;
    end.message =
        std::string("stopped by ") + stop::signalName(stop::requested()) + " during step " +
        std::to_string(steps() + 1) + " from t = " + formatted("%g", time()) +
        " s: the step was abandoned, the outputs written " + "before stay" +
        (p.lastOutput >= 0 ? " (the last at t = " + formatted("%g", p.lastOutput) + " s)" : "");
    if (!p.options.quiet) p.progress->clearLine();
    std::fprintf(stderr, "%s: %s\n", p.options.program.c_str(), end.message.c_str());
}

template <int Dim>
int runSimulation(const SceneDocument& doc, const RunOptions& options) {
    Simulation<Dim> simulation(doc, options);
    return simulation.run();
}

template class Simulation<2>;
template class Simulation<3>;
template int runSimulation<2>(const SceneDocument&, const RunOptions&);
template int runSimulation<3>(const SceneDocument&, const RunOptions&);

}  // namespace num::app
