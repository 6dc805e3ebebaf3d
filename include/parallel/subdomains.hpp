// One box per process by recursive coordinate bisection of the particles (Berger & Bokhari
// 1987, IEEE Trans. Comput. 36, 570): the points are cut across the longest axis of their
// bounding box so that each side holds points in proportion to its processes, and each side
// again, until one process is left. The boxes tile space: unbounded on open axes, the domain on
// periodic ones. The cuts depend on the set of points only, never on their order, so every
// process given the same points computes the same boxes.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "spatial/cell_grid.hpp"

namespace num::parallel {

template <int Dim>
class Subdomains {
  public:
    using Point = num::Vec<double, Dim>;

    explicit Subdomains(const Domain<Dim>& domain) : domain_(domain) {}

    /// Cuts `points` (wrapped on periodic axes) into `parts` boxes holding about as many each.
    void bisect(std::vector<Point> points, int parts) {
        boxes_.assign(std::size_t(parts), wholeSpace());
        bisect(points.begin(), points.end(), 0, parts, wholeSpace());
    }

    /// The box that holds x (wrapped on periodic axes), or -1 (a position that is not finite).
    int owner(const Point& x) const {
        for (int r = 0; r < int(boxes_.size()); ++r) {
            bool inside = true;
            for (int k = 0; k < Dim && inside; ++k)
                inside = x[k] >= boxes_[r].lo[k] && x[k] < boxes_[r].hi[k];
            if (inside) return r;
        }
        return -1;
    }

    /// The distance from x to box r, through the periodic images.
    double distance(const Point& x, int r) const {
        const Bounds& b = boxes_[std::size_t(r)];
        double d2 = 0;
        for (int k = 0; k < Dim; ++k) {
            auto gap = [&](double c) {
                return c < b.lo[k] ? b.lo[k] - c : c > b.hi[k] ? c - b.hi[k] : 0.0;
            };
            double g = gap(x[k]);
            if (domain_.periodic[k])
                g = std::min({g, gap(x[k] - domain_.length(k)), gap(x[k] + domain_.length(k))});
            d2 += g * g;
        }
        return std::sqrt(d2);
    }

  private:
    struct Bounds {
        Point lo, hi;
    };

    /// The bounds a box starts from: the domain on periodic axes, unbounded on the others.
    Bounds wholeSpace() const {
        Bounds b;
        for (int k = 0; k < Dim; ++k) {
            const double inf = std::numeric_limits<double>::infinity();
            b.lo[k] = domain_.periodic[k] ? domain_.min[k] : -inf;
            b.hi[k] = domain_.periodic[k] ? domain_.max[k] : inf;
        }
        return b;
    }

    /// Splits box `box`, holding the points [begin, end), among the processes [first, first +
    /// parts): points below the cut go to the first parts / 2.
    template <class It>
    void bisect(It begin, It end, int first, int parts, Bounds box) {
        if (parts == 1) {
            boxes_[std::size_t(first)] = box;
            return;
        }
        const auto n = std::size_t(end - begin);
        int axis = 0;
        if (n > 0) {
            Point lo = *begin, hi = *begin;
            for (It p = begin; p != end; ++p)
                for (int k = 0; k < Dim; ++k)
                    lo[k] = std::min(lo[k], (*p)[k]), hi[k] = std::max(hi[k], (*p)[k]);
            for (int k = 1; k < Dim; ++k)
                if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
        }
        const int below = parts / 2;
        double cut = 0;
        if (n > 0) {
            // The point of rank n * below / parts along the axis.
            const auto at = begin + std::ptrdiff_t(std::min(n * std::size_t(below) / parts, n - 1));
            std::nth_element(begin, at, end,
                             [axis](const Point& a, const Point& b) { return a[axis] < b[axis]; });
            cut = (*at)[axis];
        } else {
            // No points: the middle of the box, or its finite side.
            const double lo = box.lo[axis], hi = box.hi[axis];
            cut = std::isfinite(lo) && std::isfinite(hi) ? 0.5 * (lo + hi)
                  : std::isfinite(lo)                    ? lo
                  : std::isfinite(hi)                    ? hi
                                                         : 0.0;
        }
        const It middle = std::partition(begin, end, [&](const Point& p) { return p[axis] < cut; });
        Bounds left = box, right = box;
        left.hi[axis] = cut, right.lo[axis] = cut;
        bisect(begin, middle, first, below, left);
        bisect(middle, end, first + below, parts - below, right);
    }

    Domain<Dim> domain_;
    std::vector<Bounds> boxes_;
};

}  // namespace num::parallel
