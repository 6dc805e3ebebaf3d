// The simple solids of any dimension: ball (a circle in 2D), axis-aligned box, half-space, and a
// box turned by a rotation. Their signed distances are exact, and so are the mass properties of
// the ball and the box (mass_properties.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "geometry/transformed.hpp"

namespace num::geometry {

/// |x - c| - r
template <int Dim>
class Ball final : public Solid<Dim> {
  public:
    Ball(Point<Dim> center, double radius) : center_(center), radius_(radius) {
        if (!(radius > 0)) throw std::invalid_argument("a ball's radius must be positive");
    }
    double signedDistance(const Point<Dim>& x) const override {
        return norm(x - center_) - radius_;
    }
    Bounds<Dim> bounds() const override {
        return {center_ - Point<Dim>::filled(radius_), center_ + Point<Dim>::filled(radius_)};
    }
    Point<Dim> outwardNormal(const Point<Dim>& x, double h = 1e-6) const override {
        const Point<Dim> d = x - center_;
        const double len = norm(d);
        return len > 0 ? d / len : Solid<Dim>::outwardNormal(x, h);
    }
    std::optional<MassProperties<Dim>> massProperties() const override {
        return ballMassProperties(center_, radius_);
    }
    const Point<Dim>& center() const { return center_; }
    double radius() const { return radius_; }

  private:
    Point<Dim> center_;
    double radius_;
};

/// Axis-aligned box: with q = |x - c| - half per axis, |max(q, 0)| + min(max_k q_k, 0).
template <int Dim>
class Box final : public Solid<Dim> {
  public:
    Box(Point<Dim> min, Point<Dim> max) : min_(min), max_(max) {
        for (int k = 0; k < Dim; ++k)
            if (!(max[k] > min[k]))
                throw std::invalid_argument("a box needs max > min on every axis");
    }
    double signedDistance(const Point<Dim>& x) const override {
        double outside = 0, inside = -HUGE_VAL;
        for (int k = 0; k < Dim; ++k) {
            const double q = std::abs(x[k] - (min_[k] + max_[k]) / 2) - (max_[k] - min_[k]) / 2;
            outside += q > 0 ? q * q : 0;
            inside = std::max(inside, q);
        }
        return std::sqrt(outside) + std::min(inside, 0.0);
    }
    Bounds<Dim> bounds() const override { return {min_, max_}; }
    std::optional<MassProperties<Dim>> massProperties() const override {
        return boxMassProperties(min_, max_);
    }
    const Point<Dim>& min() const { return min_; }
    const Point<Dim>& max() const { return max_; }

  private:
    Point<Dim> min_, max_;
};

/// The half-space behind a plane (a line in 2D): (x - p) . n with the unit outward normal n.
template <int Dim>
class HalfSpace final : public Solid<Dim> {
  public:
    HalfSpace(Point<Dim> point, Point<Dim> outward) : point_(point) {
        const double len = norm(outward);
        if (!(len > 0)) throw std::invalid_argument("a plane's normal must not be zero");
        normal_ = outward / len;
    }
    double signedDistance(const Point<Dim>& x) const override { return dot(x - point_, normal_); }
    Point<Dim> outwardNormal(const Point<Dim>&, double = 1e-6) const override { return normal_; }
    /// Unbounded, except on the axis of a normal along that axis.
    Bounds<Dim> bounds() const override {
        Bounds<Dim> b;
        for (int k = 0; k < Dim; ++k) {
            if (std::abs(normal_[k]) != 1) continue;
            (normal_[k] > 0 ? b.max : b.min)[k] = point_[k];
        }
        return b;
    }
    const Point<Dim>& point() const { return point_; }
    /// The unit outward normal.
    const Point<Dim>& normal() const { return normal_; }

  private:
    Point<Dim> point_, normal_;
};

/// A box of the given half-sizes centred on `center` and turned by `rotation` about its centre.
template <int Dim>
SolidPtr<Dim> rotatedBox(const Point<Dim>& center, const Point<Dim>& halfSizes,
                         const Rotation<Dim>& rotation) {
    auto box = std::make_shared<Box<Dim>>(-halfSizes, halfSizes);
    return std::make_shared<Transformed<Dim>>(box, 1.0, rotation, center);
}

}  // namespace num::geometry
