// What a run prints at its end: where its outputs went, then the key figures of summary.json
// (steps, speed, conservation drift, warnings), and one line each when the movie or the probes'
// plot is missing.
#pragma once

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/formatted.hpp"
#include "app/outputs.hpp"
#include "app/scene.hpp"

namespace num::app {

/// Adds the files made at the end of the run, why a movie is missing and the scene's warnings.
inline void addEndOfRun(nlohmann::json& summary, const EndOfRun& end,
                        const std::vector<std::string>& warnings) {
    summary["video"] = end.video;
    summary["video_note"] = end.videoNote;
    summary["probe_plot"] = end.probePlot;
    summary["probe_plot_note"] = end.probePlotNote;
    summary["paraview_script"] = end.paraviewScript;
    summary["warnings"] = warnings;
}

namespace detail {

/// "+0.012 %" of a relative change, or the absolute change with its unit when the start is 0.
inline std::string change(double start, double end, const char* unit) {
    if (std::abs(start) > 1e-300)
        return formatted("%+.3g %%", 100 * (end - start) / std::abs(start));
    return formatted("%+.3g %s", end - start, unit);
}

/// One line of the report's file list: "  NAME   what it holds".
inline void reportItem(const std::string& file, const std::string& what) {
    std::printf("  %-24s %s\n", file.c_str(), what.c_str());
}

/// The steps line and the particles line of the summary's figures.
inline void reportStepsAndParticles(const nlohmann::json& summary) {
    const double wall = summary.at("wall_seconds");
    reportItem("  steps",
               formatted("%llu (this run) in %.1f s, %.3g million particle-steps/s, %d threads",
                         (unsigned long long)summary.at("steps_this_run").get<std::uint64_t>(),
                         wall, summary.at("particle_steps_per_second").get<double>() * 1e-6,
                         summary.at("threads").get<int>()));
    std::string particles =
        formatted("%llu fluid of %llu (emitted %llu, removed %llu)",
                  (unsigned long long)summary.at("fluid_particles").get<std::uint64_t>(),
                  (unsigned long long)summary.at("particles").get<std::uint64_t>(),
                  (unsigned long long)summary.at("emitted_particles").get<std::uint64_t>(),
                  (unsigned long long)summary.at("removed_particles").get<std::uint64_t>());
    if (const auto blocked = summary.at("emitter_points_blocked").get<std::uint64_t>())
        particles += ", " + std::to_string(blocked) + " nozzle points left out (water was there)";
    reportItem("  particles", particles);
}

/// The conservation line: the books' balance where water flowed through inlets and outlets,
/// the drift of a closed system, or the mass of one that particles entered or left.
inline void reportConservation(const nlohmann::json& summary) {
    const auto& c = summary.at("conservation");
    auto startOf = [&](const char* k) { return c.at(k).at("start").get<double>(); };
    auto endOf = [&](const char* k) { return c.at(k).at("end").get<double>(); };
    auto booked = [&](const char* k, const char* part) {
        return c.at(k).contains(part) ? c.at(k).at(part).get<double>() : 0.0;
    };
    const bool closed = summary.at("emitted_particles").get<std::uint64_t>() == 0 &&
                        summary.at("removed_particles").get<std::uint64_t>() == 0;
    const bool flows = booked("mass", "in") != 0 || booked("mass", "out") != 0;
    const double mechStart = startOf("kinetic_energy") + startOf("potential_energy");
    const double mechEnd = endOf("kinetic_energy") + endOf("potential_energy");
    if (closed && flows)
        reportItem("  conservation books",
                   "mass end - (start + in - out) = " +
                       formatted("%.3g kg", endOf("mass") - startOf("mass") - booked("mass", "in") +
                                                booked("mass", "out")) +
                       ", thermal energy end - (start + in - out + walls) = " +
                       formatted("%.3g J", endOf("thermal_energy") - startOf("thermal_energy") -
                                               booked("thermal_energy", "in") +
                                               booked("thermal_energy", "out") -
                                               booked("thermal_energy", "walls")));
    else if (closed)
        reportItem("  conservation drift",
                   "mass " + change(startOf("mass"), endOf("mass"), "kg") +
                       ", kinetic + potential energy " + change(mechStart, mechEnd, "J") +
                       ", thermal energy " +
                       change(startOf("thermal_energy"), endOf("thermal_energy"), "J"));
    else  // particles came in or left: the sums are not meant to be conserved
        reportItem("  conservation", "not a closed system (emitters, open sides): fluid mass " +
                                         formatted("%.4g", startOf("mass")) + " -> " +
                                         formatted("%.4g", endOf("mass")) + " kg");
}

}  // namespace detail

template <int Dim>
void printRunReport(const std::string& program, const Outputs<Dim>& out, const Scene<Dim>&,
                    const EndOfRun& end, const nlohmann::json& summary) {
    const std::string status = summary.at("status");
    const bool completed = status == "completed";
    const std::string ended = completed                 ? "finished"
                              : status == "interrupted" ? "stopped by a signal"
                                                        : "stopped (" + status + ")";
    std::printf("%s: %s at t = %.4g s\n", program.c_str(), ended.c_str(),
                summary.at("final_time").get<double>());
    std::printf("Output written to %s/\n", out.directory().c_str());
    for (const WrittenFile& f : out.files()) detail::reportItem(f.name, f.what);
    detail::reportItem("summary.json",
                       "run statistics and conservation diagnostics; its key figures:");
    detail::reportStepsAndParticles(summary);
    detail::reportConservation(summary);
    const auto& warnings = summary.at("warnings");
    detail::reportItem("  warnings",
                       warnings.empty() ? "none" : std::to_string(warnings.size()) + " (above)");
    if (end.videoWanted && end.video.empty() && completed)
        std::printf("%s: no movie: %s\n", program.c_str(), end.videoNote.c_str());
    if (!end.probePlotNote.empty())  // the run itself went on: its probes.csv is there
        std::printf("%s: no probe plot: %s\n", program.c_str(), end.probePlotNote.c_str());
    std::fflush(stdout);
}

}  // namespace num::app
