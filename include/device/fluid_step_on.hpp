// IDeviceFluid over the device step on one execution: HostExecution (tests, in
// device/fluid_run.hpp) or CudaExecution (src/cuda/device_run.cu); one class for both.
#pragma once

#include <cstddef>
#include <utility>

#include "device/fluid_state.hpp"
#include "device/fluid_step.hpp"

namespace num::device {

/// The device step on the execution Exec; particles are copied back after its work is done.
template <int Dim, class Exec>
class FluidStepOn final : public IDeviceFluid<Dim> {
  public:
    explicit FluidStepOn(FluidStepConfig<Dim> config) : step_(std::move(config), exec_) {}
    void upload(const ParticleArrays<Dim>& p) override { step_.upload(p); }
    void download(ParticleArrays<Dim>& p) override {
        exec_.synchronize();
        step_.download(p);
    }
    void evaluate(Float t) override { step_.evaluate(t); }
    StepMaxima maxima() override { return step_.maxima(); }
    HeatPowers heatPowers() override { return step_.heatPowers(); }
    sph::FluidExtent<Dim> fluidExtent() override { return step_.fluidExtent(); }
    void advance(Float t, Float dt) override { step_.advance(t, dt); }
    void postStep(Float dt) override { step_.postStep(dt); }
    void setBodies(const DeviceBodies<Dim>& b) override { step_.setBodies(b); }
    void bodyLoads(BodyLoads<Dim>& loads) override {
        exec_.synchronize();
        step_.bodyLoads(loads);
    }
    std::size_t size() const override { return step_.size(); }
    std::size_t bytes() const override { return step_.bytes(); }
    const char* execution() const override { return step_.execution(); }

  private:
    Exec exec_;
    DeviceFluidStep<Dim, Exec> step_;
};

}  // namespace num::device
