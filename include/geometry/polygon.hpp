// Solids given by vertex lists: closed polygons in 2D (exact signed distance, inside by the
// even-odd rule, so a set of loops may hold holes) and polyline walls (a band of half-thickness
// t about an open vertex list, in any dimension).
#pragma once

#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/geometry_error.hpp"
#include "geometry/segment.hpp"

namespace num::geometry {

namespace detail {
class EdgeTree;
}

using Loop = std::vector<Point<2>>;

/// Closed loops (each last vertex joins its first), either orientation; a point is inside when
/// a ray from it crosses the loops an odd number of times. The edges are held in a
/// bounding-volume tree (src/geometry/edge_tree.hpp): a query costs about log(edges), and
/// gives bit for bit what a loop over every edge gives. Queries change nothing: threads may
/// share a set.
class PolygonSet final : public Solid<2> {
  public:
    explicit PolygonSet(const std::vector<Loop>& loops);
    double signedDistance(const Point<2>& x) const override;
    Bounds<2> bounds() const override { return bounds_; }
    /// Exact for one loop (Green's theorem, polygon.cpp); empty for several.
    std::optional<MassProperties<2>> massProperties() const override { return mass_; }
    /// The edges (each from one vertex to the next of its loop), the loops' in order.
    std::vector<std::array<Point<2>, 2>> edges() const;

  private:
    friend SolidPtr<2> polygon(const Loop& points);  ///< checks the outline with tree_
    std::shared_ptr<const detail::EdgeTree> tree_;
    Bounds<2> bounds_;
    std::optional<MassProperties<2>> mass_;  ///< of the one loop, found on construction
};

/// One simple polygon of at least 3 vertices, either orientation. Throws GeometryError when two
/// vertices in a row coincide or two edges cross (naming them: edge i joins points i and i+1;
/// of several crossings the one of the lowest i, then the lowest j). The crossing check goes
/// through the edge tree: about n log(n) for n points.
SolidPtr<2> polygon(const Loop& points);

/// The band of points within `halfThickness` of an open vertex list: distance - halfThickness.
template <int Dim>
class Polyline final : public Solid<Dim> {
  public:
    Polyline(std::vector<Point<Dim>> points, double halfThickness)
        : points_(std::move(points)), halfThickness_(halfThickness) {
        if (points_.size() < 2) throw GeometryError("a polyline needs 2 points or more");
        if (!(halfThickness > 0)) throw GeometryError("a polyline's thickness must be positive");
    }
    double signedDistance(const Point<Dim>& x) const override {
        double d2 = HUGE_VAL;
        for (std::size_t i = 0; i + 1 < points_.size(); ++i)
            d2 = std::min(d2, segmentDistanceSqr(x, points_[i], points_[i + 1]));
        return std::sqrt(d2) - halfThickness_;
    }
    Bounds<Dim> bounds() const override {
        Bounds<Dim> b{points_[0], points_[0]};
        for (const Point<Dim>& p : points_)
            for (int k = 0; k < Dim; ++k)
                b.min[k] = std::min(b.min[k], p[k]), b.max[k] = std::max(b.max[k], p[k]);
        return {b.min - Point<Dim>::filled(halfThickness_),
                b.max + Point<Dim>::filled(halfThickness_)};
    }
    const std::vector<Point<Dim>>& points() const { return points_; }
    double halfThickness() const { return halfThickness_; }

  private:
    std::vector<Point<Dim>> points_;
    double halfThickness_;
};

}  // namespace num::geometry
