#!/usr/bin/env bash
# Set-up, build, and run the default 2D scene of fluid_sim end to end.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
exec ./build/release/apps/fluid_sim/fluid_sim "$@"
