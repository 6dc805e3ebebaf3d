// Triangle meshes (3D): reading STL, OBJ and PLY files, the checks a closed volume needs, its
// exact volume, and its section by a plane.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "geometry/geometry_error.hpp"
#include "geometry/solid.hpp"

namespace num::geometry {

/// a x b
inline Point<3> cross(const Point<3>& a, const Point<3>& b) {
    return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

struct TriangleMesh {
    std::vector<Point<3>> vertices;
    std::vector<std::array<int, 3>> triangles;  ///< vertex indices, counter-clockwise seen from out
};

/// Every triangle of an STL (binary or ASCII), OBJ or PLY file, read by assimp, in one mesh with
/// the vertices at the same position merged. Throws GeometryError when the file cannot be read
/// or holds no triangle.
TriangleMesh readMesh(const std::string& path);

namespace detail {
/// readMesh's reading without its check and its child process: assimp reads the file in this
/// process, so a file it crashes on ends the program. For the in-process fuzzers (tests/fuzz/).
TriangleMesh readWithAssimp(const std::string& path);
}  // namespace detail

/// The volume enclosed: the divergence theorem gives sum over triangles of a . (b x c) / 6
/// (positive when the triangles face outward).
double enclosedVolume(const TriangleMesh& mesh);

/// Checks that the mesh bounds a volume: no zero-area triangle, every edge shared by exactly two
/// triangles that run along it in opposite directions; then turns it outward if it faces in.
/// Throws GeometryError saying what is wrong, how often and where; `name` names the mesh.
void checkClosedVolume(TriangleMesh& mesh, const std::string& name);

/// The closed outlines where the plane x[axis] = at cuts a closed mesh, in the coordinates
/// (x[axis + 1], x[axis + 2]) (cyclic: y, z for axis x; z, x for y; x, y for z). Empty when the
/// plane misses the mesh.
std::vector<std::vector<Point<2>>> sectionLoops(const TriangleMesh& mesh, int axis, double at);

}  // namespace num::geometry
