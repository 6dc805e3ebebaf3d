// Neighbour search on a uniform cell grid (cell size >= radius / reach; a query visits 2 reach + 1
// cells per axis), built by counting sort. 3D uses cells of half the radius (reach 2: 42 % fewer
// candidates, measured 9 % faster on the 3D dam break); 1D and 2D cells of one radius (half-radius
// cells read 30 % fewer candidates in 2D but measured 6 % slower, and need a 4 times larger cell
// table; see docs/performance.md).
// Copies the positions in cell order, knows nothing of physics. Periodic in any subset of axes: on
// a periodic axis, pair vectors are the nearest image (the period must be at least twice the
// radius).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "spatial/vec.hpp"

namespace num {

/// The simulation box and which of its axes are periodic.
/// x mapped into [lo, hi) on a periodic axis (the CPU's Domain::wrap and the device's wrap).
NUMERICS_HD_INLINE double wrapIntoPeriod(double x, double lo, double hi) {
    const double length = hi - lo;
    x = lo + hd::fmod(x - lo, length);
    if (x < lo) x += length;
    if (x >= hi) x = lo;
    return x;
}

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
            if (periodic[k]) x[k] = wrapIntoPeriod(x[k], min[k], max[k]);
        return x;
    }
};

template <int Dim>
class CellGrid {
  public:
    using Vector = Vec<double, Dim>;
    using Index = std::uint32_t;

    /// Sorts the particles into cells of at least radius / reach. Non-periodic axes span the
    /// particles' bounding box; periodic axes span the domain.
    void build(std::span<const Vector> x, double radius, const Domain<Dim>& domain) {
        if (!(radius > 0)) throw std::invalid_argument("cell grid: radius must be positive");
        radius_ = radius;
        domain_ = domain;
        Vector lo, hi;
        boundingBox(x, lo, hi);
        layCells(Index(x.size()), lo, hi);
        Index total = 1;
        for (int k = 0; k < Dim; ++k) total *= Index(cells_[k]);
        anyPerPair_ = false;
        for (int k = 0; k < Dim; ++k) {
            perPair_[k] = domain.periodic[k] && cells_[k] < 2 * reach + 1;
            anyPerPair_ |= perPair_[k];
        }
        sortIntoCells(x, total);
    }

    /// Calls f(j, dx, r2) for every particle j (itself too, if xi is a particle's position)
    /// with r2 = |dx|^2 < radius^2, dx = xi - x_j for the nearest periodic image of x_j. Cells
    /// are visited in a fixed order, and particles within a cell in increasing index, so the
    /// order of neighbours is deterministic. Pair vectors are exactly antisymmetric:
    /// dx_ij == -dx_ji bit for bit.
    template <class F>
    void forEachNeighbour(const Vector& xi, F&& f) const {
        Vector p = xi;
        std::array<int, Dim> c;
        locate(p, c);
        visitCells(p, c, std::forward<F>(f));
    }

    /// forEachNeighbour for particle i of the last build (faster: its cell is known).
    template <class F>
    void forEachNeighbourOf(Index i, F&& f) const {
        std::array<int, Dim> c;
        Index flat = cellOf_[i];
        for (int k = 0; k < Dim; ++k) c[k] = int(flat % Index(cells_[k])), flat /= Index(cells_[k]);
        visitCells(sortedX_[slot_[i]], c, std::forward<F>(f));
    }

    /// Neighbour lists in flat arrays, filled by collect(): j, dx = x_i - x_j and r2 = |dx|^2 of
    /// the first `count` entries are valid (the arrays may be longer).
    struct Neighbours {
        std::vector<Index> j;
        std::vector<Vector> dx;
        std::vector<double> r2;
        Index count = 0;
        void reserve(std::size_t n) {
            if (j.size() < n) j.resize(2 * n), dx.resize(2 * n), r2.resize(2 * n);
        }
    };

