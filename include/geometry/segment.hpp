// Distances to segments, shared by polygons, polylines, cones and meshes.
#pragma once

#include <algorithm>

#include "geometry/solid.hpp"

namespace num::geometry {

/// The parameter in [0, 1] of the point of segment a-b nearest to x.
template <int Dim>
double nearestOnSegment(const Point<Dim>& x, const Point<Dim>& a, const Point<Dim>& b) {
    const Point<Dim> ab = b - a;
    const double len2 = normSqr(ab);
    return len2 > 0 ? std::clamp(dot(x - a, ab) / len2, 0.0, 1.0) : 0.0;
}

/// Squared distance from x to segment a-b.
template <int Dim>
double segmentDistanceSqr(const Point<Dim>& x, const Point<Dim>& a, const Point<Dim>& b) {
    return normSqr(x - (a + (b - a) * nearestOnSegment(x, a, b)));
}

}  // namespace num::geometry
