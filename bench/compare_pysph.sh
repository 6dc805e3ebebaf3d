#!/usr/bin/env bash
# The app as users run it against PySPH on PySPH's 2D dam break: a 1 m x 2 m column in a
# 4 m x 4 m tank, dx = 0.01 (20,000 fluid + 3,618 wall particles in both codes, on the same
# lattice), h = 1.3 dx, Wendland C2, Tait EOS, c0 = 10 sqrt(2 g H) = 62.6 m/s, alpha = 0.1.
#
#   bench/compare_pysph.sh [BUILD_DIR] [END_TIME] [REPEATS]
#   defaults: build/release 0.05 (simulated seconds, both codes) 3 repeats
#
# numerics: `fluid_sim bench/pysph_dam_break_2d.json`, the apps' default physics (heat
# conduction, delta-SPH, particle shifting, free-surface clamp, the adaptive time step), CSV
# output at the start and the end. PySPH (bench/pysph_dam_break_2d.py, Debian's python3-pysph):
# WCSPHScheme with delta-SPH, the fixed step 0.125 h / c0, no output. Both are timed as whole
# processes (start to exit, wall clock), 1 thread and 2 threads (PySPH: --openmp with
# OMP_NUM_THREADS=2), alternately (PySPH, numerics, PySPH, numerics, ...) so that a change of
# machine load hits both; the medians and their ratio are printed. PySPH compiles its generated
# code once: a warm-up run fills its cache first, so its whole-process time excludes the
# compilation; its own timing of the solver loop alone is printed too.
#
# Installs Debian's python3-pysph if missing.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build/release}
END_TIME=${2:-0.05}
REPEATS=${3:-3}
PY=/usr/bin/python3
SCENE=bench/pysph_dam_break_2d.json
APP="$BUILD/apps/fluid_sim/fluid_sim"

if ! "$PY" -c "import pysph" 2>/dev/null; then
    echo "installing python3-pysph"
    SUDO=""
    [ "$(id -u)" -ne 0 ] && SUDO=sudo
    $SUDO apt-get install -y python3-pysph
fi
if [ ! -x "$APP" ]; then
    cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null
    cmake --build "$BUILD" --target fluid_sim -j2
fi

WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
now() { date +%s.%N; }
since() { awk -v a="$1" -v b="$(now)" 'BEGIN {printf "%.3f", b - a}'; }
pysph() {  # threads -> "wall_seconds loop_seconds steps"
    local flags=() start line
    [ "$1" -gt 1 ] && flags=(--openmp)
    start=$(now)
    line=$(cd "$WORK" && OMP_NUM_THREADS=$1 "$PY" "$OLDPWD/bench/pysph_dam_break_2d.py" \
        --dx 0.01 --time "$END_TIME" "${flags[@]}" 2>/dev/null | tail -1)
    echo "$(since "$start") $(echo "$line" | field seconds) $(echo "$line" | field steps)"
}
ours() {  # threads -> "wall_seconds steps"
    local start
    rm -rf "$WORK/out"
    start=$(now)
    "$APP" "$SCENE" --threads "$1" --end-time "$END_TIME" --out "$WORK/out" >/dev/null
    echo "$(since "$start") $(grep -o '"steps": *[0-9]*' "$WORK/out/summary.json" | grep -o '[0-9]*$')"
}
field() { grep -o "$1=[0-9.e+-]*" | cut -d= -f2; }
median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "simulated time: $END_TIME s; medians of $REPEATS alternating runs, whole process"
# Warm-up: PySPH compiles its serial and OpenMP extension modules once (not timed).
(cd "$WORK" && "$PY" "$OLDPWD/bench/pysph_dam_break_2d.py" --steps 1 >/dev/null 2>&1)
(cd "$WORK" && OMP_NUM_THREADS=2 "$PY" "$OLDPWD/bench/pysph_dam_break_2d.py" --steps 1 \
    --openmp >/dev/null 2>&1)
printf "%-8s %-12s %-14s %-12s %-14s %s\n" threads "pysph [s]" "(loop, steps)" \
    "fluid_sim [s]" "(steps)" "pysph / fluid_sim"
for t in 1 2; do
    : >"$WORK/p" && : >"$WORK/pl" && : >"$WORK/o"
    for r in $(seq "$REPEATS"); do
        read -r wall loop psteps <<<"$(pysph "$t")"
        echo "$wall" >>"$WORK/p" && echo "$loop" >>"$WORK/pl"
        read -r owall osteps <<<"$(ours "$t")"
        echo "$owall" >>"$WORK/o"
    done
    p=$(median <"$WORK/p")
    o=$(median <"$WORK/o")
    printf "%-8s %-12.2f %-14s %-12.2f %-14s %.2f\n" "$t" "$p" \
        "($(median <"$WORK/pl" | xargs printf '%.2f'), $psteps)" "$o" "($osteps)" \
        "$(awk -v o="$o" -v p="$p" 'BEGIN {print p / o}')"
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
