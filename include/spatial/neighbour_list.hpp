// Verlet neighbour lists: for every particle, the candidates j within radius (1 + skin) of a
// build, i itself included, sorted by increasing j. A list is kept while no particle has moved
// more than skin radius / 2 since its build: every pair within radius is then still among the
// candidates (triangle inequality). Queries filter the candidates by the current distance, so
// the neighbours found and their order (increasing j) depend only on the current positions:
// never on the skin, on when the list was built or on the number of threads that built it.
// Rebuilt when a particle moved too far, when the number of particles changed, or after
// invalidate() (the caller reordered, added or removed particles; the displacement test alone
// would catch a renumbering too, as it compares positions index by index).
// The candidates of each block of kChunk particles are one flat array of the exact size, filled
// by one task of the build (no copy into a global array). The cell grid they are found with is
// held during the build only.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "spatial/cell_grid.hpp"

namespace num {

template <int Dim>
class VerletList {
  public:
    using Vector = Vec<double, Dim>;
    using Index = std::uint32_t;

    /// Runs body(begin, end) over [0, n) on one thread: the default of update().
    struct Sequential {
        template <class Body>
        void operator()(std::size_t n, Body&& body) const {
            if (n > 0) body(std::size_t(0), n);
        }
    };

    /// The support radius, the skin (a fraction of the radius; 0 rebuilds at every update) and
    /// the domain. On a periodic axis the candidates' radius is capped at half the period (the
    /// cell grid's limit), which narrows the skin there.
    void configure(double radius, double skin, const Domain<Dim>& domain) {
        if (!(radius > 0)) throw std::invalid_argument("neighbour list: radius must be positive");
        if (!(skin >= 0)) throw std::invalid_argument("neighbour list: skin must be >= 0");
        radius_ = radius;
        domain_ = domain;
        listRadius_ = radius * (1 + skin);
        for (int k = 0; k < Dim; ++k)
            if (domain.periodic[k])
                listRadius_ = std::max(radius, std::min(listRadius_, domain.length(k) / 2));
        periodic_ = domain.anyPeriodic();
        valid_ = false;
    }

    /// Forces a rebuild at the next update (particles were reordered, added or removed).
    void invalidate() { valid_ = false; }

    /// Makes the lists valid for the positions x (kept by reference: they must stay alive and
    /// unchanged while queries run), rebuilding them if needed; returns whether it rebuilt.
    /// parallelFor(n, body) runs body(begin, end) over sub-ranges covering [0, n), in any order
    /// and on any threads: the lists are the same either way.
    template <class ParallelFor = Sequential>
    bool update(std::span<const Vector> x, ParallelFor&& parallelFor = {}) {
        x_ = x;
        if (valid_ && x.size() == built_.size() && !movedTooFar(parallelFor)) return false;
        build(parallelFor);
        return true;
    }

    /// Calls f(j, dx, r2) for every particle j (i itself included) with r2 = |dx|^2 < radius^2,
    /// dx = x_i - x_j (the nearest image on periodic axes), in increasing j. dx_ij == -dx_ji bit
    /// for bit.
    template <class F>
    void forEachNeighbourOf(Index i, F&& f) const {
        const double r2max = radius_ * radius_;
        const Vector xi = x_[i];
        const Index* cand = first(i);
        for (Index k = 0; k < count_[i]; ++k) {
            const Index j = cand[k];
            const Vector dx = pairVector(xi, x_[j]);
            const double r2 = normSqr(dx);
            if (r2 < r2max) f(j, dx, r2);
        }
    }

    /// Neighbour lists in flat arrays, filled by collect() (the cell grid's: j, dx = x_i - x_j and
    /// r2 = |dx|^2 of the first `count` entries are valid; the arrays may be longer).
    using Neighbours = typename CellGrid<Dim>::Neighbours;

    /// The neighbours j != i of particle i, in increasing j, into `out`; returns their number.
    /// The hot path of the gather pair loop: candidates are written unconditionally and kept by
    /// advancing the count, so the loop has no branch per candidate.
    Index collect(Index i, Neighbours& out) const {
        const Index* cand = first(i);
        out.reserve(count_[i]);
        const Index n = collectRange(i, cand, cand + self_[i], out, 0);
        return out.count = collectRange(i, cand + self_[i] + 1, cand + count_[i], out, n);
    }

    /// The neighbours j > i of particle i, in increasing j: every pair is found from exactly one
    /// of its particles. For symmetric pair loops.
    Index collectAfter(Index i, Neighbours& out) const {
        const Index* cand = first(i);
        out.reserve(count_[i]);
        return out.count = collectRange(i, cand + self_[i] + 1, cand + count_[i], out, 0);
    }

    /// Candidates of particle i at the last build (within listRadius(), i included, increasing).
    std::span<const Index> candidates(Index i) const { return {first(i), count_[i]}; }
    double radius() const { return radius_; }
    double listRadius() const { return listRadius_; }
    /// How often the lists were built.
    std::size_t builds() const { return builds_; }

  private:
    static constexpr std::size_t kChunk = 512;  // particles per task of the build and the check

    const Index* first(Index i) const { return parts_[i / kChunk].data() + start_[i]; }

    Vector pairVector(const Vector& xi, const Vector& xj) const {
        Vector dx;
        for (int k = 0; k < Dim; ++k) dx[k] = xi[k] - xj[k];
        return periodic_ ? domain_.minimumImage(dx) : dx;
    }

