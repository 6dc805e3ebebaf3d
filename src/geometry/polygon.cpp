// Polygons: the even-odd inside test, the exact distance to the edges, and the check that a
// polygon does not cross itself.
#include "geometry/polygon.hpp"

#include <cmath>
#include <string>

namespace num::geometry {

namespace {

double cross(const Point<2>& a, const Point<2>& b) { return a[0] * b[1] - a[1] * b[0]; }

/// Whether segments p1-p2 and q1-q2 share a point (touching included).
bool segmentsMeet(const Point<2>& p1, const Point<2>& p2, const Point<2>& q1, const Point<2>& q2) {
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

/// Throws when two edges of the closed loop cross or touch, other than neighbours at their
/// shared point; neighbours that fold back onto each other count as crossing.
void checkSimple(const Loop& p) {
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Point<2>&a = p[i], &b = p[(i + 1) % n], &c = p[(i + 2) % n];
        if (cross(b - a, c - b) == 0 && dot(b - a, c - b) < 0)
            throw GeometryError("the polygon folds back on itself at point " +
                                std::to_string((i + 1) % n) + " (" + edgeName(i, n) + " and " +
                                edgeName((i + 1) % n, n) + " overlap)");
        for (std::size_t j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1) continue;
            if (segmentsMeet(a, b, p[j], p[(j + 1) % n]))
                throw GeometryError("the polygon crosses itself: " + edgeName(i, n) + " and " +
                                    edgeName(j, n) +
                                    " meet (list the points in order around the outline)");
        }
    }
}

}  // namespace

PolygonSet::PolygonSet(const std::vector<Loop>& loops) {
    bounds_ = {Point<2>::filled(HUGE_VAL), Point<2>::filled(-HUGE_VAL)};
    for (const Loop& loop : loops)
        for (std::size_t i = 0; i < loop.size(); ++i) {
            edges_.push_back({loop[i], loop[(i + 1) % loop.size()]});
            for (int k = 0; k < 2; ++k)
                bounds_.min[k] = std::min(bounds_.min[k], loop[i][k]),
                bounds_.max[k] = std::max(bounds_.max[k], loop[i][k]);
        }
    if (edges_.size() < 3) throw GeometryError("a polygon needs 3 points or more");
}

/// The distance to the nearest edge, negative when a ray towards +x crosses an odd number of
/// edges (each edge counted on the half-open span of its y).
double PolygonSet::signedDistance(const Point<2>& x) const {
    double d2 = HUGE_VAL;
    bool inside = false;
    for (const Edge& e : edges_) {
        d2 = std::min(d2, segmentDistanceSqr(x, e.a, e.b));
        if ((e.a[1] > x[1]) != (e.b[1] > x[1])) {
            const double xCross = e.a[0] + (x[1] - e.a[1]) * (e.b[0] - e.a[0]) / (e.b[1] - e.a[1]);
            if (x[0] < xCross) inside = !inside;
        }
    }
    return inside ? -std::sqrt(d2) : std::sqrt(d2);
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
    checkSimple(points);
    return std::make_shared<PolygonSet>(std::vector<Loop>{points});
}

}  // namespace num::geometry
