// A solid scaled (uniformly, about the origin), then rotated about the origin, then translated:
// x' = t + R (s x). Its signed distance is s times the original one at the original point.
#pragma once

#include <cmath>
#include <stdexcept>
#include <utility>

#include "geometry/rotation.hpp"
#include "geometry/solid.hpp"

namespace num::geometry {

template <int Dim>
class Transformed final : public Solid<Dim> {
  public:
    Transformed(SolidPtr<Dim> inner, double scale, Rotation<Dim> rotation, Point<Dim> translate)
        : inner_(std::move(inner)), scale_(scale), rotation_(rotation), translate_(translate) {
        if (!(scale > 0 && std::isfinite(scale)))
            throw std::invalid_argument("a transformation's scale must be a positive number");
    }

    double signedDistance(const Point<Dim>& x) const override {
        return scale_ * inner_->signedDistance(toInner(x));
    }
    Point<Dim> outwardNormal(const Point<Dim>& x, double h = 1e-6) const override {
        return rotation_.apply(inner_->outwardNormal(toInner(x), h / scale_));
    }
    Bounds<Dim> bounds() const override;
    /// The inner solid's, transformed (mass_properties.hpp).
    std::optional<MassProperties<Dim>> massProperties() const override {
        const auto inner = inner_->massProperties();
        if (!inner) return std::nullopt;
        return transformed(*inner, scale_, rotation_.rows(), translate_);
    }
    const Solid<Dim>& inner() const { return *inner_; }
    double scale() const { return scale_; }
    const Rotation<Dim>& rotation() const { return rotation_; }
    const Point<Dim>& translation() const { return translate_; }

  private:
    Point<Dim> toInner(const Point<Dim>& x) const {
        return rotation_.applyInverse(x - translate_) / scale_;
    }
    Point<Dim> toOuter(const Point<Dim>& x) const {
        return translate_ + rotation_.apply(x * scale_);
    }

    SolidPtr<Dim> inner_;
    double scale_;
    Rotation<Dim> rotation_;
    Point<Dim> translate_;
};

/// The box of the transformed corners of the inner box; unbounded when the inner box is and the
/// rotation could turn an infinite side onto any axis.
template <int Dim>
Bounds<Dim> Transformed<Dim>::bounds() const {
    const Bounds<Dim> in = inner_->bounds();
    bool finite = true;
    for (int k = 0; k < Dim; ++k) finite = finite && std::isfinite(in.min[k] - in.max[k]);
    if (!finite && !rotation_.isIdentity()) return {};
    if (!finite) return {translate_ + in.min * scale_, translate_ + in.max * scale_};
    Bounds<Dim> out{Point<Dim>::filled(HUGE_VAL), Point<Dim>::filled(-HUGE_VAL)};
    for (int corner = 0; corner < (1 << Dim); ++corner) {
        Point<Dim> c;
        for (int k = 0; k < Dim; ++k) c[k] = (corner >> k & 1) ? in.max[k] : in.min[k];
        const Point<Dim> p = toOuter(c);
        for (int k = 0; k < Dim; ++k)
            out.min[k] = std::min(out.min[k], p[k]), out.max[k] = std::max(out.max[k], p[k]);
    }
    return out;
}

}  // namespace num::geometry
