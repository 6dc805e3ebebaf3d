#!/usr/bin/env bash
# Set-up (with the test-only tools: setup.sh --tests), build, and run the whole test suite;
# exits non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh --tests
./scripts/build.sh
ctest --preset release -j "$(nproc)" "$@"
