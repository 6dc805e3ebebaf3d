#!/usr/bin/env bash
# The whole benchmark suite: micro-benchmarks, end-to-end dam breaks (2D heat off/on, 3D), the
# 2D scaling from 1e4 to 1e6 particles, 1 versus 2 threads, the roofline of the pair loops and
# the PySPH comparison.
#
#   bench/run_all.sh [BUILD_DIR]        (default build/release; configured and built if needed)
#
# Prints markdown tables (the ones in docs/performance.md). Every end-to-end figure is the
# median of 5 timed runs after warm-up steps; the load average is printed with each line, as
# the timings of a shared machine depend on it.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build/release}
REPEATS=${REPEATS:-5}
BACKEND=${BACKEND:-threads}
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$BUILD" --target bench_dam_break bench_pair_loops bench_neighbours bench_two_cores bench_core_peak \
    -j2 >/dev/null
DAM="$BUILD/bench/bench_dam_break"

echo "## Machine"
echo
echo '```'
lscpu | grep -E "Model name|^CPU\(s\)|Thread|L1d|L2|L3" || true
echo "load: $(cut -d' ' -f1-3 /proc/loadavg)   $(date -u +%FT%TZ)"
echo '```'

echo
echo "## Micro-benchmarks (items = particles of any kind per evaluation)"
echo
echo '```'
"$BUILD/bench/bench_pair_loops" --benchmark_min_time=0.5 2>/dev/null | grep -E "^(search|loop|step)"
"$BUILD/bench/bench_neighbours" --benchmark_min_time=0.3 2>/dev/null | grep -E "^(build|query)"
echo '```'

row() {  # label args...
    local label=$1
    shift
    local line
    line=$("$DAM" --repeats "$REPEATS" --backend "$BACKEND" "$@" | tail -1)
    f() { echo "$line" | grep -o " $1=[^ ]*" | cut -d= -f2; }
    printf "| %s | %s | %s | %s | %.3g | %s | %s | %s | %s | %s |\n" "$label" "$(f threads)" \
        "$(f fluid_particles)" "$(f particles)" "$(f particle_steps_per_second)" \
        "$(f ns_per_particle_step)" "$(f cpu_ns_per_particle_step)" "$(f neighbours)" \
        "$(f bytes_per_particle)" "$(f load)"
}
header() {
    echo
    echo "| case ($BACKEND backend) | threads | fluid | all | particle-steps/s | ns/particle-step | CPU ns/particle-step | neighbours | bytes/particle | load |"
    echo "|---|---|---|---|---|---|---|---|---|---|"
}

echo
echo "## End to end: 2D dam break, dx = 0.01"
header
for eval in symmetric asymmetric; do
    for heat in 0 1; do
        for t in 1 2; do
            row "2D heat $heat $eval" --dim 2 --dx 0.01 --heat $heat --threads $t --steps 20 \
                --warmup 5 --evaluation $eval
        done
    done
done
BACKEND=omp row "2D heat 1 symmetric, OpenMP backend" --dim 2 --dx 0.01 --heat 1 --threads 2 \
    --steps 20 --warmup 5 --evaluation symmetric

echo
echo "## End to end: 3D dam break, dx = 0.02, h = 1.3 dx"
header
for eval in symmetric asymmetric; do
    for t in 1 2; do
        row "3D heat 0 $eval" --dim 3 --dx 0.02 --threads $t --steps 5 --warmup 2 --evaluation $eval
    done
done

echo
echo "## Scaling: 2D dam break, heat on, 1e4 to 1e6 fluid particles (sizes alternated)"
echo
for loop in asymmetric symmetric; do
    bench/size_scaling.py "$BUILD" "$REPEATS" 1,2 "$loop"
    echo
done

echo "## Two threads apart from SPH (a loop that computes, one that streams memory)"
echo
echo '```'
"$BUILD/bench/bench_two_cores" --rounds "$REPEATS"
echo '```'

echo
echo "## The roofline of the pair loops (1 thread)"
echo
/usr/bin/python3 bench/roofline.py "$BUILD" 3

echo
echo "## PySPH side by side"
echo
echo '```'
bench/compare_pysph.sh "$BUILD"
echo '```'
