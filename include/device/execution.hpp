// The portable execution layer of the CUDA back end: where the device step's per-particle
// functors run. Two executions with one interface:
//   HostExecution  (this file, plain C++): buffers in host memory, forEach a plain loop, the
//                  reductions a loop, the sort std::stable_sort of (key, index) pairs;
//   CudaExecution  (device/cuda_execution.cuh, compiled by nvcc only): cudaMalloc'ed buffers,
//                  forEach a kernel launch, CUB's DeviceReduce and DeviceRadixSort::SortPairs.
// A functor passed to forEach has `NUMERICS_HD void operator()(Index i) const` and holds plain
// pointers into buffers of its execution: the same code runs as a CUDA kernel and, on the host,
// in the loop, so the CPU tests run what the GPU runs. The radix sort is stable, so both
// executions sort into the same order.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <new>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "sph/host_device.hpp"

namespace num::device {

/// A particle's index on the device (up to 4e9 particles).
using Index = std::uint32_t;
/// A particle's cell.
using CellKey = std::uint32_t;
/// What the cell sort sorts by: the cell in the upper 32 bits, a tie-break in the lower.
using SortKey = std::uint64_t;

/// A failure of the device (allocation, launch, a call of the CUDA runtime).
struct DeviceError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class HostExecution {
  public:
    static constexpr bool onDevice = false;
    static const char* name() { return "host"; }

    template <class T>
    T* allocate(std::size_t n) {
        return n ? static_cast<T*>(::operator new(n * sizeof(T))) : nullptr;
    }
    void release(void* p) { ::operator delete(p); }
    template <class T>
    void upload(T* device, const T* host, std::size_t n) {
        std::copy_n(host, n, device);
    }
    template <class T>
    void download(T* host, const T* device, std::size_t n) {
        std::copy_n(device, n, host);
    }
    template <class T>
    void copy(T* to, const T* from, std::size_t n) {
        std::copy_n(from, n, to);
    }

    /// f(i) for i = 0 .. n-1.
    template <class F>
    void forEach(Index n, const F& f) {
        for (Index i = 0; i < n; ++i) f(i);
    }

    /// The largest of v[0 .. n-1]; -infinity for n = 0.
    double maxOf(const double* v, Index n) {
        double m = -std::numeric_limits<double>::infinity();
        for (Index i = 0; i < n; ++i) m = std::max(m, v[i]);
        return m;
    }
    /// The sum of v[0 .. n-1] in index order; 0 for n = 0.
    double sumOf(const double* v, Index n) {
        double s = 0;
        for (Index i = 0; i < n; ++i) s += v[i];
        return s;
    }
    /// The smallest of v[0 .. n-1]; +infinity for n = 0.
    double minOf(const double* v, Index n) {
        double m = std::numeric_limits<double>::infinity();
        for (Index i = 0; i < n; ++i) m = std::min(m, v[i]);
        return m;
    }

    /// Sorts the pairs (keysIn[k], valuesIn[k]) by key, stably, into keysOut / valuesOut.
    /// keyBits: the keys are below 2^keyBits.
    void sortPairs(const SortKey* keysIn, SortKey* keysOut, const Index* valuesIn, Index* valuesOut,
                   Index n, int /*keyBits*/) {
        pairs_.resize(n);
        for (Index k = 0; k < n; ++k) pairs_[k] = {keysIn[k], valuesIn[k]};
        std::stable_sort(pairs_.begin(), pairs_.end(),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
        for (Index k = 0; k < n; ++k) keysOut[k] = pairs_[k].first, valuesOut[k] = pairs_[k].second;
    }

    void synchronize() {}

  private:
    std::vector<std::pair<SortKey, Index>> pairs_;
};

/// An array in the memory of an execution (RAII): allocated by the execution, never copied.
template <class T, class Exec>
class Buffer {
  public:
    explicit Buffer(Exec& exec) : exec_(&exec) {}
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;
    Buffer(Buffer&& o) noexcept
        : exec_(o.exec_), data_(o.data_), size_(o.size_), capacity_(o.capacity_) {
        o.data_ = nullptr, o.size_ = o.capacity_ = 0;
    }
    ~Buffer() {
        if (data_) exec_->release(data_);
    }

    /// n elements; the contents are undefined after a change of size. The memory only grows
    /// (a cell grid whose size changes every step allocates nothing once it reached its most).
    void resize(std::size_t n) {
        if (n > capacity_) {
            if (data_) exec_->release(data_);
            data_ = nullptr, size_ = capacity_ = 0;
            data_ = exec_->template allocate<T>(n);
            capacity_ = n;
        }
        size_ = n;
    }
    void upload(const std::vector<T>& host) {
        resize(host.size());
        exec_->upload(data_, host.data(), host.size());
    }
    void download(std::vector<T>& host) const {
        host.resize(size_);
        exec_->download(host.data(), data_, size_);
    }
    void swap(Buffer& o) noexcept {
        std::swap(exec_, o.exec_), std::swap(data_, o.data_), std::swap(size_, o.size_);
        std::swap(capacity_, o.capacity_);
    }
    T* data() { return data_; }
    const T* data() const { return data_; }
    std::size_t size() const { return size_; }
    /// Memory held [bytes].
    std::size_t bytes() const { return capacity_ * sizeof(T); }

  private:
    Exec* exec_;
    T* data_ = nullptr;
    std::size_t size_ = 0, capacity_ = 0;
};

}  // namespace num::device
