// The end of a Simulation's run: summary.json (with what each observer adds), the report on
// the terminal and the exit code.
#include "app/file.hpp"
#include "run/run_parts.hpp"
#include "run/run_report.hpp"
#include "run/run_state.hpp"

namespace num::app {

namespace {

/// The decomposition's figures, summed over the processes.
template <int Dim>
nlohmann::json decompositionJson(const RunParts<Dim>& p, std::uint64_t runSteps) {
    const parallel::DomainDecomposition<Dim>& d = *p.decomposition;
    const std::int64_t haloParticles = p.comm.sum(d.haloParticles());
    const std::int64_t haloBytes = p.comm.sum(std::int64_t(d.haloBytes()));
    const auto exchanges = std::int64_t(d.exchanges());
    return {
        {"load_imbalance", d.imbalance()},
        {"repartitions", d.repartitions()},
        {"halo_particles", haloParticles},
        {"halo_bytes_per_exchange", exchanges > 0 ? double(haloBytes) / double(exchanges) : 0.0},
        {"halo_bytes_per_step", runSteps > 0 ? double(haloBytes) / double(runSteps) : 0.0},
        {"note",
         "load_imbalance: the most loaded process's fluid particles over the mean, less one, "
         "at the last redistribution; halo figures summed over the processes, at the end"}};
}

/// What crossed the inlets and outlets, and the heat the walls and bodies gave (with heat, on
/// one process), in summary.json's conservation books: mass end = start + in - out to round-off,
/// thermal energy end = start + in - out + walls (docs/scenes.md, "Outputs").
template <int Dim>
void addFlowBooks(const RunParts<Dim>& p, nlohmann::json& summary) {
    nlohmann::json& c = summary["conservation"];
    const auto& flow = p.setup->model.flowBoundaries;
    const sph::FlowBooks books = flow ? flow->books : sph::FlowBooks{};
    c["mass"]["in"] = books.massIn, c["mass"]["out"] = books.massOut;
    c["thermal_energy"]["in"] = books.heatIn, c["thermal_energy"]["out"] = books.heatOut;
    // The walls' books are each process's own sums: given on one process only.
    const auto* walls = p.engine->wallHeat();
    if (walls && p.comm.size() == 1)
        c["thermal_energy"]["walls"] = walls->heatFromFixed() + walls->heatFromSources();
}

}  // namespace

template <int Dim>
int Simulation<Dim>::finishRun(RunEnd end) {
    RunParts<Dim>& p = *parts_;
    const double lastDt = p.stepClock().lastDt();
    p.progress->finish(time(), lastDt, sph::Size(p.comm.sum(p.countOwned())), steps());
    p.state.emitted = p.emitters->emitted();
    p.state.emitterBlocked = p.emitters->blocked();
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - p.wallStart).count();
    const std::uint64_t runSteps = steps() - p.startSteps;
    const nlohmann::json decomposition = decompositionJson(p, runSteps);
    EndOfRun files;
    p.everyParticle(p.storage, [&](const sph::Storage<Dim>& all) {
        onRoot(p.comm, [&] {
            files = p.outputs->finish(end.status == "completed");
            end.summary = summaryJson(p.scene, all, *p.setup, p.state, time(), steps(), runSteps,
                                      wall, p.particleSteps, p.threads, p.engine->backend(),
                                      end.status, end.message, p.engine->meanNeighbours());
        });
    });
    end.summary["processes"] = p.comm.size();
    p.engine->describe(end.summary, p.storage.size());
    if (p.root()) addFlowBooks(p, end.summary);
    end.summary["decomposition"] = decomposition;
    end.warnings = p.scene.warnings;
    for (auto& o : observers_) o->summarize(*this, end);
    onRoot(p.comm, [&] {
        addEndOfRun(end.summary, files, end.warnings);
        writeFileAtomically(p.outputs->path("summary.json"), end.summary.dump(2) + "\n");
        p.outputs->releaseLock();  // the run's last file
    });
    // Until here a first signal only sets the flag: the video and the summary are still made.
    if (p.options.handleSignals) stop::restoreDefaults();
    if (end.status == "unstable" || end.status == "failed")
        throw AppError(end.failure, end.message + " (last good output kept in " +
                                        p.scene.output.directory + ")");
    if (!p.options.quiet && p.root())
        printRunReport(p.options.program, *p.outputs, p.scene, files, end.summary);
    return end.status == "interrupted" ? int(ExitCode::INTERRUPTED) : 0;
}

template int Simulation<2>::finishRun(RunEnd);
template int Simulation<3>::finishRun(RunEnd);

}  // namespace num::app
