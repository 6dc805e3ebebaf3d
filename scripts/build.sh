#!/usr/bin/env bash
# Installs what is missing and builds the release preset (build/release).
#   scripts/build.sh               everything: library, apps, tests, benchmarks, examples, the
#                                  Python module, and the CUDA back end when nvcc is found
#   scripts/build.sh TARGET...     only those targets and what they link (scripts/run.sh:
#                                  fluid_sim); the CUDA back end only where a GPU is present
#                                  (nvidia-smi lists one) or NUMERICS_CUDA=ON asks for it
# NUMERICS_CUDA=ON or OFF decides either way; an existing build keeps its choice otherwise
# (a build with the CUDA back end keeps it, so that run.sh after test.sh builds nothing again).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
cuda=${NUMERICS_CUDA:-}
case "$cuda" in
  ""|ON|OFF) ;;
  *) echo "error: NUMERICS_CUDA must be ON or OFF, found '$cuda'" >&2; exit 2 ;;
esac
if [ -z "$cuda" ]; then
  if [ $# -eq 0 ] || nvidia-smi -L >/dev/null 2>&1; then
    cuda=ON
  elif [ ! -f build/release/CMakeCache.txt ]; then
    cuda=OFF
  fi
fi
cmake --preset release ${cuda:+-DNUMERICS_WITH_CUDA=$cuda} >/dev/null
if [ $# -eq 0 ]; then
  cmake --build --preset release -j "$(nproc)"
else
  cmake --build --preset release -j "$(nproc)" --target "$@"
fi
