// The parallel backends, the only file of the library that names a threading API: OpenMP
// (ParallelScheduler) and a pool of std::threads (ThreadPoolScheduler).
#include <omp.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "sph/scheduler.hpp"

namespace num::sph {

ParallelScheduler::ParallelScheduler(Size threads) : threads_(std::max<Size>(1, threads)) {}

void ParallelScheduler::parallelFor(Size n, Size granularity,
                                    const std::function<void(Size, Size)>& task) {
    if (granularity == 0) granularity = 1;
    const long chunks = long((n + granularity - 1) / granularity);
    std::exception_ptr error;
    std::mutex errorMutex;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads_)
    for (long c = 0; c < chunks; ++c) {
        try {
            const Size b = Size(c) * granularity;
            task(b, std::min(n, b + granularity));
        } catch (...) {
            std::lock_guard<std::mutex> lock(errorMutex);
            if (!error) error = std::current_exception();
        }
    }
    if (error) std::rethrow_exception(error);
}

namespace {
thread_local bool insidePoolTask = false;
}

struct ThreadPoolScheduler::Pool {
    struct Job {
        const std::function<void(Size, Size)>* task = nullptr;
        Size n = 0, granularity = 1, chunks = 0;
        std::atomic<Size> next{0};
        std::atomic<int> active{0};
        std::exception_ptr error;
        std::mutex errorMutex;

        /// Runs chunks until none is left.
        void work() {
            for (Size c; (c = next.fetch_add(1, std::memory_order_relaxed)) < chunks;) {
                const Size b = c * granularity;
                try {
                    (*task)(b, std::min(n, b + granularity));
                } catch (...) {
                    std::lock_guard<std::mutex> lock(errorMutex);
                    if (!error) error = std::current_exception();
                }
            }
        }
    };

    std::mutex mutex;
    std::condition_variable wake;
    Job* job = nullptr;
    std::uint64_t generation = 0;
    bool stop = false;
    std::vector<std::thread> workers;

    void stopWorkers() {
        {
            std::lock_guard<std::mutex> lock(mutex);
            stop = true;
        }
        wake.notify_all();
        for (auto& w : workers) w.join();
        workers.clear();
    }

    void workerLoop() {
        insidePoolTask = true;
        std::uint64_t seen = 0;
        for (;;) {
            Job* j;
            {
                std::unique_lock<std::mutex> lock(mutex);
                wake.wait(lock, [&] { return stop || (generation != seen && job); });
                if (stop) return;
                seen = generation;
                j = job;
                j->active.fetch_add(1, std::memory_order_acq_rel);  // registered under the lock
            }
            j->work();
            j->active.fetch_sub(1, std::memory_order_acq_rel);
        }
    }
};

ThreadPoolScheduler::ThreadPoolScheduler(Size threads)
    : threads_(std::max<Size>(1, threads)), pool_(std::make_unique<Pool>()) {
    try {
        for (Size t = 1; t < threads_; ++t)
            pool_->workers.emplace_back([p = pool_.get()] { p->workerLoop(); });
    } catch (const std::system_error& e) {
        // The threads started so far end before the error leaves: a joinable std::thread that
        // is destroyed ends the program.
        const std::size_t started = pool_->workers.size();
        pool_->stopWorkers();
        throw ThreadStartError("the system refused thread " + std::to_string(started + 2) + " of " +
                               std::to_string(threads_) + " (" + e.code().message() + ")");
    }
}

ThreadPoolScheduler::~ThreadPoolScheduler() { pool_->stopWorkers(); }

void ThreadPoolScheduler::parallelFor(Size n, Size granularity,
                                      const std::function<void(Size, Size)>& task) {
    if (granularity == 0) granularity = 1;
    Pool::Job job;
    job.task = &task, job.n = n, job.granularity = granularity;
    job.chunks = (n + granularity - 1) / granularity;
    // One chunk, one thread, or a call from inside a task: run here, in order.
    if (job.chunks <= 1 || pool_->workers.empty() || insidePoolTask) {
        job.work();
        if (job.error) std::rethrow_exception(job.error);
        return;
    }
    {
        std::lock_guard<std::mutex> lock(pool_->mutex);
        pool_->job = &job;
        ++pool_->generation;
    }
    pool_->wake.notify_all();
    insidePoolTask = true;
    job.work();
    insidePoolTask = false;
    {
        // No worker registers after this: the job is withdrawn under the lock.
        std::lock_guard<std::mutex> lock(pool_->mutex);
        pool_->job = nullptr;
    }
    // Workers that registered finish their last chunk; spin briefly, then yield.
    for (int spin = 0; job.active.load(std::memory_order_acquire) != 0; ++spin)
        if (spin > 1000) std::this_thread::yield();
    if (job.error) std::rethrow_exception(job.error);
}

}  // namespace num::sph
