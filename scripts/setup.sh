#!/usr/bin/env bash
# Installs the Debian packages numerics needs, only those that are missing. Idempotent and quiet
# when nothing is missing. Runs as root, or through sudo when available.
#   scripts/setup.sh           what building, running and testing need
#   scripts/setup.sh --tests   and the test-only tools (scripts/test.sh): ParaView, meshio, Xvfb
set -euo pipefail

packages=(
  g++ cmake make pkg-config      # compiler and build
  libgtest-dev                   # unit tests (GoogleTest)
  libbenchmark-dev               # micro-benchmarks (Google Benchmark)
  nlohmann-json3-dev             # scene files (JSON)
  libcli11-dev                   # command lines of the apps
  libmuparser-dev                # expressions in scene files
  libassimp-dev                  # triangle meshes in scenes (STL, OBJ, PLY): src/geometry/mesh_reader.cpp
  libpng-dev                     # pictures (PNG)
  libfreetype-dev fonts-dejavu-core  # pictures: their text in DejaVu Sans (src/output/image.cpp)
  zlib1g-dev                     # checkpoints: the CRC-32 checksum of each (src/output/checkpoint.cpp)
  ffmpeg                         # the movie of a run (<prefix>.mp4) from its pictures
  python3-numpy                  # validation: comparison of the apps' outputs (validation/cases.py)
  python3-matplotlib             # the apps' plots (scripts/plot_series.py: probes.png); validation's plots
  libopenmpi-dev openmpi-bin     # several processes (mpirun): MPI domain decomposition
  pybind11-dev python3-pybind11  # the Python module numerics (python/): its build
  python3-dev                    # the Python module numerics: Python's headers
  python3-tqdm                   # the Python module numerics: the progress bar of sim.run()
)

# Test-only: the outputs opened by the tools users open them with (tests/tools, label tools).
# ParaView with its libraries is about 700 MB installed, so scripts/run.sh does not install these.
test_packages=(
  paraview python3-paraview      # tests/tools: pvbatch runs <prefix>_paraview.py, renders a picture
  xvfb                           # tests/tools: a virtual X display for pvbatch (Xvfb)
  python3-meshio                 # tests/tools: meshio reads the VTU files
  python3-pil                    # tests/tools: reads the pixels of ParaView's picture
  python3-pytest                 # tests/python: the Python module's tests (pytest)
)
case "${1:-}" in
  "") ;;
  --tests) packages+=("${test_packages[@]}") ;;
  *) echo "usage: $0 [--tests]" >&2; exit 2 ;;
esac

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "Installing missing Debian packages: ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "error: run as root or install sudo to install ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
