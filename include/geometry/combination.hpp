// Union, intersection and difference of solids: min, max and max(a, -b, ...) of their signed
// distances. Exact outside a union and inside an intersection; elsewhere (inside a union, near
// the edges a difference cuts) a bound on |distance| with the right sign: exact enough for the
// inside test and for wall layers, as solid.hpp asks.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "geometry/solid.hpp"

namespace num::geometry {

enum class Combine { UNION, INTERSECTION, DIFFERENCE };

template <int Dim>
class Combination final : public Solid<Dim> {
  public:
    /// DIFFERENCE: the first minus all the others.
    Combination(Combine how, std::vector<SolidPtr<Dim>> parts)
        : how_(how), parts_(std::move(parts)) {
        if (parts_.size() < 2)
            throw std::invalid_argument(
                "a union, intersection or difference needs two shapes or more");
    }

    double signedDistance(const Point<Dim>& x) const override { return nearest(x).second; }
    /// The normal of the part whose distance decides (turned inward for a subtracted part).
    Point<Dim> outwardNormal(const Point<Dim>& x, double h = 1e-6) const override {
        const std::size_t i = nearest(x).first;
        const Point<Dim> n = parts_[i]->outwardNormal(x, h);
        return how_ == Combine::DIFFERENCE && i > 0 ? -n : n;
    }
    Bounds<Dim> bounds() const override;
    Combine how() const { return how_; }
    const std::vector<SolidPtr<Dim>>& parts() const { return parts_; }

  private:
    /// The part that decides, and the distance.
    std::pair<std::size_t, double> nearest(const Point<Dim>& x) const {
        std::pair<std::size_t, double> best{0, parts_[0]->signedDistance(x)};
        for (std::size_t i = 1; i < parts_.size(); ++i) {
            const double d = parts_[i]->signedDistance(x);
            const bool better = how_ == Combine::UNION          ? d < best.second
                                : how_ == Combine::INTERSECTION ? d > best.second
                                                                : -d > best.second;
            if (better) best = {i, how_ == Combine::DIFFERENCE ? -d : d};
        }
        return best;
    }

    Combine how_;
    std::vector<SolidPtr<Dim>> parts_;
};

template <int Dim>
Bounds<Dim> Combination<Dim>::bounds() const {
    Bounds<Dim> b = parts_[0]->bounds();
    if (how_ == Combine::DIFFERENCE) return b;
    for (std::size_t i = 1; i < parts_.size(); ++i) {
        const Bounds<Dim> p = parts_[i]->bounds();
        for (int k = 0; k < Dim; ++k) {
            if (how_ == Combine::UNION)
                b.min[k] = std::min(b.min[k], p.min[k]), b.max[k] = std::max(b.max[k], p.max[k]);
            else
                b.min[k] = std::max(b.min[k], p.min[k]), b.max[k] = std::min(b.max[k], p.max[k]);
        }
    }
    return b;
}

}  // namespace num::geometry
