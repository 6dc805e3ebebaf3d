// A bounding-volume tree of axis-aligned boxes over the triangles of a mesh, and the exact
// nearest point of a triangle (internal to numerics_geometry).
#pragma once

#include <string>
#include <vector>

#include "geometry/triangle_mesh.hpp"

namespace num::geometry::detail {

/// Where the nearest point of a triangle (a, b, c) lies.
enum class Feature { FACE, EDGE_AB, EDGE_BC, EDGE_CA, VERTEX_A, VERTEX_B, VERTEX_C };

struct TrianglePoint {
    Point<3> point;
    Feature feature;
};

/// The point of triangle abc nearest to p (Ericson, Real-Time Collision Detection, 5.1.5).
TrianglePoint nearestOnTriangle(const Point<3>& p, const Point<3>& a, const Point<3>& b,
                                const Point<3>& c);

struct NearestTriangle {
    double distanceSqr;
    int triangle;
    TrianglePoint at;
};

class TriangleTree {
  public:
    explicit TriangleTree(const TriangleMesh& mesh);
    /// The triangle nearest to p and its nearest point.
    NearestTriangle nearest(const Point<3>& p) const;
    Bounds<3> bounds() const { return nodes_[0].box; }
    /// Calls f(triangle) for each triangle whose box may overlap `box`.
    template <class F>
    void overlapping(const Bounds<3>& box, F&& f) const;

  private:
    struct Node {
        Bounds<3> box;
        int first, count;  ///< leaf: triangles order_[first, first + count); inner: count = 0,
                           ///< children first and first + 1
    };
    void build(int slot, int begin, int end);
    void search(const Point<3>& p, NearestTriangle& best) const;

    const TriangleMesh& mesh_;
    std::vector<int> order_;
    std::vector<Node> nodes_;
};

template <class F>
void TriangleTree::overlapping(const Bounds<3>& box, F&& f) const {
    auto apart = [&](const Bounds<3>& b) {
        for (int k = 0; k < 3; ++k)
            if (b.min[k] > box.max[k] || b.max[k] < box.min[k]) return true;
        return false;
    };
    int stack[128], top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (apart(node.box)) continue;
        if (node.count == 0) {
            stack[top++] = node.first, stack[top++] = node.first + 1;
            continue;
        }
        for (int i = node.first; i < node.first + node.count; ++i) f(order_[i]);
    }
}

/// Throws GeometryError when two triangles that share no vertex cross (an edge of one through
/// the inside of the other): there the inside of the mesh is ambiguous. Touching and coplanar
/// overlaps are not detected.
void checkSelfCrossings(const TriangleMesh& mesh, const TriangleTree& tree,
                        const std::string& name);

}  // namespace num::geometry::detail
