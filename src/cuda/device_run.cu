// The CUDA back end: the device step instantiated for the CUDA execution (Dim 2 and 3).
#include "device/cuda_execution.cuh"
#include "device/neighbour_grid.hpp"

namespace num::device {

template class NeighbourGrid<2, CudaExecution>;
template class NeighbourGrid<3, CudaExecution>;

}  // namespace num::device
