// The CUDA execution of the device step (compiled by nvcc only; the interface of
// HostExecution in device/execution.hpp): buffers by cudaMalloc, forEach a kernel launch of
// the same functor the host runs in a loop, reductions by CUB's DeviceReduce and the cell sort
// by CUB's DeviceRadixSort::SortPairs (stable, so the order is the host's std::stable_sort).
// Every call is on the default stream, in order; errors become DeviceError.
//
// Debug mode (NUMERICS_CUDA_DEBUG=1 in the environment, read when the execution is made): every
// kernel launch and CUB call is followed by cudaGetLastError and cudaDeviceSynchronize, so that a
// failing kernel (a bad address, a launch failure) throws a DeviceError naming it (the functor's
// type) and the CUDA error, instead of a later call reporting it. It changes no result, only
// when the host waits; without it nothing is synchronised beyond what the copies do.
#pragma once

#include <cuda_runtime.h>
#include <cxxabi.h>

#include <cstdlib>
#include <cub/device/device_radix_sort.cuh>
#include <cub/device/device_reduce.cuh>
#include <string>
#include <typeinfo>

#include "device/execution.hpp"

namespace num::device {

inline void check(cudaError_t e, const char* what) {
    if (e != cudaSuccess)
        throw DeviceError(std::string("CUDA: ") + what + ": " + cudaGetErrorString(e));
}

/// NUMERICS_CUDA_DEBUG=1 (or any value but "" and "0"): the debug mode above.
inline bool cudaDebugMode() {
    const char* e = std::getenv("NUMERICS_CUDA_DEBUG");
    return e && *e && std::string(e) != "0";
}

/// A kernel's name for messages: the functor's type, demangled.
template <class F>
std::string kernelName() {
    int status = 0;
    char* name = abi::__cxa_demangle(typeid(F).name(), nullptr, nullptr, &status);
    std::string s = status == 0 && name ? name : typeid(F).name();
    std::free(name);
    return s;
}

template <class F>
__global__ void forEachKernel(Index n, F f) {
    const Index i = Index(blockIdx.x) * Index(blockDim.x) + Index(threadIdx.x);
    if (i < n) f(i);
}

class CudaExecution {
  public:
    static constexpr bool onDevice = true;
    static const char* name() { return "cuda"; }

    CudaExecution() : debug_(cudaDebugMode()) {
        check(cudaMalloc(&result_, sizeof(double)), "cudaMalloc");
    }
    CudaExecution(const CudaExecution&) = delete;
    CudaExecution& operator=(const CudaExecution&) = delete;
    ~CudaExecution() {
        cudaFree(temp_);
        cudaFree(result_);
    }

    template <class T>
    T* allocate(std::size_t n) {
        void* p = nullptr;
        if (n) check(cudaMalloc(&p, n * sizeof(T)), "cudaMalloc (out of device memory?)");
        return static_cast<T*>(p);
    }
    void release(void* p) { cudaFree(p); }
    template <class T>
    void upload(T* device, const T* host, std::size_t n) {
        if (n) check(cudaMemcpy(device, host, n * sizeof(T), cudaMemcpyHostToDevice), "upload");
    }
    template <class T>
    void download(T* host, const T* device, std::size_t n) {
        if (n) check(cudaMemcpy(host, device, n * sizeof(T), cudaMemcpyDeviceToHost), "download");
    }
    template <class T>
    void copy(T* to, const T* from, std::size_t n) {
        if (n) check(cudaMemcpy(to, from, n * sizeof(T), cudaMemcpyDeviceToDevice), "copy");
    }

    template <class F>
    void forEach(Index n, const F& f) {
        if (n == 0) return;
        constexpr unsigned threads = 256;
        forEachKernel<<<(n + threads - 1) / threads, threads>>>(n, f);
        if (debug_) {
            completed(
                ("kernel " + kernelName<F>() + " (" + std::to_string(n) + " threads)").c_str());
            return;
        }
        check(cudaGetLastError(), "kernel launch");
    }

    double maxOf(const double* v, Index n) {
        if (n == 0) return -std::numeric_limits<double>::infinity();
        std::size_t bytes = 0;
        check(cub::DeviceReduce::Max(nullptr, bytes, v, result_, int(n)), "DeviceReduce::Max");
        check(cub::DeviceReduce::Max(temp(bytes), bytes, v, result_, int(n)), "DeviceReduce::Max");
        if (debug_) completed("cub::DeviceReduce::Max");
        return fetchResult();
    }
    /// Run to run deterministic on one GPU (CUB's reduction tree is fixed by n and the device).
    double sumOf(const double* v, Index n) {
        if (n == 0) return 0;
        std::size_t bytes = 0;
        check(cub::DeviceReduce::Sum(nullptr, bytes, v, result_, int(n)), "DeviceReduce::Sum");
        check(cub::DeviceReduce::Sum(temp(bytes), bytes, v, result_, int(n)), "DeviceReduce::Sum");
        if (debug_) completed("cub::DeviceReduce::Sum");
        return fetchResult();
    }
    double minOf(const double* v, Index n) {
        if (n == 0) return std::numeric_limits<double>::infinity();
        std::size_t bytes = 0;
        check(cub::DeviceReduce::Min(nullptr, bytes, v, result_, int(n)), "DeviceReduce::Min");
        check(cub::DeviceReduce::Min(temp(bytes), bytes, v, result_, int(n)), "DeviceReduce::Min");
        if (debug_) completed("cub::DeviceReduce::Min");
        return fetchResult();
    }

    void sortPairs(const SortKey* keysIn, SortKey* keysOut, const Index* valuesIn, Index* valuesOut,
                   Index n, int keyBits) {
        std::size_t bytes = 0;
        check(cub::DeviceRadixSort::SortPairs(nullptr, bytes, keysIn, keysOut, valuesIn, valuesOut,
                                              int(n), 0, keyBits),
              "DeviceRadixSort::SortPairs");
        check(cub::DeviceRadixSort::SortPairs(temp(bytes), bytes, keysIn, keysOut, valuesIn,
                                              valuesOut, int(n), 0, keyBits),
              "DeviceRadixSort::SortPairs");
        if (debug_) completed("cub::DeviceRadixSort::SortPairs");
    }

    void synchronize() { check(cudaDeviceSynchronize(), "kernel"); }

  private:
    /// Debug mode: the launch of `what` and its run to completion, or a DeviceError naming it.
    void completed(const char* what) {
        const cudaError_t launch = cudaGetLastError();
        if (launch != cudaSuccess)
            throw DeviceError(std::string("CUDA: launch of ") + what +
                              " failed: " + cudaGetErrorString(launch));
        const cudaError_t run = cudaDeviceSynchronize();
        if (run != cudaSuccess)
            throw DeviceError(std::string("CUDA: ") + what + " failed: " + cudaGetErrorString(run));
    }

    /// CUB's temporary storage, grown as needed and kept.
    void* temp(std::size_t bytes) {
        if (bytes > tempBytes_) {
            cudaFree(temp_);
            temp_ = nullptr, tempBytes_ = 0;
            check(cudaMalloc(&temp_, bytes), "cudaMalloc (CUB temporary storage)");
            tempBytes_ = bytes;
        }
        return temp_;
    }
    double fetchResult() {
        double r = 0;
        check(cudaMemcpy(&r, result_, sizeof(double), cudaMemcpyDeviceToHost), "reduction");
        return r;
    }

    bool debug_ = false;
    void* temp_ = nullptr;
    std::size_t tempBytes_ = 0;
    double* result_ = nullptr;
};

}  // namespace num::device
