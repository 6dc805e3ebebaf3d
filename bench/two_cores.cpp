// Whether two threads slow each other down on this machine, apart from any SPH code: the time
// of a loop run by one thread alone and by each of two threads at once, for a loop that only
// computes (registers) and one that streams a 256 MiB array per thread (memory bandwidth).
//
//   bench_two_cores [--rounds R]     (default 5; alone and together alternate each round)
//
// Prints per loop the medians and "together / alone": about 1 means the two cores do not share
// that resource; 2 would mean one core's worth shared by both (e.g. two hardware threads of one
// core). The SPH loops' two-thread speed-up (docs/performance.md) can be no better than this.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace {

volatile double sink = 0;  // keeps the loops' results alive

void compute() {
    double x = 1, y = 2, z = 3, w = 4;
    for (long i = 0; i < 400'000'000L; ++i) {  // four independent multiply-add chains
        x = x * 1.0000001 + 1e-9, y = y * 0.9999999 + 1e-9;
        z = z * 1.0000001 - 1e-9, w = w * 0.9999999 - 1e-9;
    }
    sink = sink + x + y + z + w;
}

void stream(const std::vector<double>& v) {
    double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
    for (int r = 0; r < 8; ++r)
        for (std::size_t i = 0; i + 3 < v.size(); i += 4)
            s0 += v[i], s1 += v[i + 1], s2 += v[i + 2], s3 += v[i + 3];
    sink = sink + s0 + s1 + s2 + s3;
}

/// Seconds for `work` on one thread, or the slower of two threads running it at once.
template <class F>
double timed(int threads, F work) {
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) pool.emplace_back(work, t);
    for (auto& t : pool) t.join();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

}  // namespace

int main(int argc, char** argv) {
    int rounds = 5;
    for (int a = 1; a + 1 < argc; a += 2)
        if (std::string(argv[a]) == "--rounds") rounds = std::max(1, std::atoi(argv[a + 1]));
    std::vector<std::vector<double>> arrays(2, std::vector<double>(std::size_t(1) << 25, 1.0));
    auto computeWork = [](int) { compute(); };
    auto streamWork = [&](int t) { stream(arrays[t]); };
    for (const char* name : {"compute", "stream"}) {
        std::vector<double> alone, together;
        for (int r = 0; r < rounds; ++r) {
            const bool c = std::strcmp(name, "compute") == 0;
            alone.push_back(c ? timed(1, computeWork) : timed(1, streamWork));
            together.push_back(c ? timed(2, computeWork) : timed(2, streamWork));
        }
        std::printf("%-8s alone %.3f s  together %.3f s  together / alone %.2f  (%d rounds)\n",
                    name, median(alone), median(together), median(together) / median(alone),
                    rounds);
    }
    return 0;
}
