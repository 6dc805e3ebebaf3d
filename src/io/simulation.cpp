// The time loop of the apps.
#include "io/simulation.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "agreed_errors.hpp"
#include "device_backend.hpp"
#include "fingerprint.hpp"
#include "initial_state.hpp"
#include "io/checkpoint.hpp"
#include "io/diagnostics.hpp"
#include "io/emitters.hpp"
#include "io/file.hpp"
#include "io/formatted.hpp"
#include "io/outputs.hpp"
#include "io/progress.hpp"
#include "parallel/domain_decomposition.hpp"
#include "physical_check.hpp"
#include "plugins.hpp"
#include "run_limits.hpp"
#include "run_report.hpp"
#include "run_state.hpp"
#include "sph/timestepping.hpp"
#include "stop_signals.hpp"

namespace num::io {

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

/// The number of particles a process owns (those not yet assigned count on the root).
template <int Dim>
std::int64_t ownedParticles(const sph::Storage<Dim>& s, const parallel::Communicator& comm) {
    std::int64_t n = 0;
    for (int owner : s.template getValue<int>(QuantityId::OWNER))
        n += owner == comm.rank() || (owner < 0 && comm.isRoot());
    return n;
}

template <int Dim>
int runSimulation(const SceneDocument& given, const RunOptions& opt) {
    const auto wallStart = std::chrono::steady_clock::now();
    const parallel::Communicator single;
    const parallel::Communicator& comm = opt.communicator ? *opt.communicator : single;
    const bool root = comm.isRoot();
    // Plugin libraries by absolute path: the scene a checkpoint stores finds them anywhere.
    const SceneDocument doc = withAbsolutePluginPaths(given);
    const stop::DefaultsOnExit defaultSignalsOnExit;
    stop::duringSetUp(opt.program);  // a signal ends the program at once until the time loop
    Scene<Dim> scene = readScene<Dim>(doc);
    if (opt.endTime) scene.endTime = *opt.endTime;
    if (opt.outDir) scene.output.directory = *opt.outDir;
    if (!opt.quiet && root)
        for (const std::string& w : scene.warnings)
            std::fprintf(stderr, "%s: warning: %s\n", opt.program.c_str(), w.c_str());
    // The CUDA back end runs the steps on the GPU; the CPU backend's threads do the rest.
    const bool onCuda = runsOnCuda(scene, opt);
    const std::string cpuBackend =
        opt.backend == "cuda" || opt.backend == "cpu" ? "threads" : opt.backend;
    const int threads = cpuBackend == "seq" ? 1
                        : opt.threads > 0   ? opt.threads
                                          : int(std::max(1u, std::thread::hardware_concurrency()));
    checkGravity(scene);
    const ScenePlugins<Dim> plugins = loadPlugins<Dim>(doc);  // before set-up, in scene order
    SceneSetup<Dim> setup = makeSceneSetup(scene, threads, plugins.terms);
    if (onCuda) checkCudaRun(scene, setup, opt, !plugins.empty(), comm.size());
    checkRunLimits(scene, setup, opt.checkpointEvery);
    sph::Storage<Dim> initial = makeInitialStorage(scene, setup);
    checkInitialState(scene, setup, initial);
    if (comm.size() > 1 && setup.settings.template get<std::string>("evaluation") == "symmetric")
        throw AppError(ExitCode::USAGE,
                       "numerics.evaluation \"symmetric\" cannot run on several processes: "
                       "remove it (the default gathers) or run without mpirun");
    // The process that owns each particle (parallel/domain_decomposition.hpp); -1 until the
    // particles are distributed.
    initial.template insert<int>(QuantityId::OWNER, sph::OrderEnum::ZERO, -1);
    for (auto& t : setup.emitterTemplates)
        t.template insert<int>(QuantityId::OWNER, sph::OrderEnum::ZERO, -1);
    const std::string dir = scene.output.directory;
    const std::string fingerprint = runFingerprint(doc, setup, initial) + plugins.fingerprint;
    const FieldNames fieldNames = pluginFieldNames(plugins, initial, opt.fieldNames, doc.file());

    // The root writes every output, from the particles of every process gathered.
    std::optional<Outputs<Dim>> outputs;
    onRoot(comm, [&] { outputs.emplace(scene, setup, dir, initial, fieldNames); });
    const std::size_t initialParticles = initial.size();

    RunState<Dim> state;
    sph::Storage<Dim> storage;
    if (opt.restart) {
        const std::string payload = readCheckpointFile(*opt.restart, Dim);
        ByteReader r(payload, *opt.restart);
        r.getString();  // the scene, read by the caller
        checkFingerprint(r.getString(), fingerprint, *opt.restart);
        state.read(r);
        if (state.emitterLayers.size() != scene.emitters.size())
            throw AppError(ExitCode::CHECKPOINT, *opt.restart + ": the checkpoint has " +
                                                     std::to_string(state.emitterLayers.size()) +
                                                     " emitters, the scene " +
                                                     std::to_string(scene.emitters.size()));
        storage = readStorage<Dim>(r, initial);
        if (state.time >= scene.endTime)
            throw AppError(ExitCode::USAGE,
                           *opt.restart + ": the checkpoint is at t = " +
                               formatted("%g", state.time) + " s, at or after the end time " +
                               formatted("%g", scene.endTime) + " s (raise it with --end-time)");
    } else {
        storage = std::move(initial);
    }
    // Not needed any more: a copy of every particle for the whole run (a third of its memory).
    initial = sph::Storage<Dim>();
    Emitters<Dim> emitters(scene, setup);
    emitters.layers() = state.emitterLayers.empty() ? emitters.layers() : state.emitterLayers;
    emitters.setEmitted(state.emitted);
    emitters.setBlocked(state.emitterBlocked);

    auto scheduler = sph::makeScheduler(cpuBackend, Size(threads));
    sph::Solver<Dim> solver(*scheduler, setup.settings,
                            sph::makeFluidEquations(setup.model, setup.geometry),
                            setup.geometry.domain);
    auto integrator = sph::makeIntegrator<Dim>(scene.integrator);
    sph::Run<Dim> run(storage, solver, *integrator, state.time);
    // On the CUDA back end the steps run on the GPU (gpu below); `run` then keeps the time and
    // the step count, and `storage` is brought up to date for outputs, checkpoints and checks.
    std::unique_ptr<device::DeviceRun<Dim>> gpu;
    if (onCuda) gpu = makeCudaRun(setup, state.time);
    // Each process keeps its share of the particles and a halo; one process keeps them all.
    parallel::DomainDecomposition<Dim> decomposition(comm, solver.domain(),
                                                     solver.kernel().supportRadius());
    // Every particle at once: the whole storage on the root (a copy only with several
    // processes), for outputs, checkpoints and the summary.
    auto everyParticle = [&](const sph::Storage<Dim>& s, auto&& use) {
        if (comm.size() == 1) return use(s);
        const sph::Storage<Dim> all = decomposition.gatherToRoot(s);
        return use(all);
    };
    // A nozzle point is left out where water is, every process agreeing (io/emitters.hpp).
    const sph::RunKernel<Dim> kernel(setup.settings);
    auto occupied = [&](const std::vector<sph::Vector<Dim>>& points) {
        return occupiedPoints(storage, solver.domain(), kernel, points, scene.spacing, comm);
    };
    std::size_t emitterWarningsPrinted = 0;  // of emitters.warnings(), by the time loop
    // Emitted particles come last in the particle order, with ids after the initial particles'
    // (the same on every process: each emits every particle, and keeps its own).
    auto emit = [&, firstId = initialParticles](double t) {
        const std::size_t before = emitters.emitted(), added = emitters.emit(storage, t, occupied);
        auto id = storage.template getValue<int>(QuantityId::PARTICLE_ID);
        auto key = storage.template getValue<int>(QuantityId::ORDER_KEY);
        for (std::size_t k = 0; k < added; ++k) {
            const std::size_t i = storage.size() - added + k;
            id[i] = int(firstId + before + k), key[i] = sph::kNewParticleKey;
        }
        return added;
    };
    if (opt.restart) {
        // The checkpoint holds the derivatives at its time; terms keep no time of their own (a
        // step's post-step phase gets its dt from Run), so the run continues as it would have.
        decomposition.distribute(storage);
        if (comm.size() > 1) solver.setDecomposition(&decomposition);
        run.setTime(state.time, Size(state.steps));
        run.markPrimed(true);
        if (gpu) gpu->setTime(state.time, Size(state.steps)), gpu->upload(storage, true);
        onRoot(comm, [&] { outputs->resume(state.time, state.series); });
    } else {
        onRoot(comm, [&] { outputs->start(); });
        if (root && !outputs->earlierRunNote().empty()) {
            if (!opt.quiet)
                std::fprintf(stderr, "%s: warning: %s\n", opt.program.c_str(),
                             outputs->earlierRunNote().c_str());
            scene.warnings.push_back(outputs->earlierRunNote());  // and in summary.json
        }
        emit(0.0);
        decomposition.distribute(storage);
        if (comm.size() > 1) solver.setDecomposition(&decomposition);
        if (gpu) {
            gpu->upload(storage, false);
            gpu->prime();
            gpu->download(storage);
        } else {
            run.prime();
        }
        everyParticle(storage, [&](const sph::Storage<Dim>& all) {
            if (root) state.start = conservationVector(all, setup.gravity(1e300));
        });
    }
    const double every = scene.output.every;
    auto reached = [](double t, double target) {
        return t >= target - 1e-9 * std::max(1e-300, std::abs(target)) - 1e-300;
    };
    // Outputs fall on multiples of `every`; outputSlot is the next multiple, the file index
    // (state.outputIndex) counts the files written. They differ only after a restart with
    // another output.every: its outputs go on from the first multiple after the checkpoint's
    // time and its files from the next free index, so no earlier file is overwritten.
    std::int64_t outputSlot = 0;  // a new run writes its output at t = 0 first
    if (opt.restart) {
        outputSlot = std::max<std::int64_t>(0, std::int64_t(state.time / every) - 1);
        while (reached(state.time, double(outputSlot) * every)) ++outputSlot;
    }
    auto nextOutputTime = [&] { return double(outputSlot) * every; };

    // From here a signal asks for a stop (stop_signals.hpp): after the step in progress, or at
    // once when that step is still running half a second later.
    stop::duringRun();
    const stop::TestSignal testSignal = stop::testSignal();
    // Several processes finish the step in progress together: one alone cannot abandon it.
    if (comm.size() == 1 && !gpu)
        solver.setAbandonCheck([&] { return stop::abandonStep(run.steps() + 1); });
    Progress progress(opt.quiet || !root         ? Progress::Mode::QUIET
                      : ::isatty(fileno(stdout)) ? Progress::Mode::TERMINAL
                                                 : Progress::Mode::PLAIN,
                      run.time(), scene.endTime);
    PhysicalCheck physical(setup.velocityScale, setup.model.c0(), setup.model.restDensity);
    for (const auto& r : plugins.ranges)
        physical.addRange({r.id, r.name, r.unit, r.lo, r.hi,
                           "the range the plugin " + r.library + " declares for it"});
    std::vector<std::pair<double, std::string>> checkpoints;
    auto resumable = [&] {
        RunState<Dim> r = state;
        r.time = run.time(), r.steps = run.steps();
        r.emitterLayers = emitters.layers(), r.emitted = emitters.emitted();
        r.emitterBlocked = emitters.blocked();
        if (root) r.series = outputs->series().entries();
        return r;
    };
    // A step cut short by an unaligned end time leaves the trajectory a longer run follows: a
    // checkpoint then holds the state before that step, so a restart continues bitwise.
    std::optional<std::pair<RunState<Dim>, sph::Storage<Dim>>> beforeEndStep;
    auto writeCheckpoint = [&](const std::string& name) {
        const RunState<Dim> r = beforeEndStep ? beforeEndStep->first : resumable();
        everyParticle(beforeEndStep ? beforeEndStep->second : storage,
                      [&](const sph::Storage<Dim>& all) {
                          onRoot(comm, [&] {
                              ByteWriter w;
                              w.putString(doc.dump());
                              w.putString(fingerprint);
                              r.write(w);
                              writeStorage(w, all);
                              writeCheckpointFile(outputs->path(name), Dim, w.bytes());
                          });
                      });
        checkpoints.emplace_back(r.time, name);
    };
    auto output = [&] {
        everyParticle(storage, [&](const sph::Storage<Dim>& all) {
            onRoot(comm, [&] { outputs->write(all, run.time(), state.outputIndex); });
        });
        ++state.outputIndex, ++outputSlot;
    };
    double lastOutput = -1;
    if (!opt.restart) output(), lastOutput = 0;

    std::string status = "completed", message;
    ExitCode failure = ExitCode::OK;
    bool abandoned = false;
    double particleSteps = 0;
    const std::uint64_t startSteps = run.steps();
    // A signal reaches the processes at different moments: they stop when any has one.
    auto stopRequested = [&] { return comm.any(stop::requested() != 0); };
    try {
        while (!reached(run.time(), scene.endTime) && !stopRequested()) {
            // An end time on an output time (to round-off) steps to that output time exactly,
            // as a longer run does.
            const double next = nextOutputTime();
            const double stop = reached(scene.endTime, next) ? next : scene.endTime;
            const double nextDt =
                gpu ? gpu->timeStepLimits().dt() : solver.timeStepLimits(storage).dt();
            if (stop < next && run.time() + nextDt > stop) {
                if (gpu) gpu->download(storage);
                beforeEndStep.emplace(resumable(), storage);
            }
            double dt = 0;
            try {
                if (gpu) {
                    dt = gpu->step(stop);
                    run.setTime(gpu->time(), gpu->steps());
                } else {
                    dt = run.step(stop);
                }
            } catch (const sph::EvaluationAbandoned&) {
                abandoned = true;
                break;
            } catch (const AppError& e) {
                // A plugin's term that failed on this process alone, mid-step.
                if (comm.size() > 1) throw LoneFailure(e);
                throw;
            }
            const std::int64_t owned = ownedParticles(storage, comm);
            const std::int64_t particles = comm.sum(owned);
            particleSteps += double(particles);
            // On the GPU the particles are copied back (and checked) only when an output or a
            // checkpoint is due, or the run ends.
            const bool current =
                !gpu || reached(run.time(), nextOutputTime()) ||
                reached(run.time(), scene.endTime) ||
                (opt.checkpointEvery > 0 &&
                 reached(run.time(), (state.checkpointCount + 1) * opt.checkpointEvery)) ||
                (testSignal.signal && run.steps() == testSignal.step);
            if (gpu && current) gpu->download(storage);
            if (current)
                agreed(comm, [&] {
                    checkHealth(*scheduler, storage, scene, run.time(), run.steps(), dt,
                                gpu ? gpu->limitingCriterion() : run.limitingCriterion(),
                                fieldNames);
                });
            if (const std::string w =
                    current ? physical.check(storage, run.time(), comm, *scheduler) : std::string();
                !w.empty() && !opt.quiet && root) {
                progress.clearLine();
                std::fprintf(stderr, "%s: warning: %s\n", opt.program.c_str(), w.c_str());
            }
            const bool anyRemoved = comm.any(removeOutflow(storage, scene) > 0);
            if (anyRemoved) {
                state.removed += std::uint64_t(comm.sum(owned - ownedParticles(storage, comm)));
                run.particlesChanged();
            }
            if (emit(run.time()) > 0) run.particlesChanged();
            for (; emitterWarningsPrinted < emitters.warnings().size(); ++emitterWarningsPrinted)
                if (!opt.quiet && root) {
                    progress.clearLine();
                    std::fprintf(stderr, "%s: warning: %s\n", opt.program.c_str(),
                                 emitters.warnings()[emitterWarningsPrinted].c_str());
                }
            progress.update(run.time(), dt, Size(particles), run.steps());
            if (testSignal.signal && run.steps() == testSignal.step) std::raise(testSignal.signal);
            if (reached(run.time(), nextOutputTime())) output(), lastOutput = run.time();
            if (opt.checkpointEvery > 0 &&
                reached(run.time(), (state.checkpointCount + 1) * opt.checkpointEvery)) {
                while (reached(run.time(), (state.checkpointCount + 1) * opt.checkpointEvery))
                    ++state.checkpointCount;
                writeCheckpoint(formatted("checkpoint_%04.0f.chk", double(state.checkpointCount)));
            }
        }
        if (stopRequested()) status = "interrupted";
        if (gpu) gpu->download(storage);
        if (abandoned) {
            // The storage is part-way through the abandoned step: no output or checkpoint of it.
            message =
                std::string("stopped by ") + stop::signalName(stop::requested()) + " during step " +
                std::to_string(run.steps() + 1) + " from t = " + formatted("%g", run.time()) +
                " s: the step was abandoned, the outputs written before stay" +
                (lastOutput >= 0 ? " (the last at t = " + formatted("%g", lastOutput) + " s)" : "");
            if (!opt.quiet) progress.clearLine();
            std::fprintf(stderr, "%s: %s\n", opt.program.c_str(), message.c_str());
        } else {
            if (run.time() != lastOutput) output();
            if (status == "interrupted") writeCheckpoint("checkpoint_interrupted.chk");
        }
    } catch (const LoneFailure&) {
        throw;  // the other processes wait mid-step: no summary, every process ends at once
    } catch (const AppError& e) {
        // A plugin term that failed in a step stops the run as an instability does.
        if (e.code() != ExitCode::UNSTABLE && e.code() != ExitCode::PLUGIN) throw;
        status = e.code() == ExitCode::UNSTABLE ? "unstable" : "failed", message = e.what();
        // The first step from a checkpoint: the checkpoint may hold a state no run reached.
        if (opt.restart && e.code() == ExitCode::UNSTABLE && run.steps() <= startSteps + 1)
            message += "; this was the first step from " + *opt.restart +
                       ": if that checkpoint was edited, restart from one that was not";
        failure = e.code();
    }
    const std::int64_t particles = comm.sum(ownedParticles(storage, comm));
    progress.finish(run.time(), gpu ? gpu->lastDt() : run.lastDt(), Size(particles), run.steps());

    state.emitted = emitters.emitted();
    state.emitterBlocked = emitters.blocked();
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
    // The decomposition's figures, summed over the processes.
    const std::int64_t haloParticles = comm.sum(decomposition.haloParticles());
    const std::int64_t haloBytes = comm.sum(std::int64_t(decomposition.haloBytes()));
    const auto exchanges = std::int64_t(decomposition.exchanges());
    EndOfRun end;
    nlohmann::json summary;
    everyParticle(storage, [&](const sph::Storage<Dim>& all) {
        onRoot(comm, [&] {
            end = outputs->finish(status == "completed");
            summary =
                summaryJson(scene, all, setup, state, run.time(), run.steps(),
                            run.steps() - startSteps, wall, particleSteps, threads,
                            gpu ? "cuda" : cpuBackend, status, message, solver.meanNeighbours());
        });
    });
    summary["processes"] = comm.size();
    if (gpu) {
        summary["device"] = cudaDeviceText();
        summary["device_bytes"] = gpu->fluid().bytes();
        summary["device_bytes_per_particle"] =
            double(gpu->fluid().bytes()) / double(std::max<std::size_t>(1, storage.size()));
    }
    summary["neighbour_list_builds"] = solver.neighbours().builds();
    summary["decomposition"] = {
        {"load_imbalance", decomposition.imbalance()},
        {"repartitions", decomposition.repartitions()},
        {"halo_particles", haloParticles},
        {"halo_bytes_per_exchange", exchanges > 0 ? double(haloBytes) / double(exchanges) : 0.0},
        {"halo_bytes_per_step",
         run.steps() > startSteps ? double(haloBytes) / double(run.steps() - startSteps) : 0.0},
        {"note",
         "load_imbalance: the most loaded process's fluid particles over the mean, less one, "
         "at the last redistribution; halo figures summed over the processes, at the end"}};
    for (const auto& [t, f] : checkpoints)
        summary["checkpoints"].push_back({{"time", t}, {"file", f}});
    // The passes of an evaluation, each with its terms in the order they run.
    const std::vector<std::string> termNames = solver.equations().names();
    for (const auto& pass : solver.schedule().passes) {
        nlohmann::json names = nlohmann::json::array();
        for (std::size_t t : pass.terms) names.push_back(termNames[t]);
        summary["passes"].push_back(names);
    }
    std::vector<std::string> warnings = scene.warnings;
    warnings.insert(warnings.end(), physical.warnings().begin(), physical.warnings().end());
    warnings.insert(warnings.end(), emitters.warnings().begin(), emitters.warnings().end());
    onRoot(comm, [&] {
        addEndOfRun(summary, end, warnings);
        writeFileAtomically(outputs->path("summary.json"), summary.dump(2) + "\n");
    });
    // Until here a first signal only sets the flag: the video and the summary are still made.
    stop::restoreDefaults();

    if (status == "unstable" || status == "failed")
        throw AppError(failure, message + " (last good output kept in " + dir + ")");
    if (!opt.quiet && root) printRunReport(opt.program, *outputs, scene, end, summary);
    return status == "interrupted" ? int(ExitCode::INTERRUPTED) : 0;
}

template int runSimulation<2>(const SceneDocument&, const RunOptions&);
template int runSimulation<3>(const SceneDocument&, const RunOptions&);

}  // namespace num::io
