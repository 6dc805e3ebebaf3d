// Detection of triangles of a mesh that cross each other: for each triangle, the triangles
// whose boxes overlap its box (through the tree), tested edge against triangle with the signs
// of tetrahedron volumes (strict: contacts and coplanar overlaps are not counted).
#include <algorithm>
#include <cstdio>

#include "triangle_tree.hpp"

namespace num::geometry::detail {

namespace {

/// The sign of the volume of tetrahedron abcd (six times it).
int orientation(const Point<3>& a, const Point<3>& b, const Point<3>& c, const Point<3>& d) {
    const double v = dot(cross(b - a, c - a), d - a);
    return (v > 0) - (v < 0);
}

/// Whether segment pq passes through the inside of triangle abc.
bool segmentCrosses(const Point<3>& p, const Point<3>& q, const Point<3>& a, const Point<3>& b,
                    const Point<3>& c) {
    if (orientation(a, b, c, p) * orientation(a, b, c, q) >= 0) return false;
    const int s1 = orientation(p, q, a, b), s2 = orientation(p, q, b, c),
              s3 = orientation(p, q, c, a);
    return s1 != 0 && s1 == s2 && s2 == s3;
}

bool trianglesCross(const TriangleMesh& m, const std::array<int, 3>& s,
                    const std::array<int, 3>& t) {
    const auto& V = m.vertices;
    for (int k = 0; k < 3; ++k) {
        if (segmentCrosses(V[s[k]], V[s[(k + 1) % 3]], V[t[0]], V[t[1]], V[t[2]])) return true;
        if (segmentCrosses(V[t[k]], V[t[(k + 1) % 3]], V[s[0]], V[s[1]], V[s[2]])) return true;
    }
    return false;
}

bool shareVertex(const std::array<int, 3>& s, const std::array<int, 3>& t) {
    for (int u : s)
        if (std::find(t.begin(), t.end(), u) != t.end()) return true;
    return false;
}

Bounds<3> boxOf(const TriangleMesh& m, const std::array<int, 3>& t) {
    Bounds<3> b{m.vertices[t[0]], m.vertices[t[0]]};
    for (int v : t)
        for (int k = 0; k < 3; ++k)
            b.min[k] = std::min(b.min[k], m.vertices[v][k]),
            b.max[k] = std::max(b.max[k], m.vertices[v][k]);
    return b;
}

}  // namespace

void checkSelfCrossings(const TriangleMesh& mesh, const TriangleTree& tree,
                        const std::string& name) {
    std::size_t pairs = 0;
    int first[2] = {-1, -1};
    for (int i = 0; i < int(mesh.triangles.size()); ++i) {
        const auto& s = mesh.triangles[i];
        tree.overlapping(boxOf(mesh, s), [&](int j) {
            const auto& t = mesh.triangles[j];
            if (j <= i || shareVertex(s, t) || !trianglesCross(mesh, s, t)) return;
            if (pairs++ == 0) first[0] = i, first[1] = j;
        });
    }
    if (pairs == 0) return;
    const Point<3>& at = mesh.vertices[mesh.triangles[first[0]][0]];
    char where[96];
    std::snprintf(where, sizeof where, "(%g, %g, %g)", at[0], at[1], at[2]);
    throw GeometryError(
        name + " intersects itself: " + std::to_string(pairs) +
        " pairs of triangles cross (triangles " + std::to_string(first[0]) + " and " +
        std::to_string(first[1]) + ", near " + where +
        "), where its inside is ambiguous: repair the mesh (a union of the overlapping parts)");
}

}  // namespace num::geometry::detail