    /// The neighbours j of particle i of the last build for which keep(j) holds, in the order of
    /// forEachNeighbourOf, into `out`; returns their number. The hot path of the pair loop:
    /// candidates are written unconditionally and kept by advancing the count, so the loop
    /// has no branch per candidate.
    template <class Keep>
    Index collect(Index i, Keep&& keep, Neighbours& out) const {
        return collectFrom(i, keep, out, 0);
    }

    /// The neighbours of particle i that come after it in cell order (sortedOrder()), into
    /// `out`: every pair is found from exactly one of its particles, and only about half the
    /// candidates are read (the cells before i's cell are skipped). For symmetric pair loops.
    Index collectAfter(Index i, Neighbours& out) const {
        const Index own = slot_[i];
        if (anyPerPair_)
            return collectFrom(
                i, [&](Index j) { return slot_[j] > own; }, out, own + 1);
        return collectFrom(
            i, [](Index) { return true; }, out, own + 1);
    }

    /// Particle indices ordered by cell: the permutation that makes neighbours near in memory.
    const std::vector<Index>& sortedOrder() const { return sorted_; }
    double radius() const { return radius_; }

  private:
    /// The particles' bounding box (zero for none), refusing a non-finite position.
    static void boundingBox(std::span<const Vector> x, Vector& lo, Vector& hi) {
        const Index n = Index(x.size());
        lo = hi = Vector::filled(0);
        if (n > 0) lo = hi = x[0];
        for (Index i = 0; i < n; ++i)
            for (int k = 0; k < Dim; ++k) {
                if (!std::isfinite(x[i][k]))
                    throw std::invalid_argument("cell grid: particle " + std::to_string(i) +
                                                " has a non-finite position");
                lo[k] = std::min(lo[k], x[i][k]), hi[k] = std::max(hi[k], x[i][k]);
            }
    }

    /// Sets the cells' count, origin and size on each axis for n particles in [lo, hi].
    void layCells(Index n, const Vector& lo, const Vector& hi) {
        // Never more than about 8 cells per particle: a stray particle far away enlarges the
        // cells rather than exhausting memory.
        const double maxCells = 8.0 * std::max<Index>(n, 64);
        // Cells are a hair larger than radius / reach so that rounding in the cell coordinate of a
        // particle on a cell border can never put two neighbours two cells apart.
        double cellSize = radius_ / reach * (1 + 1e-8);
        for (;;) {
            double total = 1;
            for (int k = 0; k < Dim; ++k) {
                if (domain_.periodic[k]) {
                    const double L = domain_.length(k);
                    if (L < 2 * radius_)
                        throw std::invalid_argument(
                            "cell grid: periodic length is below twice the radius");
                    cells_[k] = std::max(1, int(std::floor(L / cellSize)));
                    if (L / cells_[k] < cellSize) cells_[k] = std::max(1, cells_[k] - 1);
                    origin_[k] = domain_.min[k];
                    size_[k] = L / cells_[k];
                } else {
                    cells_[k] = std::max(1, int(std::floor((hi[k] - lo[k]) / cellSize)) + 1);
                    origin_[k] = lo[k];
                    size_[k] = cellSize;
                }
                total *= cells_[k];
            }
            if (total <= maxCells) return;
            cellSize *= 2;
        }
    }

