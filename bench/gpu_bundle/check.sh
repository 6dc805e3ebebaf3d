#!/usr/bin/env bash
# The GPU check, in the bundle made by bench/gpu_bundle.sh: on a machine with an NVIDIA GPU, its
# driver, the CUDA toolkit (compute-sanitizer) and Python 3,
#
#   bash check.sh [--host] [--debug] [--work DIR] [--only gpu,step,memcheck,apps,1e5,1e6,1e7]
#
# runs the CUDA tests, compute-sanitizer's memcheck, the apps on the GPU against the CPU and the
# GPU's ns per particle-step and bytes per particle at 1e5, 1e6 and 1e7 particles (about 5
# minutes on an H100), and prints one table; exit 1 when a check failed. gpu_check.py says what
# each part does; --host runs what runs without a GPU (a test of the bundle, no GPU figures).
set -euo pipefail
. "$(dirname "${BASH_SOURCE[0]}")/env.sh"
python=${PYTHON:-$(command -v python3 || true)}
if [ -z "$python" ]; then
    echo "check.sh: python3 not found (set PYTHON)" >&2
    exit 2
fi
exec "$python" "$NUMERICS_BUNDLE/gpu_check.py" "$@"
