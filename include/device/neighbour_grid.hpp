// The device step's neighbour structure: particles sorted by cell every evaluation, and for each
// cell the range of sorted particles in it. A particle's neighbours are gathered from the 3^Dim
// cells around its own, visited in a fixed order (z outer, x inner: increasing cell key where
// no axis wraps), each cell's particles in sorted order; on periodic axes the cells wrap and the
// pair vector is the nearest image (as spatial/neighbour_list.hpp). No atomics: every particle
// writes only its own entries, so two runs are bitwise identical.
//
// Cells have the support radius as their least side. On a periodic axis the grid spans the
// domain (floor(L / radius) cells, at least one); on other axes it spans the particles' bounding
// box of this evaluation.
#pragma once

#include <cmath>
#include <string>

#include "device/execution.hpp"
#include "spatial/vec.hpp"

namespace num::device {

template <int Dim>
struct GridShape {
    using Point = num::Vec<double, Dim>;
    Point origin{};
    Point inverseCell{};
    Point length{};  ///< domain length on periodic axes
    int cells[Dim] = {};
    bool periodic[Dim] = {};
    double radius2 = 0;  ///< squared support radius: neighbours have r^2 < radius2

    NUMERICS_HD int cellOf(const Point& x, int k) const {
        const double c = ::floor((x[k] - origin[k]) * inverseCell[k]);
        return c < 0 ? 0 : c >= cells[k] ? cells[k] - 1 : int(c);
    }
    NUMERICS_HD CellKey keyOf(const int (&c)[Dim]) const {
        CellKey key = 0;
        for (int k = Dim - 1; k >= 0; --k) key = key * CellKey(cells[k]) + CellKey(c[k]);
        return key;
    }
    NUMERICS_HD CellKey keyOf(const Point& x) const {
        int c[Dim];
        for (int k = 0; k < Dim; ++k) c[k] = cellOf(x, k);
        return keyOf(c);
    }
    /// x_i - x_j, the nearest image on periodic axes (Domain::minimumImage).
    NUMERICS_HD Point pairVector(const Point& xi, const Point& xj) const {
        Point dx;
        for (int k = 0; k < Dim; ++k) dx[k] = xi[k] - xj[k];
        for (int k = 0; k < Dim; ++k)
            if (periodic[k]) dx[k] -= length[k] * ::nearbyint(dx[k] / length[k]);
        return dx;
    }
    std::size_t cellCount() const {
        std::size_t n = 1;
        for (int k = 0; k < Dim; ++k) n *= std::size_t(cells[k]);
        return n;
    }
};

/// Calls f(j, dx = x_i - x_j, r2) for every particle j != i with r2 < radius^2, in the order
/// described at the top. x: sorted positions; start / end: each cell's range of sorted indices.
template <int Dim, class F>
NUMERICS_HD void forEachNeighbour(const GridShape<Dim>& g, const Vec<double, Dim>* x,
                                  const Index* start, const Index* end, Index i, F&& f) {
    const Vec<double, Dim> xi = x[i];
    int c[Dim], lo[Dim], hi[Dim];
    for (int k = 0; k < Dim; ++k) {
        c[k] = g.cellOf(xi, k);
        if (g.periodic[k]) {  // the distinct wrapped cells: up to 3
            lo[k] = -1, hi[k] = (g.cells[k] < 3 ? g.cells[k] : 3) - 2;
        } else {
            lo[k] = c[k] > 0 ? -1 : 0, hi[k] = c[k] + 1 < g.cells[k] ? 1 : 0;
        }
    }
    int o[Dim];
    for (int k = 0; k < Dim; ++k) o[k] = lo[k];
    while (true) {
        int cell[Dim];
        for (int k = 0; k < Dim; ++k) {
            int n = c[k] + o[k];
            if (g.periodic[k]) n = (n + g.cells[k]) % g.cells[k];
            cell[k] = n;
        }
        const CellKey key = g.keyOf(cell);
        for (Index j = start[key]; j < end[key]; ++j) {
            if (j == i) continue;
            const Vec<double, Dim> dx = g.pairVector(xi, x[j]);
            const double r2 = normSqr(dx);
            if (r2 < g.radius2) f(j, dx, r2);
        }
        // The next offset, x fastest.
        int k = 0;
        while (k < Dim && o[k] == hi[k]) o[k] = lo[k], ++k;
        if (k == Dim) break;
        ++o[k];
    }
}

namespace detail {
template <int Dim>
struct CellKeys {  // (cell, tie) in one key: the order within a cell owes nothing to history
    GridShape<Dim> grid;
    const Vec<double, Dim>* x;
    const Index* tie;
    SortKey* keys;
    Index* order;
    NUMERICS_HD void operator()(Index i) const {
        keys[i] = SortKey(grid.keyOf(x[i])) << 32 | SortKey(tie ? tie[i] : i);
        order[i] = i;
    }
};
struct ClearCells {
    Index* start;
    Index* end;
    NUMERICS_HD void operator()(Index c) const { start[c] = 0, end[c] = 0; }
};
struct CellRanges {
    const SortKey* keys;
    Index n;
    Index* start;
    Index* end;
    NUMERICS_HD void operator()(Index k) const {
        const CellKey key = CellKey(keys[k] >> 32);
        if (k == 0 || CellKey(keys[k - 1] >> 32) != key) start[key] = k;
        if (k + 1 == n || CellKey(keys[k + 1] >> 32) != key) end[key] = k + 1;
    }
};
template <int Dim>
struct Component {
    const Vec<double, Dim>* x;
    int k;
    double* out;
    NUMERICS_HD void operator()(Index i) const { out[i] = x[i][k]; }
};
}  // namespace detail

/// The cell sort of an evaluation and the cells' ranges, in the memory of an execution.
template <int Dim, class Exec>
class NeighbourGrid {
  public:
    using Point = num::Vec<double, Dim>;
    /// radius: the kernel's support radius; domainMin / domainMax / periodic: the run's domain.
    NeighbourGrid(Exec& exec, double radius, Point domainMin, Point domainMax,
                  const bool (&periodic)[Dim])
        : exec_(exec),
          radius_(radius),
          domainMin_(domainMin),
          domainMax_(domainMax),
          keys_(exec),
          sortedKeys_(exec),
          order_(exec),
          sortedOrder_(exec),
          start_(exec),
          end_(exec),
          scratch_(exec) {
        for (int k = 0; k < Dim; ++k) periodic_[k] = periodic[k];
    }

