// The core's double-precision peak as the engine is compiled (numerics' flags: no fused
// multiply-add, -ffp-contract=off): 32 independent chains (16 leave it latency-bound, 64 spill) of
// a = a * b + c, each a multiply and an add, in scalars and in vectors of 2, 4 and 8 doubles (GCC's
// vector extension; the widths the CPU lacks are emulated and slower). The roofline of the pair
// loops (bench/roofline.py) sets the loops' flop rates against these.
//   bench_core_peak   prints flops_per_second per width (one thread)
#include <benchmark/benchmark.h>

// The scalar chains stay scalar (else the compiler packs the 16 chains into vectors).
#pragma GCC optimize("no-tree-vectorize", "no-tree-slp-vectorize")

namespace {

template <int Lanes>
struct Lanes_ {
    typedef double type __attribute__((vector_size(8 * Lanes)));
};
template <>
struct Lanes_<1> {
    using type = double;
};

template <int Lanes>
void peak(benchmark::State& state) {
    using V = typename Lanes_<Lanes>::type;
    constexpr int chains = 32, rounds = 2048;
    V a[chains];
    for (int k = 0; k < chains; ++k) a[k] = V{} + 1.0 + 1e-3 * k;
    const V b = V{} + 0.999999, c = V{} + 1e-6;
    for (auto _ : state) {
        for (int r = 0; r < rounds; ++r)
            for (int k = 0; k < chains; ++k) a[k] = a[k] * b + c;
        benchmark::DoNotOptimize(a);
    }
    state.counters["flops_per_second"] = benchmark::Counter(
        double(state.iterations()) * rounds * chains * 2 * Lanes, benchmark::Counter::kIsRate);
}

BENCHMARK(peak<1>)->Name("scalar");
BENCHMARK(peak<2>)->Name("vector2");
BENCHMARK(peak<4>)->Name("vector4");
BENCHMARK(peak<8>)->Name("vector8");

}  // namespace

BENCHMARK_MAIN();
