// The CUDA back end in the apps (internal to numerics_io): which backend a run uses, what a
// scene must leave out to run on it (refused before anything is allocated, with the scene key),
// and the device run itself. A build without CUDA refuses --backend cuda here.
#pragma once

#include <cstdlib>
#include <memory>
#include <string>

#include "device/backend.hpp"
#include "device/fluid_run.hpp"
#include "io/errors.hpp"
#include "io/scene_setup.hpp"
#include "io/simulation.hpp"

namespace num::io {

/// For tests: NUMERICS_TEST_DEVICE_EXECUTION=host runs the cuda backend's device step on the
/// host execution (the same functors, in loops), so that the apps' use of the device step is
/// tested on machines without a GPU or a CUDA build.
inline bool deviceStepOnHost() {
    const char* e = std::getenv("NUMERICS_TEST_DEVICE_EXECUTION");
    return e && std::string(e) == "host";
}

/// Whether the run uses the CUDA back end: --backend when given, else numerics.backend.
template <int Dim>
bool runsOnCuda(const Scene<Dim>& scene, const RunOptions& opt) {
    return opt.backendGiven ? opt.backend == "cuda" : scene.backend == "cuda";
}

/// Refuses what the CUDA back end does not run (yet), naming the scene key; then a build
/// without the back end or a machine without a GPU (exit code 12).
template <int Dim>
void checkCudaRun(const Scene<Dim>& scene, const SceneSetup<Dim>& setup, const RunOptions& opt,
                  bool plugins, int processes) {
    const std::string chosen =
        opt.backendGiven ? "--backend cuda" : scene.file + ": numerics.backend \"cuda\"";
    if (processes > 1)
        throw AppError(ExitCode::USAGE, chosen +
                                            " runs on one process with one GPU: run it "
                                            "without mpirun (several GPUs: not yet)");
    const auto refuse = [&](const std::string& key, const std::string& what) {
        throw AppError(ExitCode::SCENE, chosen + " does not support " + key + " yet: " + what +
                                            " runs on the CPU back end only (--backend cpu)");
    };
    if (plugins) refuse("plugins", "a plugin's equation terms");
    if (!scene.emitters.empty()) refuse("emitters", "a scene with emitters");
    if (!scene.walls.empty()) refuse("walls", "a wall inside the domain");
    if (const std::string key = firstGeneralShapeKey(scene); !key.empty())
        refuse(key, "a shape other than a box or a ball");
    for (int k = 0; k < Dim; ++k)
        for (int hi = 0; hi < 2; ++hi)
            if (scene.sides[k][hi]->letsFluidOut())
                refuse(std::string("boundaries.") + sideName(k, hi) + ".type \"" +
                           scene.sides[k][hi]->type() + "\"",
                       "an open side");
    if (scene.integrator != "leapfrog")
        refuse("time.integrator \"" + scene.integrator + "\"", "this integrator");
    if (sph::evaluationFromName(scene.evaluation) == sph::Evaluation::SYMMETRIC)
        refuse("particles.evaluation \"symmetric\"", "the symmetric evaluation");
    if (setup.model.density == sph::DensityMode::SUMMATION)
        refuse("physics.density \"" + scene.physics.density + "\" (density by summation here)",
               "density by summation");
    if (const std::string what = device::unsupported(setup.model, setup.geometry, setup.settings);
        !what.empty())
        refuse("this scene", what);
    if (deviceStepOnHost()) return;
    if constexpr (!device::cudaBuilt()) {
        throw AppError(ExitCode::NO_GPU,
                       chosen +
                           ": this build has no CUDA back end (no CUDA compiler was found "
                           "when it was built: install the CUDA toolkit, nvcc on PATH or in "
                           "/usr/local/cuda/bin, and rebuild)");
    } else {
#ifdef NUMERICS_HAVE_CUDA
        if (const std::string why = device::cudaUnavailable(); !why.empty())
            throw AppError(ExitCode::NO_GPU, chosen + ": " + why +
                                                 " (the CUDA back end needs an NVIDIA GPU; "
                                                 "--backend cpu runs on the CPU)");
#endif
    }
}

/// The device run of a scene on the CUDA back end (after checkCudaRun).
template <int Dim>
std::unique_ptr<device::DeviceRun<Dim>> makeCudaRun(const SceneSetup<Dim>& setup, double t0) {
    const device::FluidStepConfig<Dim> config =
        device::makeFluidStepConfig(setup.model, setup.geometry, setup.settings);
    if (deviceStepOnHost())
        return std::make_unique<device::DeviceRun<Dim>>(
            std::make_unique<device::HostFluidStep<Dim>>(config), config, t0);
#ifdef NUMERICS_HAVE_CUDA
    try {
        return std::make_unique<device::DeviceRun<Dim>>(device::makeCudaFluidStep<Dim>(config),
                                                        config, t0);
    } catch (const device::DeviceError& e) {
        throw AppError(ExitCode::NO_GPU, e.what());
    }
#else
    (void)config, (void)t0;
    throw AppError(ExitCode::NO_GPU, "this build has no CUDA back end");
#endif
}

/// The GPU for summary.json.
inline std::string cudaDeviceText() {
    if (deviceStepOnHost()) return "host execution (NUMERICS_TEST_DEVICE_EXECUTION=host)";
#ifdef NUMERICS_HAVE_CUDA
    return device::cudaDeviceName();
#else
    return "";
#endif
}

}  // namespace num::io
