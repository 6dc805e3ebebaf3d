// Solids of revolution about a segment (3D): the truncated cone, and the cylinder as the cone of
// equal radii. Exact signed distance: a point's distance to the solid is its distance, in the
// meridian half-plane (rho from the axis, h along it), to the outline of the cross-section.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "geometry/segment.hpp"

namespace num::geometry {

/// A cone from a disc of `baseRadius` at `base` to one of `topRadius` at `top` (0: a tip).
class Cone final : public Solid<3> {
  public:
    Cone(Point<3> base, Point<3> top, double baseRadius, double topRadius)
        : base_(base), top_(top), length_(norm(top - base)), rBase_(baseRadius), rTop_(topRadius) {
        if (!(length_ > 0)) throw std::invalid_argument("a cone's base and top must differ");
        if (!(baseRadius >= 0 && topRadius >= 0 && baseRadius + topRadius > 0))
            throw std::invalid_argument("a cone's radii must be >= 0, one of them > 0");
        axis_ = (top - base) / length_;
    }

    double signedDistance(const Point<3>& x) const override {
        const Point<3> d = x - base_;
        const double h = dot(d, axis_);
        const Point<2> p{{norm(d - axis_ * h), h}};
        const Point<2> a{{0, 0}}, b{{rBase_, 0}}, c{{rTop_, length_}}, e{{0, length_}};
        const double dist =
            std::sqrt(std::min({segmentDistanceSqr(p, a, b), segmentDistanceSqr(p, b, c),
                                segmentDistanceSqr(p, c, e)}));
        const bool inside = h > 0 && h < length_ && p[0] < rBase_ + (rTop_ - rBase_) * h / length_;
        return inside ? -dist : dist;
    }

    /// The box of the two end discs: a disc of radius r and normal u spans r sqrt(1 - u_k^2).
    Bounds<3> bounds() const override {
        Bounds<3> b;
        for (int k = 0; k < 3; ++k) {
            const double s = std::sqrt(std::max(0.0, 1 - axis_[k] * axis_[k]));
            b.min[k] = std::min(base_[k] - rBase_ * s, top_[k] - rTop_ * s);
            b.max[k] = std::max(base_[k] + rBase_ * s, top_[k] + rTop_ * s);
        }
        return b;
    }

  private:
    Point<3> base_, top_, axis_;
    double length_, rBase_, rTop_;
};

/// A cylinder of `radius` from `base` to `top`.
inline SolidPtr<3> cylinder(const Point<3>& base, const Point<3>& top, double radius) {
    return std::make_shared<Cone>(base, top, radius, radius);
}

}  // namespace num::geometry
