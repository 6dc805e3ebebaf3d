// Limits checked before anything is allocated (internal to numerics_app), so that no scene makes
// the apps write files without end, walk a lattice for hours or run out of memory: the number
// of outputs and checkpoints, the lattice the set-up walks, and every particle the run will
// hold (fluid, walls, bodies, emitted) against the memory of the machine.
#pragma once

#include <unistd.h>

#include <cmath>
#include <fstream>
#include <string>

#include "app/formatted.hpp"
#include "app/scene_setup.hpp"

namespace num::app {

inline constexpr double kMaxOutputs = 1e5;         ///< outputs (and checkpoints) per run
inline constexpr double kMaxParticles = 2e7;       ///< particles of all kinds
inline constexpr double kMaxLatticePoints = 2e8;   ///< lattice points the set-up visits
inline constexpr double kBytesPerParticle = 1024;  ///< measured: about 1 KB per particle

/// Memory available to the run [bytes]: MemAvailable of /proc/meminfo, else physical memory.
inline double availableMemory() {
    std::ifstream in("/proc/meminfo");
    std::string key;
    double kb = 0;
    while (in >> key >> kb)
        if (key == "MemAvailable:") return kb * 1024;
    return double(::sysconf(_SC_PHYS_PAGES)) * double(::sysconf(_SC_PAGESIZE));
}

/// A count in full below a million, else in three digits ("1.23e+08").
inline std::string count(double n) { return n < 1e6 ? formatted("%.0f", n) : formatted("%.3g", n); }

/// Refuses a run that would write more than kMaxOutputs outputs or checkpoints.
template <int Dim>
void checkOutputCounts(const Scene<Dim>& scene, double checkpointEvery) {
    const double outputs = scene.endTime / scene.output.every;
    if (outputs > kMaxOutputs)
        throw sceneError(
            scene.file, "output.every",
            "an interval giving at most " + count(kMaxOutputs) + " outputs over the run",
            count(outputs) +
                formatted(" outputs (every %g s until %g s)", scene.output.every, scene.endTime));
    if (checkpointEvery > 0 && scene.endTime / checkpointEvery > kMaxOutputs)
        throw AppError(ExitCode::USAGE, "--checkpoint-every: at most " + count(kMaxOutputs) +
                                            " checkpoints per run, found " +
                                            count(scene.endTime / checkpointEvery));
}

/// A shape's volume in lattice cells; another shape than a box or ball by its bounding box
/// within the domain.
template <int Dim>
double latticeCells(const SceneShape<Dim>& f, const Scene<Dim>& scene) {
    const double dx = scene.spacing;
    double v = 1;
    const geometry::Bounds<Dim> b = f.placed().bounds();
    for (int k = 0; k < Dim; ++k)
        if (f.shape == ShapeKind::SOLID)
            v *= std::max(0.0, std::min(b.max[k], scene.domainMax[k]) -
                                   std::max(b.min[k], scene.domainMin[k])) /
                 dx;
        else if (f.shape == ShapeKind::BOX)
            v *= (f.max[k] - f.min[k]) / dx;
    if (f.shape == ShapeKind::CIRCLE || f.shape == ShapeKind::SPHERE)
        v = Dim == 2 ? M_PI * f.radius * f.radius / (dx * dx)
                     : 4.0 / 3 * M_PI * std::pow(f.radius / dx, 3);
    return v;
}

/// The scene's particles, estimated before they are made.
struct ParticleEstimate {
    double lattice = 1, inside = 1;  ///< lattice points with and without the walls' layers
    double fluid = 0, bodies = 0, emitted = 0;
    double walls() const { return lattice - inside; }
    double total() const { return fluid + walls() + bodies + emitted; }
};

template <int Dim>
ParticleEstimate estimateParticles(const Scene<Dim>& scene, const SceneSetup<Dim>& setup) {
    const double dx = scene.spacing, layers = setup.wallLayers;
    ParticleEstimate e;
    for (int k = 0; k < Dim; ++k) {
        const double n = (scene.domainMax[k] - scene.domainMin[k]) / dx;
        int walls = 0;
        for (int hi = 0; hi < 2; ++hi) walls += setup.geometry.hasWall(k, hi);
        e.lattice *= n + walls * layers, e.inside *= n;
    }
    for (const auto& f : scene.fluids) e.fluid += latticeCells(f, scene);
    for (const auto& b : scene.bodies) e.bodies += latticeCells(b, scene);
    for (const auto& m : scene.emitters) {
        const double across = Dim == 2 ? 2 * m.radius / dx : M_PI * std::pow(m.radius / dx, 2);
        const double seconds = std::max(0.0, std::min(m.end, scene.endTime) - m.start);
        e.emitted += std::max(1.0, across) * (m.speed * seconds / dx + 1);
    }
    return e;
}

/// Refuses a scene whose outputs, lattice, particles or memory exceed the limits.
template <int Dim>
void checkRunLimits(const Scene<Dim>& scene, const SceneSetup<Dim>& setup, double checkpointEvery) {
    checkOutputCounts(scene, checkpointEvery);
    const ParticleEstimate e = estimateParticles(scene, setup);
    const double total = e.total();
    const std::string numbers = "about " + count(total) + " particles (fluid " + count(e.fluid) +
                                ", walls " + count(e.walls()) + ", bodies " + count(e.bodies) +
                                ", emitted " + count(e.emitted) + ")";
    const char* hint = "increase particles.spacing, or shrink the domain, the blocks or emitters";
    if (e.lattice > kMaxLatticePoints)
        throw sceneError(
            scene.file, "particles.spacing",
            "at most " + count(kMaxLatticePoints) + " lattice points over the domain and its walls",
            count(e.lattice) + " (spacing " + formatted("%g", scene.spacing) + " m)", hint);
    if (total > kMaxParticles)
        throw sceneError(scene.file, "particles.spacing",
                         "a scene of at most " + count(kMaxParticles) + " particles", numbers,
                         hint);
    const double need = total * kBytesPerParticle, have = availableMemory();
    if (need > 0.8 * have) {
        const std::string mem =
            formatted(", which need about %.3g GB; %.3g GB are available", need / 1e9, have / 1e9);
        throw sceneError(scene.file, "particles.spacing",
                         "a scene that fits in memory (at most 80 % of what is available)",
                         numbers + mem, hint);
    }
}

}  // namespace num::app
