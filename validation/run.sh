#!/usr/bin/env bash
# Runs every validation case at documentation resolution and writes docs/validation.md with
# its plots (docs/validation/*.png).
#   validation/run.sh [build-dir]      (default build/release)
# Builds the Release configuration if needed, runs the ctest label `validation` with
# NUMERICS_VALIDATION_FULL=1, collects each case's <case>.json and <case>_profile.csv, and
# calls validation/report.py (Debian's python3-matplotlib and python3-numpy, installed with
# apt-get when missing).
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build/release}"
jobs="${NUMERICS_JOBS:-2}"

if ! /usr/bin/python3 -c "import matplotlib, numpy" 2>/dev/null; then
  echo "Installing python3-matplotlib and python3-numpy"
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends python3-matplotlib python3-numpy >/dev/null
fi

if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" -j "$jobs"

out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
status=0
NUMERICS_VALIDATION_FULL=1 NUMERICS_VALIDATION_OUT="$out" \
  ctest --test-dir "$build" -L validation -j "$jobs" --output-on-failure || status=$?

/usr/bin/python3 validation/report.py "$out" docs/validation.md docs/validation
echo "wrote docs/validation.md ($(ls "$out"/*.json 2>/dev/null | wc -l) cases)"
exit $status
