#!/usr/bin/env bash
# Regenerates docs/first_run_2d.png, the picture on the README's first screen: the default scene
# of fluid_sim (built by scripts/build.sh fluid_sim) run up to TIME seconds (default 1.2, its end), its last picture.
# Usage: scripts/readme_picture.sh [TIME] [fluid_sim arguments...]; FLUID_SIM=path picks the app.
set -euo pipefail
cd "$(dirname "$0")/.."
time="${1:-1.2}"
shift || true
app="${FLUID_SIM:-./build/release/apps/fluid_sim/fluid_sim}"
[ -x "$app" ] || ./scripts/build.sh fluid_sim
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$app" --end-time "$time" --out "$work" --set output.video=false \
  -q "$@"
last="$(ls "$work"/particles_*.png | sort | tail -n 1)"
cp "$last" docs/first_run_2d.png
echo "docs/first_run_2d.png: the default 2D scene at t = $time s"
