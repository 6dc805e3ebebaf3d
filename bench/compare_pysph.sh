#!/usr/bin/env bash
# Side by side with PySPH on the 2D dam break (1 m x 2 m column in a 4 m x 4 m tank, h = 1.3 dx,
# Wendland C2, Tait EOS, c0 = 10 sqrt(2 g H), alpha = 0.1, delta-SPH), same particles in both
# codes (bench/pysph_dam_break_2d.py builds numerics' lattice), 1 and 2 threads.
#
#   bench/compare_pysph.sh [BUILD_DIR] [DX] [STEPS] [REPEATS]
#   defaults: build/release 0.01 (20,000 fluid particles) 40 steps, 5 repeats
#   EVALUATION=symmetric|asymmetric (default symmetric) picks numerics' pair evaluation,
#   BACKEND=threads|omp (default threads, the std::thread pool) its parallel backend.
#
# numerics runs the same case twice: without heat (the physics PySPH runs) and with heat
# conduction on as well (more work per pair than PySPH does); both ratios are printed.
#
# Installs Debian's python3-pysph if missing. PySPH's one-time compilation of its generated
# code is excluded: a short warm-up run compiles it, and the application times only the solver
# loop. The two codes run alternately, so a change of machine load hits both; the medians of
# the repeats and their ratio are printed. Throughput = fluid particles x steps / seconds.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build/release}
DX=${2:-0.01}
STEPS=${3:-40}
REPEATS=${4:-5}
PY=/usr/bin/python3
EVALUATION=${EVALUATION:-symmetric}
BACKEND=${BACKEND:-threads}
OURS="$BUILD/bench/bench_dam_break"

if ! "$PY" -c "import pysph" 2>/dev/null; then
    echo "installing python3-pysph"
    SUDO=""
    [ "$(id -u)" -ne 0 ] && SUDO=sudo
    $SUDO apt-get install -y python3-pysph
fi
if [ ! -x "$OURS" ]; then
    cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null
    cmake --build "$BUILD" --target bench_dam_break -j2
fi

WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
pysph() {  # threads steps -> throughput
    local flags=()
    [ "$1" -gt 1 ] && flags=(--openmp)
    (cd "$WORK" && OMP_NUM_THREADS=$1 "$PY" "$OLDPWD/bench/pysph_dam_break_2d.py" --dx "$DX" \
        --steps "$2" "${flags[@]}" 2>/dev/null | tail -1)
}
ours() {  # threads steps heat -> result line
    "$OURS" --dim 2 --dx "$DX" --threads "$1" --steps "$2" --warmup 0 --repeats 1 --heat "$3" \
        --evaluation "$EVALUATION" --backend "$BACKEND" | tail -1
}
field() { grep -o "$1=[0-9.e+-]*" | cut -d= -f2; }
median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
# Warm-up: PySPH compiles its serial and OpenMP extension modules once (not timed).
pysph 1 1 >/dev/null
pysph 2 1 >/dev/null
echo "numerics evaluation: $EVALUATION, backend: $BACKEND"
printf "%-8s %-10s %-12s %-12s %-8s %-12s %-8s %s\n" threads particles pysph numerics ratio \
    "num.+heat" ratio "(particle-steps/s, medians of $REPEATS)"
for t in 1 2; do
    : >"$WORK/p" && : >"$WORK/o" && : >"$WORK/h"
    for r in $(seq "$REPEATS"); do
        line=$(pysph "$t" "$STEPS")
        echo "$line" | field particle_steps_per_second >>"$WORK/p"
        n=$(echo "$line" | field fluid_particles)
        ours "$t" "$STEPS" 0 | field particle_steps_per_second >>"$WORK/o"
        ours "$t" "$STEPS" 1 | field particle_steps_per_second >>"$WORK/h"
    done
    p=$(median <"$WORK/p")
    o=$(median <"$WORK/o")
    h=$(median <"$WORK/h")
    printf "%-8s %-10s %-12.4g %-12.4g %-8.2f %-12.4g %-8.2f\n" "$t" "$n" "$p" "$o" \
        "$(awk -v o="$o" -v p="$p" 'BEGIN {print o / p}')" "$h" \
        "$(awk -v o="$h" -v p="$p" 'BEGIN {print o / p}')"
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
