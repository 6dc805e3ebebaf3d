// Polygons: the even-odd inside test, the exact distance to the edges, and the check that a
// polygon does not cross itself, all through the edge tree of edge_tree.hpp; the mass
// properties of one loop.
#include "geometry/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "edge_tree.hpp"

namespace num::geometry {

namespace {

double cross(const Point<2>& a, const Point<2>& b) { return a[0] * b[1] - a[1] * b[0]; }

/// Whether segments p1-p2 and q1-q2 share a point (touching included). Segments whose boxes
/// are apart never meet: the test is first, as the signs of nearly collinear segments far apart
/// may look like a crossing by rounding (and the edge tree only offers edges near p1-p2).
bool segmentsMeet(const Point<2>& p1, const Point<2>& p2, const Point<2>& q1, const Point<2>& q2) {
    for (int k = 0; k < 2; ++k)
        if (std::max(p1[k], p2[k]) < std::min(q1[k], q2[k]) ||
            std::max(q1[k], q2[k]) < std::min(p1[k], p2[k]))
            return false;
    const double d1 = cross(q2 - q1, p1 - q1), d2 = cross(q2 - q1, p2 - q1);
    const double d3 = cross(p2 - p1, q1 - p1), d4 = cross(p2 - p1, q2 - p1);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
        return true;
    auto onSegment = [](const Point<2>& a, const Point<2>& b, const Point<2>& x) {
        return std::min(a[0], b[0]) <= x[0] && x[0] <= std::max(a[0], b[0]) &&
               std::min(a[1], b[1]) <= x[1] && x[1] <= std::max(a[1], b[1]);
    };
    return (d1 == 0 && onSegment(q1, q2, p1)) || (d2 == 0 && onSegment(q1, q2, p2)) ||
           (d3 == 0 && onSegment(p1, p2, q1)) || (d4 == 0 && onSegment(p1, p2, q2));
}

std::string edgeName(std::size_t i, std::size_t n) {
    return "edge " + std::to_string(i) + " (points " + std::to_string(i) + "-" +
           std::to_string((i + 1) % n) + ")";
}

/// Throws when edge i and the next fold back onto each other (a turn of 180 degrees).
void checkFold(const Loop& p, std::size_t i) {
    const std::size_t n = p.size();
    const Point<2>&a = p[i], &b = p[(i + 1) % n], &c = p[(i + 2) % n];
    if (cross(b - a, c - b) == 0 && dot(b - a, c - b) < 0)
        throw GeometryError("the polygon folds back on itself at point " +
                            std::to_string((i + 1) % n) + " (" + edgeName(i, n) + " and " +
                            edgeName((i + 1) % n, n) + " overlap)");
}

/// Throws when two edges of the closed loop cross or touch, other than neighbours at their
/// shared point; neighbours that fold back onto each other count as crossing. The first fault
/// in the order of a loop over i, then over j > i (a fold at i before a crossing of edge i):
/// the edge tree offers each edge i the edges near it, of which the least j that meets it.
void checkSimple(const Loop& p, const detail::EdgeTree& tree) {
    const std::size_t n = p.size();
    std::vector<int> near;
    for (std::size_t i = 0; i < n; ++i) {
        checkFold(p, i);
        const Point<2>&a = p[i], &b = p[(i + 1) % n];
        tree.edgesNear(a, b, near);
        std::size_t first = n;
        for (const int k : near) {
            const std::size_t j = std::size_t(k);
            if (j < i + 2 || j >= first || (i == 0 && j == n - 1)) continue;
            if (segmentsMeet(a, b, p[j], p[(j + 1) % n])) first = j;
        }
        if (first < n)
            throw GeometryError("the polygon crosses itself: " + edgeName(i, n) + " and " +
                                edgeName(first, n) +
                                " meet (list the points in order around the outline)");
    }
}

/// Area, centroid and polar moment of a simple loop by Green's theorem (Steger 1996, "On the
/// calculation of arbitrary moments of polygons", TU Munich FGBV-96-05): with p, q the ends of
/// an edge and c = p x q, 2A = sum c, 6A C = sum (p + q) c and 12 J_0 = sum (|p|^2 + p . q +
/// |q|^2) c, all signed by the orientation. The points are taken from the first one for
/// accuracy; J about the centroid by parallel axes: J = J_0 - A |C|^2. Empty for zero area.
std::optional<MassProperties<2>> loopMassProperties(const Loop& loop) {
    const Point<2> origin = loop[0];
    double twiceArea = 0, twelveJ = 0;
    Point<2> sixAC{};
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const Point<2> a = loop[i] - origin, b = loop[(i + 1) % loop.size()] - origin;
        const double c = cross(a, b);
        twiceArea += c;
        sixAC += (a + b) * c;
        twelveJ += (dot(a, a) + dot(a, b) + dot(b, b)) * c;
    }
    if (!(std::abs(twiceArea) > 0)) return std::nullopt;
    const Point<2> centroid = sixAC / (3 * twiceArea);
    MassProperties<2> m;
    m.volume = std::abs(twiceArea) / 2;
    m.centroid = origin + centroid;
    m.inertia = (twiceArea > 0 ? twelveJ : -twelveJ) / 12 - m.volume * normSqr(centroid);
    return m;
}

}  // namespace

PolygonSet::PolygonSet(const std::vector<Loop>& loops) {
    bounds_ = {Point<2>::filled(HUGE_VAL), Point<2>::filled(-HUGE_VAL)};
    std::vector<detail::PolygonEdge> edges;
    std::size_t count = 0;
    for (const Loop& loop : loops) count += loop.size();
    edges.reserve(count);
    for (const Loop& loop : loops)
        for (std::size_t i = 0; i < loop.size(); ++i) {
            edges.push_back({loop[i], loop[(i + 1) % loop.size()]});
            for (int k = 0; k < 2; ++k)
                bounds_.min[k] = std::min(bounds_.min[k], loop[i][k]),
                bounds_.max[k] = std::max(bounds_.max[k], loop[i][k]);
        }
    if (edges.size() < 3) throw GeometryError("a polygon needs 3 points or more");
    tree_ = std::make_shared<const detail::EdgeTree>(edges);
    if (loops.size() == 1) mass_ = loopMassProperties(loops[0]);
}

/// The distance to the nearest edge, negative when a ray towards +x crosses an odd number of
/// edges (each edge counted on the half-open span of its y).
double PolygonSet::signedDistance(const Point<2>& x) const {
    const double d = std::sqrt(tree_->nearestDistanceSqr(x));
    return tree_->oddCrossings(x) ? -d : d;
}

std::vector<std::array<Point<2>, 2>> PolygonSet::edges() const {
    std::vector<std::array<Point<2>, 2>> edges;
    for (const detail::PolygonEdge& e : tree_->inputEdges()) edges.push_back({e.a, e.b});
    return edges;
}

SolidPtr<2> polygon(const Loop& points) {
    if (points.size() < 3)
        throw GeometryError("a polygon needs 3 points or more, found " +
                            std::to_string(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i)
        if (points[i] == points[(i + 1) % points.size()])
            throw GeometryError("points " + std::to_string(i) + " and " +
                                std::to_string((i + 1) % points.size()) +
                                " of the polygon coincide (list each corner once)");
    // The set's edges are the loop's in order: edge i of the tree is edge i of the outline.
    auto set = std::make_shared<PolygonSet>(std::vector<Loop>{points});
    checkSimple(points, *set->tree_);
    return set;
}

}  // namespace num::geometry
