// Neighbour search on a uniform cell grid (cell size >= search radius), built by counting sort.
// Borrows positions, knows nothing of physics. Periodic in any subset of axes: on a periodic
// axis, pair vectors are the nearest image (the period must be at least twice the radius).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "spatial/vec.hpp"

namespace num {

/// The simulation box and which of its axes are periodic.
template <int Dim>
struct Domain {
    Vec<double, Dim> min{}, max{};
    std::array<bool, Dim> periodic{};

    double length(int k) const { return max[k] - min[k]; }
    bool anyPeriodic() const {
        for (bool p : periodic)
            if (p) return true;
        return false;
    }
    /// Nearest periodic image of a pair vector.
    Vec<double, Dim> minimumImage(Vec<double, Dim> dx) const {
        for (int k = 0; k < Dim; ++k)
            if (periodic[k]) dx[k] -= length(k) * std::nearbyint(dx[k] / length(k));
        return dx;
    }
    /// Maps a position into [min, max) on periodic axes.
    Vec<double, Dim> wrap(Vec<double, Dim> x) const {
        for (int k = 0; k < Dim; ++k)
            if (periodic[k]) {
                x[k] = min[k] + std::fmod(x[k] - min[k], length(k));
                if (x[k] < min[k]) x[k] += length(k);
                if (x[k] >= max[k]) x[k] = min[k];
            }
        return x;
    }
};

template <int Dim>
class CellGrid {
public:
    using Vector = Vec<double, Dim>;
    using Index = std::uint32_t;

    /// Sorts the particles into cells of at least `radius`. Non-periodic axes span the particles'
    /// bounding box; periodic axes span the domain.
    void build(std::span<const Vector> x, double radius, const Domain<Dim>& domain) {
        if (!(radius > 0)) throw std::invalid_argument("cell grid: radius must be positive");
        radius_ = radius;
        domain_ = domain;
        const Index n = Index(x.size());
        Vector lo = Vector::filled(0), hi = Vector::filled(0);
        if (n > 0) lo = hi = x[0];
        for (const Vector& p : x)
            for (int k = 0; k < Dim; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
        // Never more than about 8 cells per particle: a stray particle far away enlarges the
        // cells rather than exhausting memory.
        const double maxCells = 8.0 * std::max<Index>(n, 64);
        double cellSize = radius;
        for (;;) {
            double total = 1;
            for (int k = 0; k < Dim; ++k) {
                if (domain.periodic[k]) {
                    const double L = domain.length(k);
                    if (L < 2 * radius)
                        throw std::invalid_argument("cell grid: periodic length is below twice the radius");
                    cells_[k] = std::max(1, int(std::floor(L / cellSize)));
                    origin_[k] = domain.min[k];
                    size_[k] = L / cells_[k];
                } else {
                    cells_[k] = std::max(1, int(std::floor((hi[k] - lo[k]) / cellSize)) + 1);
                    origin_[k] = lo[k];
                    size_[k] = cellSize;
                }
                total *= cells_[k];
            }
            if (total <= maxCells) break;
            cellSize *= 2;
        }
        Index total = 1;
        for (int k = 0; k < Dim; ++k) total *= Index(cells_[k]);

        cellOf_.resize(n);
        start_.assign(total + 1, 0);
        for (Index i = 0; i < n; ++i) {
            cellOf_[i] = cellIndex(cellCoords(x[i]));
            ++start_[cellOf_[i] + 1];
        }
        for (Index c = 0; c < total; ++c) start_[c + 1] += start_[c];
        sorted_.resize(n);
        std::vector<Index> fill(start_.begin(), start_.end() - 1);
        for (Index i = 0; i < n; ++i) sorted_[fill[cellOf_[i]]++] = i;
        x_ = x;
    }

    /// Calls f(j, dx, r2) for every particle j (i itself included) with r2 = |dx|^2 < radius^2,
    /// dx = x_i - x_j (nearest image). Cells are visited in a fixed order, and particles within
    /// a cell in increasing index, so the order of neighbours is deterministic.
    template <class F>
    void forEachNeighbour(const Vector& xi, F&& f) const {
        const std::array<int, Dim> c = cellCoords(xi);
        std::array<std::array<int, 3>, Dim> visit;
        std::array<int, Dim> count{};
        for (int k = 0; k < Dim; ++k) {
            for (int o = -1; o <= 1; ++o) {
                int cc = c[k] + o;
                if (domain_.periodic[k]) cc = (cc % cells_[k] + cells_[k]) % cells_[k];
                else if (cc < 0 || cc >= cells_[k]) continue;
                bool seen = false;
                for (int m = 0; m < count[k]; ++m) seen |= visit[k][m] == cc;
                if (!seen) visit[k][count[k]++] = cc;
            }
        }
        const double r2max = radius_ * radius_;
        const bool periodic = domain_.anyPeriodic();
        std::array<int, Dim> idx{};
        for (;;) {
            std::array<int, Dim> cell;
            for (int k = 0; k < Dim; ++k) cell[k] = visit[k][idx[k]];
            const Index ci = cellIndex(cell);
            for (Index s = start_[ci]; s < start_[ci + 1]; ++s) {
                const Index j = sorted_[s];
                Vector dx = xi - x_[j];
                if (periodic) dx = domain_.minimumImage(dx);
                const double r2 = normSqr(dx);
                if (r2 < r2max) f(j, dx, r2);
            }
            int k = 0;
            while (k < Dim && ++idx[k] == count[k]) idx[k++] = 0;
            if (k == Dim) break;
        }
    }

    /// Particle indices ordered by cell: the permutation that makes neighbours near in memory.
    const std::vector<Index>& sortedOrder() const { return sorted_; }
    double radius() const { return radius_; }

private:
    std::array<int, Dim> cellCoords(const Vector& p) const {
        std::array<int, Dim> c;
        for (int k = 0; k < Dim; ++k) {
            const int v = int(std::floor((p[k] - origin_[k]) / size_[k]));
            c[k] = std::clamp(v, 0, cells_[k] - 1);
        }
        return c;
    }
    Index cellIndex(const std::array<int, Dim>& c) const {
        Index id = 0;
        for (int k = Dim - 1; k >= 0; --k) id = id * Index(cells_[k]) + Index(c[k]);
        return id;
    }

    double radius_ = 0;
    Domain<Dim> domain_{};
    std::array<int, Dim> cells_{};
    Vector origin_{}, size_{};
    std::vector<Index> cellOf_, start_, sorted_;
    std::span<const Vector> x_;
};

}  // namespace num
