#!/usr/bin/env bash
# Runs every validation case through the apps at documentation resolution together with its
# convergence study, and rewrites docs/validation.md with its plots (docs/validation/*.png) and
# docs/validation/convergence.md.
#   validation/run.sh [build-dir]      (default build/release)
# Each run is `validation/cases.py run CASE --spacing DX` (the scene of scenes/validation/, the
# app, its defaults); its full result goes to docs/validation/results/CASE@DX.json (not kept in
# git: the profiles for the plots are most of it). validation/report.py then replaces the run's
# entry in docs/validation/summary.json (every run's figures, without profiles; kept in git) and
# writes the report from that summary (a run that fails is recorded as failed, never left with an
# older result). Environment:
#   NUMERICS_VALIDATION_CASES="a b"   only these cases (the others keep their figures and plots)
#   NUMERICS_VALIDATION_KEEP=1        skip runs whose full result is already in docs/validation/results
#   NUMERICS_THREADS=N                threads of each app run (default 2); one run at a time
# Needs Debian's python3-numpy and python3-matplotlib (scripts/setup.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build/release}"
threads="${NUMERICS_THREADS:-2}"
py=/usr/bin/python3

if ! "$py" -c "import matplotlib, numpy" 2>/dev/null; then
  echo "error: $py needs numpy and matplotlib: run scripts/setup.sh (python3-numpy, python3-matplotlib)" >&2
  exit 1
fi
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" --target fluid_sim fluid_sim_3d -j "${NUMERICS_JOBS:-2}"

results=docs/validation/results
mkdir -p "$results"
cases="${NUMERICS_VALIDATION_CASES:-$("$py" validation/cases.py list | cut -d' ' -f1)}"
status=0
for c in $cases; do
  for dx in $("$py" validation/cases.py spacings "$c"); do
    out="$results/$c@$dx.json"
    if [ "${NUMERICS_VALIDATION_KEEP:-0}" = 1 ] && [ -f "$out" ]; then continue; fi
    echo "== $c, spacing $dx"
    if "$py" validation/cases.py run "$c" --spacing "$dx" --bin "$build/apps" --threads "$threads" \
      --json "$out.tmp"; then
      mv "$out.tmp" "$out"
    else
      status=1
      # cases.py records why the run failed; if it could not, a record of the failure all the same
      [ -s "$out.tmp" ] || printf '{"case": "%s", "spacing": %s, "failed": "validation/cases.py failed"}\n' \
        "$c" "$dx" >"$out.tmp"
      mv "$out.tmp" "$out"
    fi
  done
done

"$py" validation/report.py "$results" docs/validation/summary.json docs/validation.md docs/validation
echo "wrote docs/validation.md"
exit $status