    /// Sorts n particles at x by cell and, within a cell, by tie[i] (a number of the particle
    /// that stays with it, e.g. its index in the storage; nullptr: i). Afterwards order()[k] is
    /// the particle that goes to place k (the caller permutes its arrays by it), and after the
    /// permutation cell c holds the places start()[c] .. end()[c].
    void build(const Point* x, Index n, const Index* tie = nullptr) {
        shape(x, n);
        keys_.resize(n), sortedKeys_.resize(n), order_.resize(n), sortedOrder_.resize(n);
        exec_.forEach(n, detail::CellKeys<Dim>{grid_, x, tie, keys_.data(), order_.data()});
        int bits = 33;
        while (bits < 64 && (std::size_t(1) << (bits - 32)) < grid_.cellCount()) ++bits;
        exec_.sortPairs(keys_.data(), sortedKeys_.data(), order_.data(), sortedOrder_.data(), n,
                        bits);
        const Index cells = Index(grid_.cellCount());
        start_.resize(cells), end_.resize(cells);
        exec_.forEach(cells, detail::ClearCells{start_.data(), end_.data()});
        exec_.forEach(n, detail::CellRanges{sortedKeys_.data(), n, start_.data(), end_.data()});
    }

    const GridShape<Dim>& grid() const { return grid_; }
    const Index* order() const { return sortedOrder_.data(); }
    const Index* start() const { return start_.data(); }
    const Index* end() const { return end_.data(); }
    /// Device memory the grid holds [bytes].
    std::size_t bytes() const {
        return keys_.bytes() + sortedKeys_.bytes() + order_.bytes() + sortedOrder_.bytes() +
               start_.bytes() + end_.bytes() + scratch_.bytes();
    }

  private:
    void shape(const Point* x, Index n) {
        GridShape<Dim> g;
        g.radius2 = radius_ * radius_;
        scratch_.resize(n);
        double cells = 1;
        for (int k = 0; k < Dim; ++k) {
            g.periodic[k] = periodic_[k];
            if (periodic_[k]) {
                const double length = domainMax_[k] - domainMin_[k];
                const int c = std::max(1, int(std::floor(length / radius_)));
                g.origin[k] = domainMin_[k], g.length[k] = length;
                g.cells[k] = c, g.inverseCell[k] = c / length;
            } else {
                exec_.forEach(n, detail::Component<Dim>{x, k, scratch_.data()});
                const double lo = n ? exec_.minOf(scratch_.data(), n) : 0.0;
                const double hi = n ? exec_.maxOf(scratch_.data(), n) : 0.0;
                const double c = std::floor((hi - lo) / radius_) + 1;
                if (!(c < 1e9))
                    throw DeviceError("particles spread over " + std::to_string(hi - lo) +
                                      " m along axis " + std::to_string(k) +
                                      ": too far for the cell grid (the run went unstable?)");
                g.origin[k] = lo, g.cells[k] = int(c), g.inverseCell[k] = 1 / radius_;
            }
            cells *= g.cells[k];
        }
        if (!(cells < 4.0e9))
            throw DeviceError("the particles span " + std::to_string(cells) +
                              " cells, more than the cell grid holds (the run went unstable?)");
        grid_ = g;
    }

    Exec& exec_;
    double radius_;
    Point domainMin_, domainMax_;
    bool periodic_[Dim] = {};
    GridShape<Dim> grid_;
    Buffer<SortKey, Exec> keys_, sortedKeys_;
    Buffer<Index, Exec> order_, sortedOrder_, start_, end_;
    Buffer<double, Exec> scratch_;
};

}  // namespace num::device