    Index collectRange(Index i, const Index* b, const Index* e, Neighbours& out, Index n) const {
        return periodic_ ? collectRange<true>(i, b, e, out, n)
                         : collectRange<false>(i, b, e, out, n);
    }

    template <bool Periodic>
    Index collectRange(Index i, const Index* b, const Index* e, Neighbours& out, Index n) const {
        const double r2max = radius_ * radius_;
        const Vector* X = x_.data();
        Index* J = out.j.data();
        Vector* DX = out.dx.data();
        double* R2 = out.r2.data();
        const Vector xi = X[i];
        Index count = n;  // a local count: stores through J may not alias it
        for (const Index* k = b; k < e; ++k) {
            const Index j = *k;
            Vector dx;
            for (int d = 0; d < Dim; ++d) dx[d] = xi[d] - X[j][d];
            if constexpr (Periodic) dx = domain_.minimumImage(dx);
            const double r2 = normSqr(dx);
            J[count] = j, DX[count] = dx, R2[count] = r2;
            count += Index(r2 < r2max);
        }
        return count;
    }

    /// Whether a particle moved more than half the skin since the build (a non-finite position
    /// counts as moved, so that the rebuild reports it).
    template <class ParallelFor>
    bool movedTooFar(ParallelFor& parallelFor) {
        if (!(allowed2_ > 0)) return true;
        const std::size_t n = x_.size(), chunks = (n + kChunk - 1) / kChunk;
        moved_.assign(chunks, 0);
        parallelFor(chunks, [&](auto c0, auto c1) {
            for (std::size_t c = c0; c < std::size_t(c1); ++c) {
                bool far = false;
                for (std::size_t i = c * kChunk; i < std::min(n, (c + 1) * kChunk); ++i)
                    far |= !(normSqr(pairVector(x_[i], built_[i])) <= allowed2_);
                moved_[c] = far;
            }
        });
        return std::find(moved_.begin(), moved_.end(), char(1)) != moved_.end();
    }

    template <class ParallelFor>
    void build(ParallelFor& parallelFor) {
        // The positions of the last build are not needed while building: released first, so
        // that they and the cell grid are never held at once (the peak memory of a build).
        valid_ = false;  // until the build completes (the grid throws on a non-finite position)
        std::vector<Vector>().swap(built_);
        const std::size_t n = x_.size(), chunks = (n + kChunk - 1) / kChunk;
        parts_.resize(chunks);
        start_.resize(n);
        count_.resize(n);
        self_.resize(n);
        {
            // Held during the build only: the queries read the candidates, never the grid.
            CellGrid<Dim> grid;
            grid.build(x_, listRadius_, domain_);  // throws on a non-finite position
            parallelFor(chunks, [&](auto c0, auto c1) {
                // The grid's branch-free search (a branch per candidate would be mispredicted
                // often).
                typename CellGrid<Dim>::Neighbours found;
                // One chunk's candidates, then copied into its array: sized exactly, not by the
                // doubling of a growing vector.
                std::vector<Index> chunk;
                for (std::size_t c = c0; c < std::size_t(c1); ++c) {
                    chunk.clear();
                    for (std::size_t i = c * kChunk; i < std::min(n, (c + 1) * kChunk); ++i) {
                        const auto begin = std::ptrdiff_t(chunk.size());
                        const Index m = grid.collect(
                            Index(i), [](Index) { return true; }, found);
                        chunk.insert(chunk.end(), found.j.begin(), found.j.begin() + m);
                        std::sort(chunk.begin() + begin, chunk.end());
                        start_[i] = Index(begin);
                        count_[i] = Index(chunk.size() - std::size_t(begin));
                        self_[i] =
                            Index(std::lower_bound(chunk.begin() + begin, chunk.end(), Index(i)) -
                                  (chunk.begin() + begin));
                    }
                    std::vector<Index>& part = parts_[c];
                    // Kept when it is at most 1/16 too large (the counts change little between
                    // builds), else reallocated to the exact size.
                    if (part.capacity() < chunk.size() ||
                        part.capacity() > chunk.size() + chunk.size() / 16)
                        part = std::vector<Index>(chunk.begin(), chunk.end());
                    else
                        part.assign(chunk.begin(), chunk.end());
                }
            });
        }
        built_.assign(x_.begin(), x_.end());
        // Half the skin, less a margin for the rounding of distances at the particles'
        // coordinates (no margin is needed in exact arithmetic).
        double extent = 0;
        for (const Vector& p : built_)
            for (int k = 0; k < Dim; ++k) extent = std::max(extent, std::abs(p[k]));
        const double allowed = 0.5 * (listRadius_ - radius_) - 1e-10 * (listRadius_ + extent);
        allowed2_ = allowed > 0 ? allowed * allowed : 0;
        valid_ = true;
        ++builds_;
    }

    double radius_ = 0, listRadius_ = 0, allowed2_ = 0;
    Domain<Dim> domain_{};
    bool periodic_ = false, valid_ = false;
    std::size_t builds_ = 0;
    std::span<const Vector> x_;
    std::vector<Vector> built_;              // positions at the last build
    std::vector<std::vector<Index>> parts_;  // candidates of each chunk
    // Candidates of i: count_[i] from start_[i] in parts_[i / kChunk]; i itself at self_[i].
    std::vector<Index> start_, count_, self_;
    std::vector<char> moved_;
};

}  // namespace num
