// The solids of include/geometry/ as plain data that host and CUDA device code both evaluate: a
// tree of nodes in pre-order (node i's subtree is nodes [i, i + size)) over one array of
// doubles, walked with fixed stacks (no recursion, no heap). Each formula repeats its host
// class's operation for operation, so a view gives the Solid's signed distance and outward
// normal bit for bit (with -ffp-contract=off on the host, nvcc -fmad=false on the device).
// flatten() of flat_solid.hpp builds the data.
#pragma once

#include <limits>
#include <type_traits>

#include "geometry/solid.hpp"
#include "sph/host_device.hpp"

namespace num::geometry {

/// What a node is; the leaves first, then the nodes with children.
enum class FlatKind : int {
    BALL,
    BOX,
    HALF_SPACE,
    POLYGON,
    POLYLINE,
    CONE,
    TRANSFORMED,
    UNION,
    INTERSECTION,
    DIFFERENCE
};

/// A node; its numbers start at data[first]:
///   BALL centre, radius            BOX min, max            HALF_SPACE point, unit normal
///   POLYGON (2D) `count` edges a, b, even-odd inside
///   POLYLINE `count` points, then the half-thickness
///   CONE (3D) base, unit axis, length, base radius, top radius
///   TRANSFORMED scale, the rotation's rows, translation; its inner solid: the next node
///   UNION, INTERSECTION, DIFFERENCE (the first minus the others): `count` parts, the first the
///   next node, each further one after the subtree of the one before.
struct FlatNode {
    FlatKind kind;
    int count;  ///< parts, edges or points
    int size;   ///< nodes in the subtree, this one included
    int first;  ///< index of its first number in the data
};

/// Transformations and combinations nested at most (the stacks of the walks).
inline constexpr int FLAT_MAX_DEPTH = 16;

namespace detail {

/// std::abs but for the sign of a zero, which the callers subtract a positive number from.
NUMERICS_HD_INLINE double flatAbs(double v) { return v < 0 ? -v : v; }

template <int Dim>
NUMERICS_HD Point<Dim> flatPoint(const double* d) {
    Point<Dim> p;
    for (int k = 0; k < Dim; ++k) p[k] = d[k];
    return p;
}

/// segmentDistanceSqr (segment.hpp): t = clamp((x - a).(b - a) / |b - a|^2, 0, 1), then
/// |x - (a + (b - a) t)|^2.
template <int Dim>
NUMERICS_HD double flatSegmentDistanceSqr(const Point<Dim>& x, const Point<Dim>& a,
                                          const Point<Dim>& b) {
    const Point<Dim> ab = b - a;
    const double len2 = normSqr(ab);
    double t = 0.0;
    if (len2 > 0) {
        t = dot(x - a, ab) / len2;
        t = t < 0.0 ? 0.0 : 1.0 < t ? 1.0 : t;  // std::clamp's order of tests
    }
    return normSqr(x - (a + (b - a) * t));
}

/// Box: q_k = |x_k - (min_k + max_k) / 2| - (max_k - min_k) / 2, |max(q, 0)| + min(max_k q_k, 0).
template <int Dim>
NUMERICS_HD double flatBox(const double* d, const Point<Dim>& x) {
    double outside = 0, inside = -std::numeric_limits<double>::infinity();
    for (int k = 0; k < Dim; ++k) {
        const double q = flatAbs(x[k] - (d[k] + d[Dim + k]) / 2) - (d[Dim + k] - d[k]) / 2;
        outside += q > 0 ? q * q : 0;
        inside = hd::max(inside, q);
    }
    return hd::sqrt(outside) + hd::min(inside, 0.0);
}

/// PolygonSet: the distance to the nearest edge, negative when a ray towards +x crosses an odd
/// number of edges ((a.y > x.y) != (b.y > x.y) and x.x left of the crossing; edge_tree.cpp).
NUMERICS_HD_INLINE double flatPolygon(const double* d, int edges, const Point<2>& x) {
    double best = std::numeric_limits<double>::infinity();
    bool odd = false;
    for (int i = 0; i < edges; ++i) {
        const Point<2> a = flatPoint<2>(d + 4 * i), b = flatPoint<2>(d + 4 * i + 2);
        const double d2 = flatSegmentDistanceSqr(x, a, b);
        if (d2 < best) best = d2;
        if ((a[1] > x[1]) != (b[1] > x[1])) {
            const double xCross = a[0] + (x[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
            if (x[0] < xCross) odd = !odd;
        }
    }
    const double dist = hd::sqrt(best);
    return odd ? -dist : dist;
}

/// Polyline: the distance to the nearest segment minus the half-thickness.
template <int Dim>
NUMERICS_HD double flatPolyline(const double* d, int points, const Point<Dim>& x) {
    double d2 = std::numeric_limits<double>::infinity();
    for (int i = 0; i + 1 < points; ++i)
        d2 = hd::min(d2, flatSegmentDistanceSqr(x, flatPoint<Dim>(d + Dim * i),
                                                flatPoint<Dim>(d + Dim * (i + 1))));
    return hd::sqrt(d2) - d[Dim * points];
}

/// Cone: in the meridian half-plane p = (rho, h), the distance to the outline base-side-top,
/// negative for 0 < h < L and rho < r0 + (r1 - r0) h / L.
NUMERICS_HD_INLINE double flatCone(const double* d, const Point<3>& x) {
    const Point<3> axis = flatPoint<3>(d + 3), v = x - flatPoint<3>(d);
    const double length = d[6], r0 = d[7], r1 = d[8];
    const double h = dot(v, axis);
    const Point<2> p{{norm(v - axis * h), h}};
    const Point<2> a{{0, 0}}, b{{r0, 0}}, c{{r1, length}}, e{{0, length}};
    const double dist =
        hd::sqrt(hd::min(hd::min(flatSegmentDistanceSqr(p, a, b), flatSegmentDistanceSqr(p, b, c)),
                         flatSegmentDistanceSqr(p, c, e)));
    const bool inside = h > 0 && h < length && p[0] < r0 + (r1 - r0) * h / length;
    return inside ? -dist : dist;
}

/// Transformed's toInner: R^T (x - t) / s, R^T y summed row by row as Rotation::applyInverse.
template <int Dim>
NUMERICS_HD Point<Dim> flatToInner(const double* d, const Point<Dim>& x) {
    const Point<Dim> y = x - flatPoint<Dim>(d + 1 + Dim * Dim);
    Point<Dim> r{};
    for (int i = 0; i < Dim; ++i) r += flatPoint<Dim>(d + 1 + Dim * i) * y[i];
    return r / d[0];
}

/// Rotation::apply: (R n)_i = row_i . n.
template <int Dim>
NUMERICS_HD Point<Dim> flatRotate(const double* d, const Point<Dim>& n) {
    Point<Dim> r;
    for (int i = 0; i < Dim; ++i) r[i] = dot(flatPoint<Dim>(d + 1 + Dim * i), n);
    return r;
}

/// Combination's rule for a part after the first: whether its distance d decides instead
/// (union: less, intersection: greater, difference: -d greater), then best is d (-d).
NUMERICS_HD_INLINE bool flatBeats(FlatKind how, double d, double& best) {
    const bool better = how == FlatKind::UNION          ? d < best
                        : how == FlatKind::INTERSECTION ? d > best
                                                        : -d > best;
    if (better) best = how == FlatKind::DIFFERENCE ? -d : d;
    return better;
}

}  // namespace detail

/// A flattened solid over arrays it does not own (host vectors or device copies): plain data,
/// trivially copyable into a kernel's arguments. Node 0 is the root.
template <int Dim>
struct FlatSolidView {
    const FlatNode* nodes = nullptr;
    int nodeCount = 0;
    const double* data = nullptr;
    int dataCount = 0;

    /// Solid::signedDistance: negative inside, positive outside.
    NUMERICS_HD double signedDistance(const Point<Dim>& x) const { return distanceOf(0, x); }
    NUMERICS_HD bool contains(const Point<Dim>& x) const { return signedDistance(x) < 0; }
    /// Solid::outwardNormal of step h.
    NUMERICS_HD Point<Dim> outwardNormal(const Point<Dim>& x, double h = 1e-6) const;
    /// The signed distance of the subtree of node `root`: down to each leaf through frames of
    /// the transformations (x to the inner solid's coordinates) and the combinations (the part
    /// taken next), then up with its distance (times the scale; the combination's rule).
    NUMERICS_HD double distanceOf(int root, const Point<Dim>& x) const;

  private:
    struct Frame {
        Point<Dim> x;  ///< at the node
        double best;   ///< a combination's distance so far
        int node, part, child;
    };
    NUMERICS_HD double leafDistance(const FlatNode& n, const Point<Dim>& x) const;
    NUMERICS_HD Point<Dim> leafNormal(const FlatNode& n, const Point<Dim>& x, double h) const;
    NUMERICS_HD int decidingPart(const FlatNode& n, int node, const Point<Dim>& x,
                                 bool& turned) const;
};

template <int Dim>
NUMERICS_HD double FlatSolidView<Dim>::leafDistance(const FlatNode& n, const Point<Dim>& x) const {
    const double* d = data + n.first;
    switch (n.kind) {
        case FlatKind::BALL:
            return norm(x - detail::flatPoint<Dim>(d)) - d[Dim];
        case FlatKind::BOX:
            return detail::flatBox<Dim>(d, x);
        case FlatKind::HALF_SPACE:
            return dot(x - detail::flatPoint<Dim>(d), detail::flatPoint<Dim>(d + Dim));
        case FlatKind::POLYLINE:
            return detail::flatPolyline<Dim>(d, n.count, x);
        default:
            break;
    }
    if constexpr (Dim == 2)
        if (n.kind == FlatKind::POLYGON) return detail::flatPolygon(d, n.count, x);
    if constexpr (Dim == 3)
        if (n.kind == FlatKind::CONE) return detail::flatCone(d, x);
    return std::numeric_limits<double>::quiet_NaN();
}

template <int Dim>
NUMERICS_HD double FlatSolidView<Dim>::distanceOf(int root, const Point<Dim>& x) const {
    Frame stack[FLAT_MAX_DEPTH];
    int top = 0, node = root;
    Point<Dim> p = x;
    for (;;) {
        for (; nodes[node].kind >= FlatKind::TRANSFORMED; ++node) {  // the child: next node
            if (top == FLAT_MAX_DEPTH) return std::numeric_limits<double>::quiet_NaN();
            stack[top++] = {p, 0.0, node, 0, node + 1};
            if (nodes[node].kind == FlatKind::TRANSFORMED)
                p = detail::flatToInner<Dim>(data + nodes[node].first, p);
        }
        double value = leafDistance(nodes[node], p);
        for (;; --top) {
            if (top == 0) return value;
            Frame& f = stack[top - 1];
            const FlatNode& n = nodes[f.node];
            if (n.kind == FlatKind::TRANSFORMED) {
                value = data[n.first] * value;  // scale * inner
                continue;
            }
            if (f.part == 0)
                f.best = value;
            else
                detail::flatBeats(n.kind, value, f.best);
            if (++f.part < n.count) {
                f.child += nodes[f.child].size;
                node = f.child, p = f.x;
                break;
            }
            value = f.best;
        }
    }
}

/// Combination's nearest: the index of the deciding part's node; `turned` when it is subtracted.
template <int Dim>
NUMERICS_HD int FlatSolidView<Dim>::decidingPart(const FlatNode& n, int node, const Point<Dim>& x,
                                                 bool& turned) const {
    int child = node + 1, best = child, part = 0;
    double bestDistance = distanceOf(child, x);
    for (int i = 1; i < n.count; ++i) {
        child += nodes[child].size;
        if (detail::flatBeats(n.kind, distanceOf(child, x), bestDistance)) best = child, part = i;
    }
    turned = n.kind == FlatKind::DIFFERENCE && part > 0;
    return best;
}

/// A half-space's normal; a ball's (x - c) / |x - c| off its centre; else Solid's default:
/// n_k = (d(x + h e_k) - d(x - h e_k)) / (2 h), divided by |n| when |n| > 0.
template <int Dim>
NUMERICS_HD Point<Dim> FlatSolidView<Dim>::leafNormal(const FlatNode& n, const Point<Dim>& x,
                                                      double h) const {
    if (n.kind == FlatKind::HALF_SPACE) return detail::flatPoint<Dim>(data + n.first + Dim);
    if (n.kind == FlatKind::BALL) {
        const Point<Dim> d = x - detail::flatPoint<Dim>(data + n.first);
        const double len = norm(d);
        if (len > 0) return d / len;
    }
    Point<Dim> g{};
    for (int k = 0; k < Dim; ++k) {
        Point<Dim> a = x, b = x;
        a[k] += h, b[k] -= h;
        g[k] = (leafDistance(n, a) - leafDistance(n, b)) / (2 * h);
    }
    const double len = norm(g);
    return len > 0 ? g / len : g;
}

/// Down the path of deciding parts (x and h to each inner solid's coordinates: h / scale) to a
/// leaf's normal, then back up: rotated by each transformation, turned by subtracted parts.
template <int Dim>
NUMERICS_HD Point<Dim> FlatSolidView<Dim>::outwardNormal(const Point<Dim>& x, double h) const {
    int path[FLAT_MAX_DEPTH];  // a transformation: its node; a part: -1 turned, -2 not
    int depth = 0, node = 0;
    Point<Dim> p = x;
    while (nodes[node].kind >= FlatKind::TRANSFORMED) {
        const FlatNode& n = nodes[node];
        if (depth == FLAT_MAX_DEPTH)
            return Point<Dim>::filled(std::numeric_limits<double>::quiet_NaN());
        if (n.kind == FlatKind::TRANSFORMED) {
            path[depth++] = node++;
            p = detail::flatToInner<Dim>(data + n.first, p);
            h = h / data[n.first];
            continue;
        }
        bool turned = false;
        node = decidingPart(n, node, p, turned);
        path[depth++] = turned ? -1 : -2;
    }
    Point<Dim> normal = leafNormal(nodes[node], p, h);
    while (depth > 0) {
        const int step = path[--depth];
        if (step >= 0)
            normal = detail::flatRotate<Dim>(data + nodes[step].first, normal);
        else if (step == -1)
            normal = -normal;
    }
    return normal;
}

static_assert(std::is_trivially_copyable_v<FlatNode> && std::is_standard_layout_v<FlatNode>);
static_assert(std::is_trivially_copyable_v<FlatSolidView<2>> &&
              std::is_trivially_copyable_v<FlatSolidView<3>>);

}  // namespace num::geometry
