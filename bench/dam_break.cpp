// End-to-end throughput of the dam-break benchmark scene (dam_break_scene.hpp).
//
//   bench_dam_break [--dim 2|3] [--dx D | --particles N] [--threads T] [--heat 0|1]
//                   [--steps S] [--warmup W] [--repeats R] [--evaluation asymmetric|symmetric]
//                   [--backend omp|threads]
//
// Builds the scene, primes it (first evaluation), runs W warm-up steps, then R timed runs of S
// steps each. Prints one "run ..." line per timed run and a "result ..." line with medians:
//   particle_steps_per_second  fluid particles x steps / seconds (PySPH's count: fluid only)
//   ns_per_particle_step       1e9 / the above
//   ns_per_any_particle_step   the same per particle of any kind (fluid, wall)
//   neighbours                 mean neighbours per particle (all particles, itself excluded)
//   cpu_ns_per_particle_step   CPU time of all threads per fluid particle-step (robust to load
//                              from other processes, unlike wall time)
//   bytes_per_particle         peak resident memory of the time loop (the kernel's high-water
//                              mark VmHWM, reset after set-up) minus the resident memory before
//                              the scene was built, divided by all particles
//   setup_bytes_per_particle   the same with the peak of the set-up (particle generation) too
//   storage_bytes_per_particle what the particle storage holds at the end (every level of every
//                              quantity, as allocated), divided by all particles: the rest of
//                              bytes_per_particle is the neighbour list, the per-thread sums, the
//                              integrator's copies and the allocator's slack
//   state_hash                 FNV-1a of every level of every quantity at the end: equal hashes
//                              mean bitwise equal runs (to check that a change kept the results)
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "dam_break_scene.hpp"

namespace {

/// A field of /proc/self/status in kB ("VmRSS", "VmHWM").
long statusKiB(const char* field) {
    std::ifstream in("/proc/self/status");
    std::string line;
    const std::string key = std::string(field) + ":";
    while (std::getline(in, line))
        if (line.rfind(key, 0) == 0) return std::stol(line.substr(key.size()));
    return -1;
}

double loadAverage() {
    std::ifstream in("/proc/loadavg");
    double l = -1;
    in >> l;
    return l;
}

/// CPU seconds of the process (all threads, user + system).
double cpuSeconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

/// FNV-1a over the bytes of every level of every quantity, in quantity order.
template <int Dim>
std::uint64_t stateHash(const num::sph::Storage<Dim>& storage) {
    std::uint64_t h = 1469598103934665603ull;
    storage.forEach([&](num::sph::QuantityId, const num::sph::Quantity<Dim>& q) {
        q.visit([&](const auto& b) {
            for (int k = 0; k < q.levels(); ++k) {
                const auto& v = b.level(k);
                const auto* bytes = reinterpret_cast<const unsigned char*>(v.data());
                for (std::size_t i = 0; i < v.size() * sizeof(v[0]); ++i)
                    h = (h ^ bytes[i]) * 1099511628211ull;
            }
        });
    });
    return h;
}

/// Bytes allocated for every level of every quantity.
template <int Dim>
double storageBytes(const num::sph::Storage<Dim>& storage) {
    double bytes = 0;
    storage.forEach([&](num::sph::QuantityId, const num::sph::Quantity<Dim>& q) {
        q.visit([&](const auto& b) {
            for (int k = 0; k < q.levels(); ++k)
                bytes += double(b.level(k).capacity() * sizeof(b.level(k)[0]));
        });
    });
    return bytes;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct Options {
    int dim = 2;
    double dx = 0.01, particles = 0;
    int threads = 1, steps = 20, warmup = 5, repeats = 5;
    bool heat = false;
    std::string evaluation = "asymmetric";
    std::string backend = "omp";
};

template <int Dim>
int runCase(const Options& o) {
    const long rssBefore = statusKiB("VmRSS");
    bench::SceneOptions so;
    so.dx = o.particles > 0
                ? (Dim == 2 ? bench::spacingFor2D(o.particles) : std::cbrt(1.6 / o.particles))
                : o.dx;
    so.heat = o.heat, so.threads = o.threads, so.evaluation = o.evaluation;
    so.backend = o.backend;
    auto scene = bench::makeDamBreak<Dim>(so);
    const double fluid = scene->fluidParticles(), all = scene->storage.size();
    // Resets the high-water mark (Linux >= 4.0): the peak below is that of the time loop,
    // without the transient arrays of the particle generation.
    const long setupPeak = statusKiB("VmHWM");
    { std::ofstream("/proc/self/clear_refs") << "5"; }
    scene->run->prime();
    for (int s = 0; s < o.warmup; ++s) scene->run->step();

    std::vector<double> rate, perAny, neighbours, cpu;
    for (int r = 0; r < o.repeats; ++r) {
        const double c0 = cpuSeconds();
        const auto t0 = std::chrono::steady_clock::now();
        for (int s = 0; s < o.steps; ++s) scene->run->step();
        const double sec =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        rate.push_back(fluid * o.steps / sec);
        cpu.push_back(1e9 * (cpuSeconds() - c0) / (fluid * o.steps));
        perAny.push_back(1e9 * sec / (all * o.steps));
        neighbours.push_back(scene->solver->meanNeighbours());
        std::printf("run dim=%d repeat=%d seconds=%.4f particle_steps_per_second=%.4e\n", Dim, r,
                    sec, rate.back());
    }
    const long hwm = statusKiB("VmHWM");
    const double bytes = 1024.0 * double(hwm - rssBefore) / all;
    const double setupBytes = 1024.0 * double(std::max(setupPeak, hwm) - rssBefore) / all;
    const double mrate = median(rate);
    std::printf(
        "result dim=%d dx=%.6g backend=%s threads=%d heat=%d evaluation=%s fluid_particles=%.0f "
        "particles=%.0f steps=%d repeats=%d particle_steps_per_second=%.4e "
        "ns_per_particle_step=%.2f ns_per_any_particle_step=%.2f neighbours=%.2f "
        "cpu_ns_per_particle_step=%.2f bytes_per_particle=%.0f setup_bytes_per_particle=%.0f "
        "storage_bytes_per_particle=%.0f load=%.2f sim_time=%.4g state_hash=%016llx\n",
        Dim, so.dx, o.backend.c_str(), o.threads, int(o.heat), o.evaluation.c_str(), fluid, all,
        o.steps, o.repeats, mrate, 1e9 / mrate, median(perAny), median(neighbours), median(cpu),
        bytes, setupBytes, storageBytes(scene->storage) / all, loadAverage(), scene->run->time(),
        static_cast<unsigned long long>(stateHash(scene->storage)));
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    for (int a = 1; a + 1 < argc; a += 2) {
        const std::string k = argv[a], v = argv[a + 1];
        if (k == "--dim")
            o.dim = std::stoi(v);
        else if (k == "--dx")
            o.dx = std::stod(v);
        else if (k == "--particles")
            o.particles = std::stod(v);
        else if (k == "--threads")
            o.threads = std::stoi(v);
        else if (k == "--heat")
            o.heat = std::stoi(v) != 0;
        else if (k == "--steps")
            o.steps = std::stoi(v);
        else if (k == "--warmup")
            o.warmup = std::stoi(v);
        else if (k == "--repeats")
            o.repeats = std::stoi(v);
        else if (k == "--evaluation")
            o.evaluation = v;
        else if (k == "--backend")
            o.backend = v;
        else {
            std::fprintf(stderr, "unknown option %s\n", k.c_str());
            return 2;
        }
    }
    try {
        return o.dim == 3 ? runCase<3>(o) : runCase<2>(o);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
}
