// A solid region of space given by its signed distance: the one interface through which scenes
// fill fluid volumes, place bodies and build walls of any shape (primitives, polygons, meshes and
// their combinations, include/geometry/). Virtual, so host only: the CUDA back end evaluates
// them flattened into plain data (flat_solid.hpp), meshes excepted.
#pragma once

#include <limits>
#include <memory>
#include <optional>

#include "geometry/mass_properties.hpp"
#include "spatial/vec.hpp"

namespace num::geometry {

template <int Dim>
using Point = Vec<double, Dim>;

/// An axis-aligned box holding a solid; infinite components for unbounded solids (a half-space).
template <int Dim>
struct Bounds {
    Point<Dim> min = Point<Dim>::filled(-std::numeric_limits<double>::infinity());
    Point<Dim> max = Point<Dim>::filled(std::numeric_limits<double>::infinity());
};

template <int Dim>
class Solid {
  public:
    virtual ~Solid() = default;
    /// Signed distance to the surface: negative inside, positive outside. Exact within a few
    /// kernel supports of the surface; further away at least a lower bound of |distance| with
    /// the right sign (enough for inside tests and for the layers of wall particles).
    virtual double signedDistance(const Point<Dim>& x) const = 0;
    /// A box that holds every point inside.
    virtual Bounds<Dim> bounds() const = 0;
    /// Unit normal of the nearest surface, pointing out of the solid: by default the gradient
    /// of the signed distance by central differences of step `h`.
    virtual Point<Dim> outwardNormal(const Point<Dim>& x, double h = 1e-6) const {
        Point<Dim> n{};
        for (int k = 0; k < Dim; ++k) {
            Point<Dim> a = x, b = x;
            a[k] += h, b[k] -= h;
            n[k] = (signedDistance(a) - signedDistance(b)) / (2 * h);
        }
        const double len = norm(n);
        return len > 0 ? n / len : n;
    }
    bool contains(const Point<Dim>& x) const { return signedDistance(x) < 0; }
    /// Exact volume, centroid and inertia per unit density where this solid knows them; empty:
    /// not known (callers integrate numerically).
    virtual std::optional<MassProperties<Dim>> massProperties() const { return std::nullopt; }
};

template <int Dim>
using SolidPtr = std::shared_ptr<const Solid<Dim>>;

}  // namespace num::geometry
