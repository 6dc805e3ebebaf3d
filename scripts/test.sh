#!/usr/bin/env bash
# Set-up, build, and run the whole test suite; exits non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
ctest --preset release -j "$(nproc)" "$@"
