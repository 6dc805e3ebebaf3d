// The CUDA back end: the device step of the fluid on the CUDA execution, Dim 2 and 3 (the
// functors of include/device/fluid_step.hpp launched as kernels).
#include <string>

#include "device/backend.hpp"
#include "device/cuda_execution.cuh"
#include "device/fluid_step.hpp"

namespace num::device {

std::string cudaUnavailable() {
    int count = 0;
    const cudaError_t e = cudaGetDeviceCount(&count);
    if (e != cudaSuccess) return std::string("no usable CUDA GPU (") + cudaGetErrorString(e) + ")";
    if (count == 0) return "no CUDA GPU found";
    return "";
}

std::string cudaDeviceName() {
    int device = 0;
    cudaDeviceProp p{};
    if (cudaGetDevice(&device) != cudaSuccess || cudaGetDeviceProperties(&p, device) != cudaSuccess)
        return "unknown CUDA GPU";
    return std::string(p.name) + " (compute capability " + std::to_string(p.major) + "." +
           std::to_string(p.minor) + ")";
}

namespace {
template <int Dim>
class CudaFluidStep final : public IDeviceFluid<Dim> {
  public:
    explicit CudaFluidStep(const FluidStepConfig<Dim>& config) : step_(config, exec_) {}
    void upload(const ParticleArrays<Dim>& p) override { step_.upload(p); }
    void download(ParticleArrays<Dim>& p) override {
        exec_.synchronize();
        step_.download(p);
    }
    void evaluate(Float t) override { step_.evaluate(t); }
    StepMaxima maxima() override { return step_.maxima(); }
    void advance(Float t, Float dt) override { step_.advance(t, dt); }
    void postStep(Float dt) override { step_.postStep(dt); }
    std::size_t size() const override { return step_.size(); }
    std::size_t bytes() const override { return step_.bytes(); }
    const char* execution() const override { return step_.execution(); }

  private:
    CudaExecution exec_;
    DeviceFluidStep<Dim, CudaExecution> step_;
};
}  // namespace

template <int Dim>
std::unique_ptr<IDeviceFluid<Dim>> makeCudaFluidStep(const FluidStepConfig<Dim>& config) {
    return std::make_unique<CudaFluidStep<Dim>>(config);
}

template std::unique_ptr<IDeviceFluid<2>> makeCudaFluidStep<2>(const FluidStepConfig<2>&);
template std::unique_ptr<IDeviceFluid<3>> makeCudaFluidStep<3>(const FluidStepConfig<3>&);

}  // namespace num::device
