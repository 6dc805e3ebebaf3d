// The CUDA back end's entry points (defined in src/cuda/, built when a CUDA compiler is found:
// NUMERICS_HAVE_CUDA, in the build's numerics_config.hpp). A build without it has none of these
// definitions: callers test cudaBuilt() first.
#pragma once

#include <memory>
#include <string>

#include "device/fluid_state.hpp"
#include "numerics_config.hpp"

namespace num::device {

/// Whether this build has the CUDA back end.
constexpr bool cudaBuilt() {
#ifdef NUMERICS_HAVE_CUDA
    return true;
#else
    return false;
#endif
}

#ifdef NUMERICS_HAVE_CUDA
/// "" when a CUDA GPU can run the device step here; else why not, in one sentence.
std::string cudaUnavailable();
/// The GPU the device step runs on, e.g. "NVIDIA H100 80GB HBM3 (compute capability 9.0)".
std::string cudaDeviceName();
/// The device step on the CUDA execution.
template <int Dim>
std::unique_ptr<IDeviceFluid<Dim>> makeCudaFluidStep(const FluidStepConfig<Dim>& config);
#endif

}  // namespace num::device
