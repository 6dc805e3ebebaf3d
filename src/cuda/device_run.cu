// The CUDA back end: the device step of the fluid on the CUDA execution, Dim 2 and 3 (the
// functors of include/device/fluid_step.hpp launched as kernels).
#include <string>

#include "device/backend.hpp"
#include "device/cuda_execution.cuh"
#include "device/fluid_step_on.hpp"

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

template <int Dim>
std::unique_ptr<IDeviceFluid<Dim>> makeCudaFluidStep(const FluidStepConfig<Dim>& config) {
    return std::make_unique<FluidStepOn<Dim, CudaExecution>>(config);
}

template std::unique_ptr<IDeviceFluid<2>> makeCudaFluidStep<2>(const FluidStepConfig<2>&);
template std::unique_ptr<IDeviceFluid<3>> makeCudaFluidStep<3>(const FluidStepConfig<3>&);

}  // namespace num::device
