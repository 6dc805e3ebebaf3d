#!/usr/bin/env bash
# Set-up, build only fluid_sim and what it links (no tests, benchmarks, examples or Python
# module; the CUDA back end only where a GPU is present or NUMERICS_CUDA=ON asks for it:
# scripts/build.sh), and run the default 2D scene of fluid_sim end to end.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh fluid_sim
exec ./build/release/apps/fluid_sim/fluid_sim "$@"