    /// Counts the particles per cell and copies their positions in cell order, so that the search
    /// reads them contiguously. On periodic axes each particle is placed at the image whose cell
    /// it is sorted into, so that the image shift of a neighbour follows from the cell offset
    /// alone. The image is found again when copying (no array of them: less peak memory).
    void sortIntoCells(std::span<const Vector> x, Index total) {
        const Index n = Index(x.size());
        cellOf_.resize(n);
        start_.assign(total + 1, 0);
        for (Index i = 0; i < n; ++i) {
            Vector placed = x[i];
            std::array<int, Dim> c;
            locate(placed, c);
            cellOf_[i] = cellIndex(c);
            ++start_[cellOf_[i] + 1];
        }
        for (Index c = 0; c < total; ++c) start_[c + 1] += start_[c];
        sorted_.resize(n);
        slot_.resize(n);
        sortedX_.resize(n);
        std::vector<Index> fill(start_.begin(), start_.end() - 1);
        for (Index i = 0; i < n; ++i) {
            const Index s = fill[cellOf_[i]]++;
            sorted_[s] = i;
            slot_[i] = s;
            Vector placed = x[i];
            std::array<int, Dim> c;
            locate(placed, c);
            sortedX_[s] = placed;
        }
    }

    /// collect() over the candidates of slot >= firstSlot only (all of them on axes whose
    /// images are found per pair: keep must then do the filtering).
    template <class Keep>
    Index collectFrom(Index i, Keep&& keep, Neighbours& out, Index firstSlot) const {
        std::array<int, Dim> c;
        Index flat = cellOf_[i];
        for (int k = 0; k < Dim; ++k) c[k] = int(flat % Index(cells_[k])), flat /= Index(cells_[k]);
        const Vector p = sortedX_[slot_[i]];
        const double r2max = radius_ * radius_;
        Index n = 0;
        if (anyPerPair_) {
            visitCells(p, c, [&](Index j, const Vector& dx, double r2) {
                if (!keep(j)) return;
                out.reserve(n + 1);
                out.j[n] = j, out.dx[n] = dx, out.r2[n] = r2;
                ++n;
            });
            return out.count = n;
        }
        forEachRun(c, [&](Index b, Index e, const Vector& sh) {
            b = std::max(b, firstSlot);
            if (b >= e) return;
            out.reserve(n + (e - b));
            Index* J = out.j.data();
            Vector* DX = out.dx.data();
            double* R2 = out.r2.data();
            const Vector* X = sortedX_.data();
            const Index* order = sorted_.data();
            const Vector q = p;
            auto keepJ = keep;
            Index count = n;  // a local count: stores through J may not alias it
            for (Index s = b; s < e; ++s) {
                Vector dx;
                for (int k = 0; k < Dim; ++k) dx[k] = (q[k] - X[s][k]) + sh[k];
                const double r2 = normSqr(dx);
                const Index j = order[s];
                J[count] = j, DX[count] = dx, R2[count] = r2;
                count += Index((r2 < r2max) & bool(keepJ(j)));
            }
            n = count;
        });
        return out.count = n;
    }

    /// The cell of p; on periodic axes p is moved to the image that lies in that cell.
    void locate(Vector& p, std::array<int, Dim>& c) const {
        for (int k = 0; k < Dim; ++k) {
            if (domain_.periodic[k]) {
                const double L = domain_.length(k);
                double y = p[k];
                if (y < domain_.min[k] || y >= domain_.max[k]) {
                    y = domain_.min[k] + std::fmod(y - domain_.min[k], L);
                    if (y < domain_.min[k]) y += L;
                }
                double v = std::floor((y - origin_[k]) / size_[k]);
                if (v >= cells_[k]) v = 0, y -= L;  // rounding at the upper end: the image at min
                if (v < 0) v = 0;
                p[k] = y;
                c[k] = int(v);
            } else {
                const double v = std::floor((p[k] - origin_[k]) / size_[k]);
                c[k] = int(std::clamp(v, 0.0, double(cells_[k] - 1)));
            }
        }
    }

