# shellcheck shell=bash
# The GPU check bundle's environment (bench/gpu_bundle.sh): source it to run the programs in
# bin/ by hand, e.g.  . ./env.sh && fluid_sim scenes/dam_break_3d.json --backend cuda
# Their libraries are in lib/; the NVIDIA driver's libcuda comes from the machine.
NUMERICS_BUNDLE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
export NUMERICS_BUNDLE
export PATH="$NUMERICS_BUNDLE/bin:$PATH:/usr/local/cuda/bin"
export LD_LIBRARY_PATH="$NUMERICS_BUNDLE/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
# The apps' probe plots want matplotlib, which the check does not need (probes are off).
export NUMERICS_PYTHON=${NUMERICS_PYTHON:-/nonexistent}
