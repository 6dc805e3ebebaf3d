// The bounding-volume tree over triangles: built by splitting at the median of the centroids on
// the longest axis; searched nearest box first, skipping boxes farther than the best so far.
#include "triangle_tree.hpp"

#include <algorithm>
#include <cmath>

namespace num::geometry::detail {

namespace {

constexpr int LEAF_SIZE = 4;

double boxDistanceSqr(const Bounds<3>& b, const Point<3>& p) {
    double d2 = 0;
    for (int k = 0; k < 3; ++k) {
        const double e = std::max({b.min[k] - p[k], 0.0, p[k] - b.max[k]});
        d2 += e * e;
    }
    return d2;
}

void grow(Bounds<3>& b, const Point<3>& p) {
    for (int k = 0; k < 3; ++k)
        b.min[k] = std::min(b.min[k], p[k]), b.max[k] = std::max(b.max[k], p[k]);
}

Bounds<3> empty() { return {Point<3>::filled(HUGE_VAL), Point<3>::filled(-HUGE_VAL)}; }

}  // namespace

TrianglePoint nearestOnTriangle(const Point<3>& p, const Point<3>& a, const Point<3>& b,
                                const Point<3>& c) {
    const Point<3> ab = b - a, ac = c - a, ap = p - a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return {a, Feature::VERTEX_A};
    const Point<3> bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return {b, Feature::VERTEX_B};
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return {a + ab * (d1 / (d1 - d3)), Feature::EDGE_AB};
    const Point<3> cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return {c, Feature::VERTEX_C};
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return {a + ac * (d2 / (d2 - d6)), Feature::EDGE_CA};
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
        return {b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))), Feature::EDGE_BC};
    const double denom = 1 / (va + vb + vc);
    return {a + ab * (vb * denom) + ac * (vc * denom), Feature::FACE};
}

TriangleTree::TriangleTree(const TriangleMesh& mesh) : mesh_(mesh), order_(mesh.triangles.size()) {
    for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = int(i);
    nodes_.reserve(2 * order_.size() / LEAF_SIZE + 2);
    nodes_.resize(1);
    build(0, 0, int(order_.size()));
}

/// Fills node `slot` with the triangles order_[begin, end); an inner node's two children take
/// consecutive slots.
void TriangleTree::build(int slot, int begin, int end) {
    Bounds<3> box = empty(), centres = empty();
    for (int i = begin; i < end; ++i) {
        Point<3> centre{};
        for (int v : mesh_.triangles[order_[i]])
            grow(box, mesh_.vertices[v]), centre += mesh_.vertices[v] / 3.0;
        grow(centres, centre);
    }
    nodes_[slot] = {box, begin, end - begin};
    if (end - begin <= LEAF_SIZE) return;
    int axis = 0;
    for (int k = 1; k < 3; ++k)
        if (centres.max[k] - centres.min[k] > centres.max[axis] - centres.min[axis]) axis = k;
    auto centre = [&](int t) {
        const auto& v = mesh_.triangles[t];
        return mesh_.vertices[v[0]][axis] + mesh_.vertices[v[1]][axis] + mesh_.vertices[v[2]][axis];
    };
    const int mid = (begin + end) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](int s, int t) { return centre(s) < centre(t); });
    const int children = int(nodes_.size());
    nodes_.resize(children + 2);
    nodes_[slot].first = children, nodes_[slot].count = 0;
    build(children, begin, mid);
    build(children + 1, mid, end);
}

NearestTriangle TriangleTree::nearest(const Point<3>& p) const {
    NearestTriangle best{HUGE_VAL, -1, {}};
    search(p, best);
    return best;
}

void TriangleTree::search(const Point<3>& p, NearestTriangle& best) const {
    int stack[128], top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (boxDistanceSqr(node.box, p) >= best.distanceSqr) continue;
        if (node.count == 0) {
            const double l = boxDistanceSqr(nodes_[node.first].box, p);
            const double r = boxDistanceSqr(nodes_[node.first + 1].box, p);
            // The nearer child on top of the stack: searched first.
            stack[top++] = l < r ? node.first + 1 : node.first;
            stack[top++] = l < r ? node.first : node.first + 1;
            continue;
        }
        for (int i = node.first; i < node.first + node.count; ++i) {
            const auto& t = mesh_.triangles[order_[i]];
            const TrianglePoint q = nearestOnTriangle(p, mesh_.vertices[t[0]], mesh_.vertices[t[1]],
                                                      mesh_.vertices[t[2]]);
            const double d2 = normSqr(p - q.point);
            if (d2 < best.distanceSqr) best = {d2, order_[i], q};
        }
    }
}

}  // namespace num::geometry::detail
