// The bounding-volume tree over polygon edges: built by splitting at the median of the edges'
// midpoints along the longer axis; searched with stacks, skipping boxes that cannot change the
// answer. The margins below are bounds on the rounding of the per-edge formulas (a few units
// in the last place of the coordinates) times 1e4 or more: they cost no pruning in practice.
#include "edge_tree.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "geometry/segment.hpp"

namespace num::geometry::detail {

namespace {

constexpr int LEAF_SIZE = 4;
/// Relative margin on distances and crossings (rounding is below 1e-15 of the coordinates).
constexpr double REL = 1e-12;
/// A tree of at most 2^31 edges is at most 32 levels deep: the stacks hold a path and siblings.
using Stack = std::array<int, 128>;

double boxDistanceSqr(const Bounds<2>& b, const Point<2>& p) {
    double d2 = 0;
    for (int k = 0; k < 2; ++k) {
        const double e = std::max({b.min[k] - p[k], 0.0, p[k] - b.max[k]});
        d2 += e * e;
    }
    return d2;
}

void grow(Bounds<2>& b, const Point<2>& p) {
    for (int k = 0; k < 2; ++k)
        b.min[k] = std::min(b.min[k], p[k]), b.max[k] = std::max(b.max[k], p[k]);
}

Bounds<2> empty() { return {Point<2>::filled(HUGE_VAL), Point<2>::filled(-HUGE_VAL)}; }

bool boxesOverlap(const Bounds<2>& a, const Bounds<2>& b) {
    return a.min[0] <= b.max[0] && b.min[0] <= a.max[0] && a.min[1] <= b.max[1] &&
           b.min[1] <= a.max[1];
}

/// The squared distance below which a box may hold an edge nearer than `best`: the computed
/// distance of an edge differs from its true distance by a few roundings of `scale`.
double reachSqr(double best, double scale) {
    const double reach = std::sqrt(best) * (1 + REL) + REL * scale;
    return reach * reach * (1 + REL);
}

/// Whether every point of `box` lies clearly on one side of the line through p and q: the side
/// is the sign of cross(q - p, c - p), computed as segment tests compute it, so an edge in the
/// box cannot touch or (by rounding) seem to cross p-q.
bool missesLine(const Bounds<2>& box, const Point<2>& p, const Point<2>& q) {
    const Point<2> d = q - p;
    double least = HUGE_VAL, most = -HUGE_VAL, size = 0;
    for (const double cx : {box.min[0], box.max[0]})
        for (const double cy : {box.min[1], box.max[1]}) {
            const double s = d[0] * (cy - p[1]) - d[1] * (cx - p[0]);
            least = std::min(least, s), most = std::max(most, s);
            size = std::max(size, std::abs(d[0] * (cy - p[1])) + std::abs(d[1] * (cx - p[0])));
        }
    // The cross product of a point of the box is off by at most a few roundings of `size`;
    // NaN or infinite values compare false and keep the box.
    const double margin = REL * size + 1e-300;
    return least > margin || most < -margin;
}

}  // namespace

EdgeTree::EdgeTree(const std::vector<PolygonEdge>& edges) : ids_(edges.size()) {
    std::iota(ids_.begin(), ids_.end(), 0);
    // The crossing of an edge, x = a.x + (y - a.y) (b.x - a.x) / (b.y - a.y), lies within its
    // box but for rounding, unless a product underflows into a quotient by a tiny height or
    // overflows: then the ray checks every box it meets.
    for (const PolygonEdge& e : edges) {
        for (int k = 0; k < 2; ++k) scale_ = std::max({scale_, std::abs(e.a[k]), std::abs(e.b[k])});
        const double height = std::abs(e.b[1] - e.a[1]);
        if (height != 0 && height < 1e-150) rayPrune_ = false;
    }
    if (!(scale_ <= 1e150)) rayPrune_ = false;
    raySlack_ = REL * scale_ + 1e-100;
    nodes_.reserve(2 * edges.size() / LEAF_SIZE + 2);
    nodes_.resize(1);
    build(edges, 0, 0, int(edges.size()));
    edges_.reserve(edges.size());
    for (int id : ids_) edges_.push_back(edges[id]);
}

/// Fills node `slot` with the edges ids_[begin, end); an inner node's two children take
/// consecutive slots.
void EdgeTree::build(const std::vector<PolygonEdge>& edges, int slot, int begin, int end) {
    Bounds<2> box = empty(), centres = empty();
    for (int i = begin; i < end; ++i) {
        const PolygonEdge& e = edges[ids_[i]];
        grow(box, e.a), grow(box, e.b), grow(centres, (e.a + e.b) / 2.0);
    }
    nodes_[slot] = {box, begin, end - begin};
    if (end - begin <= LEAF_SIZE) return;
    const int axis = centres.max[1] - centres.min[1] > centres.max[0] - centres.min[0] ? 1 : 0;
    const int mid = (begin + end) / 2;
    // Twice the midpoint; NaN (a vertex not a number) sorts as 0, as the order must be strict.
    auto key = [&](int e) {
        const double k = edges[e].a[axis] + edges[e].b[axis];
        return k == k ? k : 0.0;
    };
    std::nth_element(ids_.begin() + begin, ids_.begin() + mid, ids_.begin() + end,
                     [&](int s, int t) { return key(s) < key(t); });
    const int children = int(nodes_.size());
    nodes_.resize(children + 2);
    nodes_[slot].first = children, nodes_[slot].count = 0;
    build(edges, children, begin, mid);
    build(edges, children + 1, mid, end);
}

double EdgeTree::nearestDistanceSqr(const Point<2>& x) const {
    const double scale = scale_ + std::max(std::abs(x[0]), std::abs(x[1]));
    double best = HUGE_VAL, reach = HUGE_VAL;
    Stack stack;
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (boxDistanceSqr(node.box, x) > reach) continue;
        if (node.count == 0) {
            const double l = boxDistanceSqr(nodes_[node.first].box, x);
            const double r = boxDistanceSqr(nodes_[node.first + 1].box, x);
            // The nearer child on top of the stack: searched first, so `reach` shrinks sooner.
            stack[top++] = l < r ? node.first + 1 : node.first;
            stack[top++] = l < r ? node.first : node.first + 1;
            continue;
        }
        for (int i = node.first; i < node.first + node.count; ++i) {
            const double d2 = segmentDistanceSqr(x, edges_[i].a, edges_[i].b);
            if (d2 < best) best = d2, reach = reachSqr(best, scale);
        }
    }
    return best;
}