    /// Calls g(begin, end, shift) for runs of slots [begin, end) of the cells around cell c, with
    /// the image shift of the run; cells adjacent along axis 0 with the same shift form one run.
    /// Runs come in the fixed cell order of visitCells.
    template <class G>
    void forEachRun(const std::array<int, Dim>& c, G&& g) const {
        // The cells to visit on each axis and the image shift of each: an axis with fewer than
        // 2 reach + 1 cells may meet a cell from both sides, so its image is found per pair.
        std::array<std::array<int, 2 * reach + 1>, Dim> visit;
        std::array<std::array<double, 2 * reach + 1>, Dim> shift;
        std::array<int, Dim> count{};
        for (int k = 0; k < Dim; ++k) {
            for (int o = -reach; o <= reach; ++o) {
                int cc = c[k] + o;
                double s = 0;
                if (domain_.periodic[k]) {
                    if (cc < 0)
                        cc += cells_[k], s = domain_.length(k);
                    else if (cc >= cells_[k])
                        cc -= cells_[k], s = -domain_.length(k);
                } else if (cc < 0 || cc >= cells_[k]) {
                    continue;
                }
                bool seen = false;
                for (int m = 0; m < count[k]; ++m) seen |= visit[k][m] == cc;
                if (seen) continue;
                visit[k][count[k]] = cc;
                shift[k][count[k]++] = perPair_[k] ? 0.0 : s;
            }
        }
        // Runs along axis 0: consecutive cells with equal shifts.
        std::array<int, 2 * reach + 1> runFirst{}, runLast{};
        int runs = 0;
        for (int m = 0; m < count[0]; ++m) {
            if (runs > 0 && visit[0][m] == visit[0][runLast[runs - 1]] + 1 &&
                shift[0][m] == shift[0][runLast[runs - 1]]) {
                runLast[runs - 1] = m;
                continue;
            }
            runFirst[runs] = runLast[runs] = m;
            ++runs;
        }
        std::array<int, Dim> idx{};  // idx[0] counts runs
        for (;;) {
            std::array<int, Dim> first, last;
            Vector sh;
            first[0] = visit[0][runFirst[idx[0]]], last[0] = visit[0][runLast[idx[0]]];
            sh[0] = shift[0][runFirst[idx[0]]];
            for (int k = 1; k < Dim; ++k)
                first[k] = last[k] = visit[k][idx[k]], sh[k] = shift[k][idx[k]];
            g(start_[cellIndex(first)], start_[cellIndex(last) + 1], sh);
            int k = 0;
            while (k < Dim && ++idx[k] == (k == 0 ? runs : count[k])) idx[k++] = 0;
            if (k == Dim) break;
        }
    }

    template <class F>
    void visitCells(const Vector& p, const std::array<int, Dim>& c, F&& f) const {
        const double r2max = radius_ * radius_;
        forEachRun(c, [&](Index b, Index e, const Vector& sh) {
            for (Index s = b; s < e; ++s) {
                const Vector& xj = sortedX_[s];
                Vector dx;
                for (int k = 0; k < Dim; ++k) {
                    dx[k] = (p[k] - xj[k]) + sh[k];
                    if (perPair_[k])
                        dx[k] -= domain_.length(k) * std::nearbyint(dx[k] / domain_.length(k));
                }
                const double r2 = normSqr(dx);
                if (r2 < r2max) f(sorted_[s], dx, r2);
            }
        });
    }

    Index cellIndex(const std::array<int, Dim>& c) const {
        Index id = 0;
        for (int k = Dim - 1; k >= 0; --k) id = id * Index(cells_[k]) + Index(c[k]);
        return id;
    }

    /// Cells visited on each side of a particle's cell along each axis.
    static constexpr int reach = Dim == 3 ? 2 : 1;
    double radius_ = 0;
    Domain<Dim> domain_{};
    std::array<int, Dim> cells_{};
    Vector origin_{}, size_{};
    std::vector<Index> cellOf_, start_, sorted_, slot_;  // slot_: inverse of sorted_
    std::vector<Vector> sortedX_;  // positions in cell order, at the image of their cell
    std::array<bool, Dim>
        perPair_{};  // periodic axes of fewer than 2 reach + 1 cells: image per pair
    bool anyPerPair_ = false;
};

}  // namespace num
