// The OpenMP backend: the only file of the library that names a threading API.
#include <omp.h>

#include <algorithm>
#include <exception>
#include <mutex>

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

}  // namespace num::sph
