#!/usr/bin/env bash
# Builds the GPU check's bundle: what a machine with an NVIDIA GPU needs to check and measure the
# CUDA back end when it has only the NVIDIA driver, the CUDA toolkit (for compute-sanitizer) and
# Python 3: no compiler, no build, no Debian -dev packages. Run here, on the build machine:
#
#   bench/gpu_bundle.sh [BUILD_DIR] [OUT_DIR]     (defaults: build/release build/gpu_bundle)
#
# Builds fluid_sim, fluid_sim_3d and gpu_cuda_step_test in BUILD_DIR (configured as the release
# preset if it is not yet; the build must find nvcc: fluid_sim --version says "CUDA back end
# (--backend cuda): built"), then writes OUT_DIR, anew:
#   bin/      the three programs, stripped (strip --strip-unneeded on copies)
#   lib/      the shared libraries they load (ldd), but the C library, the dynamic loader,
#             libm, libpthread, libdl, librt and the NVIDIA driver's libcuda and libnvidia-*,
#             which the GPU machine has (the CUDA runtime is linked in statically)
#   scenes/   the shipped scenes the check runs (scenes/ and scenes/validation/ as here)
#   check.sh, gpu_check.py, app_backend.py, env.sh, VERSION
# prints its size and fails when it is over 60 MB. Carry OUT_DIR (or the .tar.gz beside it) to
# the GPU machine and run `bash check.sh` there (about 5 minutes on an H100; `--host` runs what
# runs without a GPU, `--debug` every kernel synchronised and checked: bench/gpu_bundle/
# gpu_check.py says what each part does). JOBS sets the build's parallel jobs (default: nproc).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build/release}
out=${2:-$here/build/gpu_bundle}
limit=$((60 * 1000 * 1000))
cd "$here"
if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O3 -DNDEBUG"
fi
cmake --build "$build" -j"${JOBS:-$(nproc)}" --target fluid_sim fluid_sim_3d gpu_cuda_step_test
programs=("$build/apps/fluid_sim/fluid_sim" "$build/apps/fluid_sim_3d/fluid_sim_3d"
          "$build/tests/device/gpu_cuda_step_test")
version=$("${programs[0]}" --version)
if ! grep -q "back end (--backend cuda): built" <<< "$version"; then
    echo "gpu_bundle.sh: $build was built without the CUDA back end (no nvcc found?):" >&2
    echo "$version" >&2
    exit 1
fi

# OUT_DIR is made anew: refuse a folder that holds something else, or one git would track.
if [ -e "$out" ] && [ -n "$(ls -A "$out")" ] && [ ! -f "$out/VERSION" ]; then
    echo "gpu_bundle.sh: $out is not empty and no bundle: give another OUT_DIR" >&2
    exit 1
fi
mkdir -p "$out"
if git -C "$here" ls-files --error-unmatch "$out" >/dev/null 2>&1 ||
   { case "$(cd "$out" && pwd)/" in "$here"/*) true ;; *) false ;; esac &&
     ! git -C "$here" check-ignore -q "$out"; }; then
    echo "gpu_bundle.sh: $out is inside the repository and not ignored by git: use build/ or out/" >&2
    rmdir "$out" 2>/dev/null || true
    exit 1
fi
rm -rf "$out"
mkdir -p "$out/bin" "$out/lib" "$out/scenes/validation"
for p in "${programs[@]}"; do
    cp "$p" "$out/bin/"
    strip --strip-unneeded "$out/bin/$(basename "$p")"
done
# The libraries: each as ldd resolves it, under the name the programs ask for. Left out: what
# every Linux has (the C library and its parts, the loader) and the NVIDIA driver's.
skip='^(linux-vdso|linux-gate|ld-linux|libc\.so|libm\.so|libmvec\.so|libpthread\.so|libdl\.so|librt\.so|libcuda\.so|libnvidia-)'
for p in "${programs[@]}"; do
    ldd "$p" | awk '$2 == "=>" && $3 ~ /^\// {print $1, $3}'
    if ldd "$p" | grep -q "not found"; then
        echo "gpu_bundle.sh: $p: a library is not found:" >&2
        ldd "$p" | grep "not found" >&2
        exit 1
    fi
done | sort -u | while read -r name path; do
    if grep -Eq "$skip" <<< "$name"; then continue; fi
    cp -L "$path" "$out/lib/$name"
    chmod u+w "$out/lib/$name"
    strip --strip-unneeded "$out/lib/$name"
done
# The scenes the check runs (bench/gpu_bundle/gpu_check.py, tests/device/app_backend.py).
cp scenes/dam_break_3d.json scenes/dam_break_hot_cold_2d.json "$out/scenes/"
cp scenes/validation/dam_break_martin_moyce.json scenes/validation/hydrostatic_tank_2d.json \
   "$out/scenes/validation/"
if grep -lE '"(mesh|file)"[[:space:]]*:' "$out"/scenes/*.json "$out"/scenes/validation/*.json; then
    echo "gpu_bundle.sh: a bundled scene names a file (a mesh?): bundle it too" >&2
    exit 1
fi
cp bench/gpu_bundle/check.sh bench/gpu_bundle/env.sh bench/gpu_bundle/gpu_check.py \
   tests/device/app_backend.py "$out/"
{
    echo "$version"
    echo "commit $(git -C "$here" rev-parse --short HEAD 2>/dev/null || echo unknown)$(
        git -C "$here" diff --quiet HEAD 2>/dev/null || echo ' (with changes not committed)')"
    echo "built $(date -u +%Y-%m-%dT%H:%M:%SZ) on $(uname -m), $(ldd --version | head -1)"
} > "$out/VERSION"
chmod +x "$out/check.sh" "$out/gpu_check.py" "$out/app_backend.py"

bytes=$(du -sb "$out" | cut -f1)
tar -C "$(dirname "$out")" -czf "$out.tar.gz" "$(basename "$out")"
echo "gpu_bundle.sh: $out: $((bytes / 1000000)).$(( (bytes % 1000000) / 100000 )) MB" \
     "($bytes bytes; $out.tar.gz $(du -b "$out.tar.gz" | cut -f1) bytes):"
du -sh "$out"/bin/* "$out/lib" "$out/scenes"
if [ "$bytes" -gt "$limit" ]; then
    echo "gpu_bundle.sh: the bundle is over 60 MB" >&2
    exit 1
fi
echo "gpu_bundle.sh: on the GPU machine: bash $(basename "$out")/check.sh   (or --host here)"
