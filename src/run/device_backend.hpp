// The CUDA back end in the apps (internal to numerics_app): which backend a run uses, what a
// scene must leave out to run on it (refused before anything is allocated, with the scene key),
// and the device engine. A build without CUDA refuses --backend cuda here.
#pragma once

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "app/errors.hpp"
#include "app/scene_setup.hpp"
#include "app/simulation.hpp"
#include "device/backend.hpp"
#include "device/fluid_run.hpp"
#include "run/engine.hpp"

namespace num::app {

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

/// The scene key of a feature the CUDA back end does not run (yet) and what it is, or {"", ""}.
/// Words for a user; what the device step cannot run is refused by device::unsupported, from the
/// model itself, whether or not it is named here.
template <int Dim>
std::pair<std::string, std::string> keyNotOnCuda(const Scene<Dim>& scene,
                                                 const SceneSetup<Dim>& setup) {
    if (const std::string solid = device::firstSolidNotOnDevice(setup.geometry); !solid.empty())
        return {solid + ".shape", "a mesh shape"};
    if (scene.integrator != "leapfrog")
        return {"time.integrator \"" + scene.integrator + "\"", "this integrator"};
    if (sph::evaluationFromName(scene.evaluation) == sph::Evaluation::SYMMETRIC)
        return {"particles.evaluation \"symmetric\"", "the symmetric evaluation"};
    return {"", ""};
}

/// Refuses what the CUDA back end does not run (yet), naming the scene key or the equation term
/// (a plugin's); then a build without the back end or a machine without a GPU (exit code 12).
template <int Dim>
void checkCudaRun(const Scene<Dim>& scene, const SceneSetup<Dim>& setup, const RunOptions& opt,
                  int processes) {
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
    if (const auto [key, what] = keyNotOnCuda(scene, setup); !key.empty()) refuse(key, what);
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

/// The device engine: the steps on the GPU (or, for tests, on the host execution), the
/// particles copied to the host's storage only when asked (outputs, probes, checkpoints, the
/// end, a front end) and sent up again when the host changed them. It keeps the heat books of
/// walls from the powers each step's last evaluation measured, and counts no neighbours.
template <int Dim>
class DeviceEngine final : public IEngine<Dim> {
  public:
    DeviceEngine(sph::Storage<Dim>& storage, const SceneSetup<Dim>& setup, double t0)
        : storage_(storage), run_(makeCudaRun(setup, t0)) {
        if (setup.model.heat.conduction) books_.emplace();
    }

    const sph::StepClock& clock() const override { return *run_; }
    void prime() override {
        run_->upload(storage_, false);
        run_->prime();
        measureHeat();
        run_->download(storage_);
    }
    void resume(double t, sph::Size steps) override {
        run_->setTime(t, steps);
        run_->upload(storage_, true);
    }
    double allowedStep() override { return run_->timeStepLimits().dt(); }
    double step(double target) override {
        hostCurrent_ = false;
        const double dt = run_->step(target);
        measureHeat();
        if (books_) books_->book(dt);
        return dt;
    }
    void copyToHost() override {
        if (!hostCurrent_) run_->download(storage_);
        hostCurrent_ = true;
    }
    bool hostCurrent() const override { return hostCurrent_; }
    sph::FluidExtent<Dim> fluidExtent() override { return run_->fluid().fluidExtent(); }
    void takeWrittenParticles() override { run_->upload(storage_, false); }
    // The host's rates are those of the current time (the CPU engine steps on with them too).
    void takeNewParticleSet() override { run_->upload(storage_, true); }
    void takeImposedValues() override { run_->upload(storage_, true); }
    void setDecomposition(sph::IDecomposition<Dim>*) override {
        throw std::logic_error("the CUDA back end runs on one process");
    }
    void setAbandonCheck(std::function<bool()>) override {}  // a step on the GPU runs to its end
    sph::WallHeatBooks* wallHeat() override { return books_ ? &*books_ : nullptr; }
    double meanNeighbours() const override { return 0; }
    std::string backend() const override { return "cuda"; }
    void describe(nlohmann::json& summary, std::size_t particles) const override {
        summary["device"] = cudaDeviceText();
        summary["device_bytes"] = run_->fluid().bytes();
        summary["device_bytes_per_particle"] =
            double(run_->fluid().bytes()) / double(std::max<std::size_t>(1, particles));
    }

  private:
    void measureHeat() {
        if (!books_) return;
        const device::HeatPowers powers = run_->fluid().heatPowers();
        books_->measured(powers.fixed, powers.source);
    }

    sph::Storage<Dim>& storage_;
    std::unique_ptr<device::DeviceRun<Dim>> run_;
    std::optional<sph::WallHeatBooks> books_;  // with conduction
    bool hostCurrent_ = true;
};

}  // namespace num::app
