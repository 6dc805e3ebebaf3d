#!/usr/bin/env bash
# The CUDA back end against the CPU: the 3D dam break (scenes/dam_break_3d.json) at about 1e5,
# 1e6 and 1e7 fluid particles and a 2D dam break at about 1e6, on the GPU (--backend cuda) and
# with 16 CPU threads (--backend threads --threads 16). Prints, per case and back end, the
# particles, the time per particle and step [ns] of the time loop alone and, on the GPU, the
# device memory per particle [bytes]; writes the table to OUT/gpu_scaling.md.
#
#   bench/gpu_scaling.sh [BUILD_DIR] [OUT] [THREADS]     (defaults: build/release out/gpu_scaling 16)
#
# Each case runs twice, to two end times (about 10 and 40 steps); the difference of the wall
# times over the difference of the particle-steps leaves set-up, the first evaluation and the
# outputs out. Needs a build with the CUDA back end (fluid_sim --version) and an NVIDIA GPU; the
# CPU runs need about 1 KB of memory per particle (1e7 particles: about 12 GB).
set -euo pipefail
build=${1:-build/release}
out=${2:-out/gpu_scaling}
threads=${3:-16}
here=$(cd "$(dirname "$0")/.." && pwd)
sim2=$build/apps/fluid_sim/fluid_sim
sim3=$build/apps/fluid_sim_3d/fluid_sim_3d
mkdir -p "$out"
if ! "$sim2" --version | grep -q "back end (--backend cuda): built"; then
    echo "gpu_scaling.sh: $sim2 was built without the CUDA back end (see its --version)" >&2
    exit 1
fi
quiet=(-q --set output.images=false --set output.video=false --set 'output.formats=["csv"]'
       --set output.every=1000)
# case name, app, scene, spacing [m], extra settings
cases=(
  "3d_1e5|$sim3|$here/scenes/dam_break_3d.json|0.01293|"
  "3d_1e6|$sim3|$here/scenes/dam_break_3d.json|0.006|"
  "3d_1e7|$sim3|$here/scenes/dam_break_3d.json|0.002785|"
  "2d_1e6|$sim2|$here/scenes/validation/dam_break_martin_moyce.json|0.0006|--set domain.max=[1.6,0.8] --set fluids.0.max=[0.6,0.6] --set probes=[]"
)
# GPU_SCALING_CASES (lines as above) replaces the cases, e.g. for a small trial.
if [ -n "${GPU_SCALING_CASES:-}" ]; then mapfile -t cases <<< "$GPU_SCALING_CASES"; fi
table=$out/gpu_scaling.md
{
  echo "| case | back end | particles | steps timed | ns per particle-step | device bytes per particle |"
  echo "| --- | --- | --- | --- | --- | --- |"
} > "$table"
for c in "${cases[@]}"; do
    IFS='|' read -r name app scene dx extra <<< "$c"
    # The leapfrog's step is about cfl h / c0: 10 and 40 of them.
    read -r t1 t2 < <(python3 - "$scene" "$dx" <<'PY'
import json, sys, math
s = json.load(open(sys.argv[1])); dx = float(sys.argv[2])
h = s["particles"].get("h_over_spacing", 1.5) * dx
cfl = s["time"].get("cfl", 0.25)
c0 = 10 * math.sqrt(2 * 9.81 * 0.6)   # about the scenes' auto sound speed
dt = cfl * h / c0
print(f"{10 * dt:.6g} {40 * dt:.6g}")
PY
)
    for backend in cuda threads; do
        args=("$scene" --set "particles.spacing=$dx" "${quiet[@]}")
        [ -n "$extra" ] && read -r -a more <<< "$extra" && args+=("${more[@]}")
        if [ "$backend" = cuda ]; then args+=(--backend cuda); else args+=(--backend threads --threads "$threads"); fi
        for t in "$t1" "$t2"; do
            echo "== $name $backend to t = $t s" >&2
            "$app" "${args[@]}" --end-time "$t" --out "$out/$name/$backend/$t"
        done
        python3 - "$out/$name/$backend/$t1/summary.json" "$out/$name/$backend/$t2/summary.json" \
            "$name" "$backend" "$threads" >> "$table" <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
name, backend, threads = sys.argv[3:6]
n = b["particles"]
steps = b["steps"] - a["steps"]
ns = (b["wall_seconds"] - a["wall_seconds"]) / (steps * n) * 1e9 if steps > 0 else float("nan")
label = "cuda (" + b.get("device", "?") + ")" if backend == "cuda" else f"{threads} CPU threads"
mem = f'{b["device_bytes_per_particle"]:.0f}' if "device_bytes_per_particle" in b else "-"
print(f"| {name} | {label} | {n:,} | {steps} | {ns:.2f} | {mem} |")
PY
    done
done
cat "$table"
