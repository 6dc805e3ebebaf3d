// libFuzzer harness of the mesh reader: any bytes as a mesh file of one format (STL, OBJ or PLY,
// chosen when the harness is built: NUMERICS_FUZZ_MESH_FORMAT, one fuzzer and one corpus per
// format), read as a scene reads a mesh: readMesh (the file check, then assimp in a child
// process), then the checks of a closed volume, its volume and its sections through the middle
// of its box. Every outcome must be a mesh or a GeometryError; anything else escaping, a crash, a
// hang or a sanitizer report is a bug. A crash or hang of assimp in the child is a GeometryError
// (by design: assimp is not instrumented, and the child's own sanitizer reports stay there).
// Built with NUMERICS_FUZZ_MESH_IN_PROCESS (fuzz_mesh_<format>_in_process, fuzzers only), it
// reads as the child does, checkMeshFile then assimp in this process: no fork per input (tens
// of times faster), but a crash or hang of assimp ends the run (run it with -fork=1
// -ignore_crashes=1 -ignore_timeouts=1, and look at the stacks).
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "geometry/mesh_file_check.hpp"
#include "geometry/triangle_mesh.hpp"

#ifndef NUMERICS_FUZZ_MESH_FORMAT
#error "define NUMERICS_FUZZ_MESH_FORMAT as stl, obj or ply"
#endif
#define NUMERICS_FUZZ_TEXT(x) #x
#define NUMERICS_FUZZ_STRING(x) NUMERICS_FUZZ_TEXT(x)

#ifdef NUMERICS_FUZZ_MESH_IN_PROCESS
// assimp leaks on some files it refuses (about 2.5 kB from within libassimp.so, whose frames
// cannot be unwound further): not ours, and in readMesh's child, gone with it.
extern "C" const char* __lsan_default_suppressions() { return "leak:libassimp.so\n"; }
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace num::geometry;
    // readMesh reads a path, and assimp picks its reader by the extension: a file of this
    // process (the fuzzer's -fork and -jobs workers run side by side), written anew each input.
    static const std::string path = "/tmp/numerics_fuzz_mesh_" + std::to_string(::getpid()) +
                                    "." NUMERICS_FUZZ_STRING(NUMERICS_FUZZ_MESH_FORMAT);
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return 0;
    const bool written = std::fwrite(data, 1, size, f) == size;
    if (std::fclose(f) != 0 || !written) return 0;
    try {
#ifdef NUMERICS_FUZZ_MESH_IN_PROCESS
        checkMeshFile(path);
        TriangleMesh mesh = detail::readWithAssimp(path);
#else
        TriangleMesh mesh = readMesh(path);
#endif
        checkClosedVolume(mesh, "fuzz mesh");
        (void)enclosedVolume(mesh);
        Point<3> lo = mesh.vertices[0], hi = lo;
        for (const Point<3>& v : mesh.vertices)
            for (int k = 0; k < 3; ++k)
                lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
        for (int axis = 0; axis < 3; ++axis)
            (void)sectionLoops(mesh, axis, (lo[axis] + hi[axis]) / 2);
    } catch (const GeometryError&) {
    }
    std::remove(path.c_str());
    return 0;
}
