// IScheduler: how loops run. Physics code calls parallelFor and never names a threading API;
// the backend (sequential, or OpenMP threads) is chosen once, where the scheduler is made.
#pragma once

#include <algorithm>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "sph/types.hpp"

namespace num::sph {

/// The operating system refused a thread (a process or memory limit of a batch system).
struct ThreadStartError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class IScheduler {
  public:
    virtual ~IScheduler() = default;
    /// Number of threads the scheduler runs tasks on.
    virtual Size threadCount() const = 0;
    /// Calls task(begin, end) on chunks of [0, n) of at most `granularity` items; chunks may run
    /// concurrently, each exactly once.
    virtual void parallelFor(Size n, Size granularity,
                             const std::function<void(Size begin, Size end)>& task) = 0;
};

/// A reduction over [0, n) in chunks of `granularity` items: chunk(begin, end, partial) fills one
/// partial per chunk (each starts as `init`; chunks may run concurrently), then
/// combine(result, partial) folds the partials in the order of the chunks. The result is the
/// same whatever the number of threads, bitwise, as the chunks are fixed by n and granularity.
template <class T, class Chunk, class Combine>
T reduceChunks(IScheduler& scheduler, Size n, Size granularity, const T& init, Chunk&& chunk,
               Combine&& combine) {
    if (granularity == 0) granularity = 1;
    std::vector<T> partial((std::uint64_t(n) + granularity - 1) / granularity, init);
    scheduler.parallelFor(Size(partial.size()), 1, [&](Size c0, Size c1) {
        for (Size c = c0; c < c1; ++c)
            chunk(c * granularity,
                  Size(std::min<std::uint64_t>(n, std::uint64_t(c + 1) * granularity)), partial[c]);
    });
    T result = init;
    for (const T& p : partial) combine(result, p);
    return result;
}

/// The largest of 0 and value(i) over [0, n), by reduceChunks; a NaN value is passed over, as
/// std::max passes it over in a serial scan.
template <class Value>
Float largestOf(IScheduler& scheduler, Size n, Value&& value) {
    return reduceChunks(
        scheduler, n, 8192, Float(0),
        [&](Size b, Size e, Float& m) {
            for (Size i = b; i < e; ++i) m = std::max(m, Float(value(i)));
        },
        [](Float& m, Float partial) { m = std::max(m, partial); });
}

/// Runs every chunk in order on the calling thread.
class SequentialScheduler final : public IScheduler {
  public:
    Size threadCount() const override { return 1; }
    void parallelFor(Size n, Size granularity,
                     const std::function<void(Size, Size)>& task) override {
        if (granularity == 0) granularity = 1;
        for (Size b = 0; b < n; b += granularity) task(b, std::min(n, b + granularity));
    }
};

/// Runs chunks on a team of OpenMP threads (dynamic schedule).
class ParallelScheduler final : public IScheduler {
  public:
    explicit ParallelScheduler(Size threads);
    Size threadCount() const override { return threads_; }
    void parallelFor(Size n, Size granularity,
                     const std::function<void(Size, Size)>& task) override;

  private:
    Size threads_;
};

/// Runs chunks on a pool of persistent std::threads; the calling thread works too. Chunks are
/// claimed one at a time from a shared counter, so a thread the operating system pauses (a busy
/// shared machine) delays only the chunk it holds, and idle threads sleep instead of spinning.
class ThreadPoolScheduler final : public IScheduler {
  public:
    explicit ThreadPoolScheduler(Size threads);
    ~ThreadPoolScheduler() override;
    ThreadPoolScheduler(const ThreadPoolScheduler&) = delete;
    ThreadPoolScheduler& operator=(const ThreadPoolScheduler&) = delete;
    Size threadCount() const override { return threads_; }
    void parallelFor(Size n, Size granularity,
                     const std::function<void(Size, Size)>& task) override;

  private:
    struct Pool;
    Size threads_;
    std::unique_ptr<Pool> pool_;
};

/// The scheduler for a backend name: "seq" (sequential) or "omp" (also "openmp", "parallel").
inline std::unique_ptr<IScheduler> makeScheduler(const std::string& backend, Size threads) {
    if (backend == "seq" || backend == "sequential") return std::make_unique<SequentialScheduler>();
    if (backend == "omp" || backend == "openmp" || backend == "parallel")
        return std::make_unique<ParallelScheduler>(threads);
    if (backend == "threads") return std::make_unique<ThreadPoolScheduler>(threads);
    throw std::invalid_argument("unknown backend '" + backend + "' (expected seq or omp)");
}

}  // namespace num::sph