bool EdgeTree::oddCrossings(const Point<2>& x) const {
    bool odd = false;
    Stack stack;
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        // An edge counts only if min(a.y, b.y) <= x.y < max(a.y, b.y): exact for boxes too.
        if (!(node.box.min[1] <= x[1] && x[1] < node.box.max[1])) continue;
        if (rayPrune_ && x[0] >= node.box.max[0] + raySlack_) continue;
        if (node.count == 0) {
            stack[top++] = node.first, stack[top++] = node.first + 1;
            continue;
        }
        for (int i = node.first; i < node.first + node.count; ++i) {
            const PolygonEdge& e = edges_[i];
            if ((e.a[1] > x[1]) != (e.b[1] > x[1])) {
                const double xCross =
                    e.a[0] + (x[1] - e.a[1]) * (e.b[0] - e.a[0]) / (e.b[1] - e.a[1]);
                if (x[0] < xCross) odd = !odd;
            }
        }
    }
    return odd;
}

void EdgeTree::edgesNear(const Point<2>& p, const Point<2>& q, std::vector<int>& ids) const {
    ids.clear();
    Bounds<2> span = empty();
    grow(span, p), grow(span, q);
    Stack stack;
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (!boxesOverlap(node.box, span) || missesLine(node.box, p, q)) continue;
        if (node.count == 0) {
            stack[top++] = node.first, stack[top++] = node.first + 1;
            continue;
        }
        for (int i = node.first; i < node.first + node.count; ++i) {
            Bounds<2> box = empty();
            grow(box, edges_[i].a), grow(box, edges_[i].b);
            if (boxesOverlap(box, span) && !missesLine(box, p, q)) ids.push_back(ids_[i]);
        }
    }
}

std::vector<PolygonEdge> EdgeTree::inputEdges() const {
    std::vector<PolygonEdge> edges(edges_.size());
    for (std::size_t k = 0; k < edges_.size(); ++k) edges[ids_[k]] = edges_[k];
    return edges;
}

}  // namespace num::geometry::detail
