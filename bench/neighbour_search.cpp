// Micro-benchmarks of the neighbour search, 2D/3D: the cell grid (build by counting sort, query)
// and the Verlet lists built from it (build with a skin of 0.2, query of every particle).
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "spatial/cell_grid.hpp"
#include "spatial/neighbour_list.hpp"

namespace {

/// A jittered lattice of n^Dim particles of spacing dx: like a fluid at rest.
template <int Dim>
std::vector<num::Vec<double, Dim>> lattice(int perAxis, double dx) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> jitter(-0.1 * dx, 0.1 * dx);
    std::vector<num::Vec<double, Dim>> x;
    int total = 1;
    for (int k = 0; k < Dim; ++k) total *= perAxis;
    x.reserve(total);
    for (int id = 0; id < total; ++id) {
        num::Vec<double, Dim> p;
        int rest = id;
        for (int k = 0; k < Dim; ++k) {
            p[k] = (rest % perAxis + 0.5) * dx + jitter(rng);
            rest /= perAxis;
        }
        x.push_back(p);
    }
    return x;
}

template <int Dim>
void buildGrid(benchmark::State& state) {
    const double dx = 0.01, radius = 2 * 1.3 * dx;
    const auto x = lattice<Dim>(int(state.range(0)), dx);
    num::Domain<Dim> domain;
    num::CellGrid<Dim> grid;
    for (auto _ : state) {
        grid.build(x, radius, domain);
        benchmark::DoNotOptimize(grid.sortedOrder().data());
    }
    state.SetItemsProcessed(state.iterations() * x.size());
}

template <int Dim>
void queryAll(benchmark::State& state) {
    const double dx = 0.01, radius = 2 * 1.3 * dx;
    const auto x = lattice<Dim>(int(state.range(0)), dx);
    num::Domain<Dim> domain;
    num::CellGrid<Dim> grid;
    grid.build(x, radius, domain);
    std::size_t pairs = 0;
    for (auto _ : state) {
        pairs = 0;
        for (const auto& p : x)
            grid.forEachNeighbour(p, [&](auto, const auto&, double) { ++pairs; });
        benchmark::DoNotOptimize(pairs);
    }
    state.SetItemsProcessed(state.iterations() * x.size());
    state.counters["neighbours"] = double(pairs) / double(x.size());
}

template <int Dim>
void buildVerlet(benchmark::State& state) {
    const double dx = 0.01, radius = 2 * 1.3 * dx;
    const auto x = lattice<Dim>(int(state.range(0)), dx);
    num::VerletList<Dim> list;
    list.configure(radius, 0.2, num::Domain<Dim>{});
    for (auto _ : state) {
        list.invalidate();
        list.update(x);
        benchmark::DoNotOptimize(list.candidates(0).data());
    }
    state.SetItemsProcessed(state.iterations() * x.size());
}

template <int Dim>
void queryVerlet(benchmark::State& state) {
    const double dx = 0.01, radius = 2 * 1.3 * dx;
    const auto x = lattice<Dim>(int(state.range(0)), dx);
    num::VerletList<Dim> list;
    list.configure(radius, 0.2, num::Domain<Dim>{});
    list.update(x);
    std::size_t pairs = 0;
    for (auto _ : state) {
        pairs = 0;
        for (std::uint32_t i = 0; i < x.size(); ++i)
            list.forEachNeighbourOf(i, [&](auto, const auto&, double) { ++pairs; });
        benchmark::DoNotOptimize(pairs);
    }
    state.SetItemsProcessed(state.iterations() * x.size());
    state.counters["neighbours"] = double(pairs) / double(x.size());
}

}  // namespace

BENCHMARK(buildGrid<2>)->Arg(141)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(queryAll<2>)->Arg(141)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(buildGrid<3>)->Arg(27)->Arg(58)->Unit(benchmark::kMillisecond);
BENCHMARK(queryAll<3>)->Arg(27)->Arg(58)->Unit(benchmark::kMillisecond);
BENCHMARK(buildVerlet<2>)->Arg(141)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(queryVerlet<2>)->Arg(141)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(buildVerlet<3>)->Arg(27)->Arg(58)->Unit(benchmark::kMillisecond);
BENCHMARK(queryVerlet<3>)->Arg(27)->Arg(58)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
