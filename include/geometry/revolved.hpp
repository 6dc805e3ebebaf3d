// Solids of revolution about a segment (3D): the truncated cone, and the cylinder as the cone of
// equal radii. Exact signed distance: a point's distance to the solid is its distance, in the
// meridian half-plane (rho from the axis, h along it), to the outline of the cross-section.
// Exact mass properties: discs stacked along the axis.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
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
    std::optional<MassProperties<3>> massProperties() const override;
    const Point<3>& base() const { return base_; }
    /// The unit vector from base to top.
    const Point<3>& axis() const { return axis_; }
    double length() const { return length_; }
    double baseRadius() const { return rBase_; }
    double topRadius() const { return rTop_; }

  private:
    Point<3> base_, top_, axis_;
    double length_, rBase_, rTop_;
};

/// Discs of radius r(h) = r0 + (r1 - r0) h / L stacked along the axis u: V = int pi r^2 dh,
/// axial moment I_a = int pi r^4 / 2 dh, transverse (about the centroid h_c) I_t = int (pi r^4 /
/// 4 + pi r^2 (h - h_c)^2) dh, and I = I_t 1 + (I_a - I_t) u u^T. The integrands are
/// polynomials of degree 4 in h, which 3-point Gauss-Legendre integrates exactly.
inline std::optional<MassProperties<3>> Cone::massProperties() const {
    const double g = std::sqrt(0.6), pi = std::numbers::pi;
    const double nodes[3] = {(1 - g) / 2, 0.5, (1 + g) / 2},
                 weights[3] = {5. / 18, 8. / 18, 5. / 18};
    auto integral = [&](auto f) {
        double sum = 0;
        for (int k = 0; k < 3; ++k) sum += weights[k] * f(nodes[k] * length_);
        return sum * length_;
    };
    auto r = [&](double h) { return rBase_ + (rTop_ - rBase_) * h / length_; };
    MassProperties<3> m;
    m.volume = integral([&](double h) { return pi * r(h) * r(h); });
    const double hc = integral([&](double h) { return pi * r(h) * r(h) * h; }) / m.volume;
    const double axial = integral([&](double h) { return pi * std::pow(r(h), 4) / 2; });
    const double transverse = integral([&](double h) {
        return pi * std::pow(r(h), 4) / 4 + pi * r(h) * r(h) * (h - hc) * (h - hc);
    });
    m.centroid = base_ + axis_ * hc;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            m.inertia[i][j] = (i == j) * transverse + (axial - transverse) * (axis_[i] * axis_[j]);
    return m;
}

/// A cylinder of `radius` from `base` to `top`.
inline SolidPtr<3> cylinder(const Point<3>& base, const Point<3>& top, double radius) {
    return std::make_shared<Cone>(base, top, radius, radius);
}

}  // namespace num::geometry
