// Micro-benchmarks of the pair loops on the dam-break scene (dam_break_scene.hpp), 2D
// (dx = 0.01: 20,000 fluid + 3,618 wall particles) and 3D (dx = 0.04: 25,000 fluid particles),
// each with 1 and 2 threads (the benchmark argument):
//   search      neighbour search alone: cell grid build + every particle's neighbour list
//   density     evaluation with the continuity equation and delta-SPH (+ search)
//   forces      evaluation with the pressure gradient and artificial viscosity (+ search)
//   heat        evaluation with heat conduction (+ search)
//   all         the full fused evaluation (fluid + heat)
//   step        one leapfrog step of the full scene with heat on
// The loops also count the pairs one evaluation visits (`pairs`).
// Items per second count all particles (fluid and wall) per evaluation or step.
#include <benchmark/benchmark.h>

#include <memory>

#include "dam_break_scene.hpp"

namespace {

using namespace num::sph;

template <int Dim>
double spacing() {
    return Dim == 2 ? 0.01 : 0.04;
}

template <int Dim>
std::unique_ptr<bench::Scene<Dim>> scene(int threads) {
    bench::SceneOptions o;
    o.dx = spacing<Dim>();
    o.heat = true;
    o.threads = threads;
    auto s = bench::makeDamBreak<Dim>(o);
    s->run->prime();
    for (int k = 0; k < 3; ++k) s->run->step();  // a state with pressures and velocities
    return s;
}

enum class Loop { DENSITY, FORCES, HEAT, ALL };

/// The terms of one loop; the equation of state supplies pressure, the fused term fuses.
template <int Dim>
EquationHolder<Dim> termsOf(Loop loop, const bench::Scene<Dim>& s) {
    const EquationOfState eos = s.model.equationOfState();
    EquationHolder<Dim> eq = makeTerm<EquationOfStateTerm<Dim>>(eos);
    eq += makeTerm<PairInputs<Dim>>();
    switch (loop) {
        case Loop::DENSITY:
            eq += makeTerm<ContinuityDensity<Dim>>();
            eq += makeTerm<DeltaSph<Dim>>(s.model.deltaSph, s.model.restDensity, eos.c0,
                                          s.model.bodyForce);
            break;
        case Loop::FORCES:
            eq += makeTerm<PressureGradient<Dim>>();
            eq += makeTerm<ArtificialViscosity<Dim>>(s.model.artificialViscosity, eos.c0);
            break;
        case Loop::HEAT:
            eq += makeTerm<HeatConduction<Dim>>();
            break;
        case Loop::ALL:
            return makeFluidEquations(s.model, s.geometry);
    }
    eq += makeTerm<FuseDerivatives<Dim, ContinuityDensityPart<Dim>, DeltaSphPart<Dim>,
                                   PressureGradientPart<Dim>, ArtificialViscosityPart<Dim>>>();
    return eq;
}

template <int Dim>
void search(benchmark::State& state) {
    auto s = scene<Dim>(int(state.range(0)));
    const auto x = s->storage.template getValue<Vector<Dim>>(QuantityId::POSITION);
    const double radius = s->solver->kernel().supportRadius();
    num::CellGrid<Dim> grid;
    typename num::CellGrid<Dim>::Neighbours found;
    const Size n = Size(x.size());
    std::vector<typename num::CellGrid<Dim>::Neighbours> perThread(s->scheduler->threadCount());
    std::size_t pairs = 0;
    for (auto _ : state) {
        grid.build(x, radius, s->geometry.domain);
        std::vector<std::size_t> counts((n + 1023) / 1024);
        s->scheduler->parallelFor(n, 1024, [&](Size b, Size e) {
            typename num::CellGrid<Dim>::Neighbours local;
            std::size_t c = 0;
            for (Size i = b; i < e; ++i)
                c += grid.collect(
                    i, [i](Size j) { return j != i; }, local);
            counts[b / 1024] = c;
        });
        pairs = 0;
        for (auto c : counts) pairs += c;
        benchmark::DoNotOptimize(pairs);
    }
    state.SetItemsProcessed(state.iterations() * n);
    state.counters["neighbours"] = double(pairs) / n;
}

/// The particles the loop's gather evaluates: fluid ones, and with conduction the walls that
/// conduct (IDerivative::gathersAtBoundary).
template <int Dim>
std::size_t evaluatedParticles(Loop loop, const Storage<Dim>& s) {
    const auto kind = s.template getValue<int>(QuantityId::KIND);
    const bool heat =
        (loop == Loop::HEAT || loop == Loop::ALL) && s.has(heat_ids::THERMAL_CONDITION);
    std::size_t n = 0;
    for (Size i = 0; i < s.size(); ++i)
        n +=
            isFluid(kind[i]) || (heat && s.template getValue<int>(heat_ids::THERMAL_CONDITION)[i] !=
                                             int(ThermalCondition::ADIABATIC));
    return n;
}

template <int Dim, Loop L>
void loop(benchmark::State& state) {
    auto s = scene<Dim>(int(state.range(0)));
    Solver<Dim> solver(*s->scheduler, s->settings, termsOf<Dim>(L, *s), s->geometry.domain);
    for (auto _ : state) solver.evaluate(s->storage, 0.0);
    state.SetItemsProcessed(state.iterations() * s->storage.size());
    // The pairs one evaluation visits (bench/roofline.py).
    state.counters["pairs"] = solver.meanNeighbours() * double(evaluatedParticles(L, s->storage));
}

template <int Dim>
void step(benchmark::State& state) {
    auto s = scene<Dim>(int(state.range(0)));
    for (auto _ : state) s->run->step();
    state.SetItemsProcessed(state.iterations() * s->storage.size());
}

#define THREADS ->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()
BENCHMARK(search<2>) THREADS;
BENCHMARK(loop<2, Loop::DENSITY>) THREADS;
BENCHMARK(loop<2, Loop::FORCES>) THREADS;
BENCHMARK(loop<2, Loop::HEAT>) THREADS;
BENCHMARK(loop<2, Loop::ALL>) THREADS;
BENCHMARK(step<2>) THREADS;
BENCHMARK(search<3>) THREADS;
BENCHMARK(loop<3, Loop::DENSITY>) THREADS;
BENCHMARK(loop<3, Loop::FORCES>) THREADS;
BENCHMARK(loop<3, Loop::HEAT>) THREADS;
BENCHMARK(loop<3, Loop::ALL>) THREADS;
BENCHMARK(step<3>) THREADS;

}  // namespace

BENCHMARK_MAIN();
