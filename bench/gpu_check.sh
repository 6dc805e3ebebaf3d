#!/usr/bin/env bash
# What to run on a machine with an NVIDIA GPU: builds with the CUDA back end, runs the device
# tests on the CPU (label device) and the GPU tests (label gpu: the device step's CUDA execution
# against its host execution, every array of an evaluation and 40 steps; the 2D and 3D dam breaks
# with --backend cuda against the CPU back end within 1 %; two GPU runs bitwise identical; a
# restart cpu -> cuda -> cpu), then the benchmark bench/gpu_scaling.sh. Stops at the first
# failure.
#
#   bench/gpu_check.sh [BUILD_DIR]        (default build/release)
#
# This is the full check, for a GPU machine with the build environment (a compiler and the
# Debian -dev packages). For a first contact with a GPU machine that has only the NVIDIA driver,
# CUDA and Python, build the bundle here with bench/gpu_bundle.sh and run its check.sh there
# (shorter runs, about 5 minutes, no CPU timings; docs/performance.md).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build/release}
cd "$here"
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv || true
cmake --preset release
cmake --build "$build" -j"$(nproc)" --target fluid_sim fluid_sim_3d numerics_cuda \
    device_neighbour_grid_test device_fluid_step_test gpu_cuda_step_test
"$build/apps/fluid_sim/fluid_sim" --version
(cd "$build" && ctest -L device --output-on-failure --no-tests=error)
(cd "$build" && ctest -L gpu -V --no-tests=error) | tee "$build/gpu_check.log"
# A skipped GPU test is no check: say so and stop.
if grep -q "skipped:" "$build/gpu_check.log"; then
    echo "gpu_check.sh: the GPU tests were skipped (see their reason above)" >&2
    exit 1
fi
bench/gpu_scaling.sh "$build" "$here/out/gpu_scaling" 16
