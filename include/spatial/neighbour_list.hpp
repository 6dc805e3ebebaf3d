// Verlet neighbour lists: for every particle, the candidates j within radius (1 + skin) of a
// build, i itself included, sorted by increasing j. A list is kept while no particle has moved
// more than skin radius / 2 since its build: every pair within radius is then still among the
// candidates (triangle inequality). Queries filter the candidates by the current distance, so
// the neighbours found and their order (increasing j) depend only on the current positions:
// never on the skin, on when the list was built or on the number of threads that built it.
// Rebuilt when a particle moved too far, when the number of particles changed, or after
// invalidate() (the caller reordered, added or removed particles; the displacement test alone
// would catch a renumbering too, as it compares positions index by index).
// The skin of each build may adapt to the flow (configure's maxSkin): a thin skin costs a
// rebuild as soon as the fastest particle has crossed half of it, a thick one more candidates
// to filter at every query. Each displacement test also measures the fastest particle's mean
// displacement per update since the build, u; the next build takes the skin with which the
// lists would last kListUpdates updates at that speed, s = 2 u kListUpdates / radius, within
// [skin, maxSkin] (the default 2D scene's fast second half: a build every 1.9 updates with a
// skin of 0.1, every 5 with the skin adapting up to 0.3, 0.91x the time: docs/performance.md).
// The candidates of each block of kChunk particles are one flat array of the exact size, filled
// by one task of the build (no copy into a global array). A particle's candidates are stored as
// its first one and the gaps to the next, each gap in bytes of 7 bits, the high ones first, every
// byte but the last with its top bit set (a gap below 128 takes one byte, below 16384 two): once
// the particles are ordered by cell, neighbours are near in index, so most gaps take one byte and
// only the jumps between rows of cells two or three (about a quarter of the memory of 32-bit
// indices). The cell grid they are found with is held during the build only. The positions of
// the build, for the displacement test, are kept in single precision (half the memory; the test
// allows for their rounding): the lists' content never depends on them.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "spatial/cell_grid.hpp"
#include "spatial/neighbour_list_codec.hpp"

namespace num {

template <int Dim>
class VerletList : private detail::VerletCodec {
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

    /// How many updates the lists of an adaptive skin are meant to last (the file comment).
    static constexpr double kListUpdates = 8;

    /// The support radius, the skin (a fraction of the radius; 0 rebuilds at every update), the
    /// largest skin it may grow to with the flow's speed (at most the skin: a fixed skin) and the
    /// domain. On a periodic axis the candidates' radius is capped at half the period (the cell
    /// grid's limit), which narrows the skin there.
    void configure(double radius, double skin, const Domain<Dim>& domain, double maxSkin = 0) {
        if (!(radius > 0)) throw std::invalid_argument("neighbour list: radius must be positive");
        if (!(skin >= 0)) throw std::invalid_argument("neighbour list: skin must be >= 0");
        if (!(maxSkin >= 0)) throw std::invalid_argument("neighbour list: maxSkin must be >= 0");
        radius_ = radius;
        domain_ = domain;
        minSkin_ = skin, maxSkin_ = std::max(skin, maxSkin);
        speed_ = 0;
        periodic_ = domain.anyPeriodic();
        setSkin(skin);
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
        setSkin(std::clamp(2 * speed_ * kListUpdates / radius_, minSkin_, maxSkin_));
        build(parallelFor);
        return true;
    }

    /// Calls f(j, dx, r2) for every particle j (i itself included) with r2 = |dx|^2 < radius^2,
    /// dx = x_i - x_j (the nearest image on periodic axes), in increasing j. dx_ij == -dx_ji bit
    /// for bit.
    template <class F>
    void forEachNeighbourOf(Index i, F&& f) const {
        forEachNeighbourOf(
            i, [](Index) { return true; }, std::forward<F>(f));
    }

    /// forEachNeighbourOf over the candidates j for which keep(j) holds only (checked before
    /// their distance is computed).
    template <class Keep, class F>
    void forEachNeighbourOf(Index i, Keep&& keep, F&& f) const {
        const double r2max = radius_ * radius_;
        const Vector xi = x_[i];
        forEachCandidate(i, [&](Index j) {
            if (!keep(j)) return;
            const Vector dx = pairVector(xi, x_[j]);
            const double r2 = normSqr(dx);
            if (r2 < r2max) f(j, dx, r2);
        });
    }

    /// Neighbour lists in flat arrays, filled by collect() (the cell grid's: j, dx = x_i - x_j and
    /// r2 = |dx|^2 of the first `count` entries are valid; the arrays may be longer).
    using Neighbours = typename CellGrid<Dim>::Neighbours;

    /// The neighbours j != i of particle i, in increasing j, into `out`; returns their number.
    /// The hot path of the gather pair loop: candidates are written unconditionally and kept by
    /// advancing the count, so the loop has no branch per candidate.
    Index collect(Index i, Neighbours& out) const {
        const Slot* s = slots(i);
        const Index n = slotCount(i), self = selfSlot(i);
        out.reserve(n + 1);
        // The candidates up to i itself, which is kept last (r2 = 0) and then dropped, then
        // those after it.
        Index count = collectRange(i, true, first_[i], s, s + self, out, 0);
        count -= Index(count > 0 && out.j[count - 1] == i);  // not kept if x_i is not finite
        return out.count = collectRange(i, false, i, s + self, s + n, out, count);
    }

    /// The neighbours j > i of particle i, in increasing j: every pair is found from exactly one
    /// of its particles. For symmetric pair loops.
    Index collectAfter(Index i, Neighbours& out) const {
        const Slot* s = slots(i);
        const Index n = slotCount(i);
        out.reserve(n);
        return out.count = collectRange(i, false, i, s + selfSlot(i), s + n, out, 0);
    }

    /// Calls g(j) for every candidate of particle i at the last build (within listRadius(), i
    /// included, increasing j): while the lists are kept, every neighbour of i is among them.
    template <class G>
    void forEachCandidate(Index i, G&& g) const {
        const Slot* s = slots(i);
        g(first_[i]);
        decode(first_[i], s, s + slotCount(i), g);
    }

    /// Candidates of particle i at the last build (within listRadius(), i included, increasing).
    std::vector<Index> candidates(Index i) const {
        std::vector<Index> out;
        forEachCandidate(i, [&](Index j) { out.push_back(j); });
        return out;
    }
    double radius() const { return radius_; }
    /// The candidates' radius of the last build (the support radius and its skin).
    double listRadius() const { return listRadius_; }
    /// How often the lists were built.
    std::size_t builds() const { return builds_; }

  private:
    static constexpr std::size_t kChunk = 512;  // particles per task of the build and the check
    using Stored = Vec<float, Dim>;
    static constexpr double kInfinity = std::numeric_limits<double>::infinity();
    static Vector toDouble(const Stored& p) {
        Vector out;
        for (int k = 0; k < Dim; ++k) out[k] = p[k];
        return out;
    }

    const Slot* slots(Index i) const { return parts_[i / kChunk].data() + start_[i]; }
    /// The number of slots of particle i: up to the next particle's, or to its chunk's end.
    Index slotCount(Index i) const {
        const std::size_t next = std::size_t(i) + 1;
        const Index end = next % kChunk != 0 && next < start_.size()
                              ? start_[next]
                              : Index(parts_[i / kChunk].size());
        return end - start_[i];
    }
    /// The first slot after i itself: the candidates after i are decoded from there.
    Index selfSlot(Index i) const { return self_[i]; }

    Vector pairVector(const Vector& xi, const Vector& xj) const {
        Vector dx;
        for (int k = 0; k < Dim; ++k) dx[k] = xi[k] - xj[k];
        return periodic_ ? domain_.minimumImage(dx) : dx;
    }

    /// The candidates of particle i within radius among j (if withFirst) and those decoded from
    /// the slots [b, e) after it, into `out` from entry n on; returns the new number of entries.
    Index collectRange(Index i, bool withFirst, Index j, const Slot* b, const Slot* e,
                       Neighbours& out, Index n) const {
        return periodic_ ? collectRange<true>(i, withFirst, j, b, e, out, n)
                         : collectRange<false>(i, withFirst, j, b, e, out, n);
    }

    template <bool Periodic>
    Index collectRange(Index i, bool withFirst, Index j, const Slot* b, const Slot* e,
                       Neighbours& out, Index n) const {
        const double r2max = radius_ * radius_;
        const Vector* X = x_.data();
        Index* J = out.j.data();
        Vector* DX = out.dx.data();
        double* R2 = out.r2.data();
        const Vector xi = X[i];
        Index count = n;  // a local count: stores through J may not alias it
        // Candidate k is written unconditionally and kept by advancing the count.
        const auto put = [=, this](Index k, Index at) {
            Vector dx;
            for (int d = 0; d < Dim; ++d) dx[d] = xi[d] - X[k][d];
            if constexpr (Periodic) dx = domain_.minimumImage(dx);
            const double r2 = normSqr(dx);
            J[at] = k, DX[at] = dx, R2[at] = r2;
            return Index(r2 < r2max);
        };
        if (withFirst) count += put(j, count);
        decode(j, b, e, [&](Index k) { count += put(k, count); });
        return count;
    }

    /// The candidates' radius for a skin (capped on periodic axes).
    void setSkin(double skin) {
        listRadius_ = radius_ * (1 + skin);
        for (int k = 0; k < Dim; ++k)
            if (domain_.periodic[k])
                listRadius_ = std::max(radius_, std::min(listRadius_, domain_.length(k) / 2));
    }

    /// Whether a particle moved more than half the skin since the build (a non-finite position
    /// counts as moved, so that the rebuild reports it). With an adaptive skin it also updates
    /// speed_, the largest displacement over the updates since the build.
    template <class ParallelFor>
    bool movedTooFar(ParallelFor& parallelFor) {
        ++updates_;
        const bool adaptive = maxSkin_ > minSkin_;
        if (!(allowed2_ > 0) && !adaptive) return true;
        const std::size_t n = x_.size(), chunks = (n + kChunk - 1) / kChunk;
        moved2_.assign(chunks, 0.0);
        parallelFor(chunks, [&](auto c0, auto c1) {
            for (std::size_t c = c0; c < std::size_t(c1); ++c) {
                double largest = 0;
                for (std::size_t i = c * kChunk; i < std::min(n, (c + 1) * kChunk); ++i) {
                    const double d2 = normSqr(pairVector(x_[i], toDouble(built_[i])));
                    largest = std::max(largest, std::isnan(d2) ? kInfinity : d2);
                }
                moved2_[c] = largest;
            }
        });
        const double largest =
            moved2_.empty() ? 0.0 : *std::max_element(moved2_.begin(), moved2_.end());
        speed_ = std::sqrt(largest) / double(updates_);
        return !(largest <= allowed2_);
    }

    template <class ParallelFor>
    void build(ParallelFor& parallelFor) {
        // The positions of the last build are not needed while building: released first, so
        // that they and the cell grid are never held at once (the peak memory of a build).
        valid_ = false;  // until the build completes (the grid throws on a non-finite position)
        std::vector<Stored>().swap(built_);
        const std::size_t n = x_.size(), chunks = (n + kChunk - 1) / kChunk;
        parts_.resize(chunks);
        start_.resize(n);
        first_.resize(n);
        self_.resize(n);
        {
            // Held during the build only: the queries read the candidates, never the grid.
            CellGrid<Dim> grid;
            grid.build(x_, listRadius_, domain_);  // throws on a non-finite position
            parallelFor(chunks, [&](auto c0, auto c1) {
                listCandidates(grid, std::size_t(c0), std::size_t(c1));
            });
        }
        storeBuiltPositions();
        valid_ = true;
        updates_ = 0;
        ++builds_;
    }

    /// Lists the candidates of the particles of chunks [c0, c1), from the grid's branch-free
    /// search (a branch per candidate would be mispredicted often).
    void listCandidates(const CellGrid<Dim>& grid, std::size_t c0, std::size_t c1) {
        const std::size_t n = x_.size();
        typename CellGrid<Dim>::Neighbours found;
        SortBuffers sortBuffers;
        // One chunk's slots, then copied into its array: sized exactly, not by the doubling of a
        // growing vector.
        std::vector<Slot> chunk;
        for (std::size_t c = c0; c < c1; ++c) {
            chunk.clear();
            for (std::size_t i = c * kChunk; i < std::min(n, (c + 1) * kChunk); ++i) {
                const Index m = grid.collect(
                    Index(i), [](Index) { return true; }, found);
                sortCandidates(found.j.data(), m, sortBuffers);
                const std::size_t begin = chunk.size();
                start_[i] = Index(begin);
                first_[i] = found.j[0];  // i itself is a candidate: m >= 1
                Index self = 0;
                for (Index k = 1; k < m; ++k) {
                    encodeGap(found.j[k - 1], found.j[k], chunk);
                    if (found.j[k] == Index(i)) self = Index(chunk.size() - begin);
                }
                self_[i] = self;
            }
            std::vector<Slot>& part = parts_[c];
            // Kept when it is at most 1/16 too large (the counts change little between builds),
            // else reallocated to the exact size.
            if (part.capacity() < chunk.size() ||
                part.capacity() > chunk.size() + chunk.size() / 16)
                part = std::vector<Slot>(chunk.begin(), chunk.end());
            else
                part.assign(chunk.begin(), chunk.end());
        }
    }

    /// Keeps the positions of the build in float and the displacement that a rebuild allows.
    void storeBuiltPositions() {
        const std::size_t n = x_.size();
        built_.resize(n);
        double extent = 0;
        for (std::size_t i = 0; i < n; ++i)
            for (int k = 0; k < Dim; ++k) {
                built_[i][k] = float(x_[i][k]);
                extent = std::max(extent, std::abs(x_[i][k]));
            }
        // Half the skin, less the rounding of the stored positions (half a unit in the last
        // place of a float, 2^-24 of a coordinate, in each of Dim components) and a margin for
        // the rounding of distances in double.
        const double stored = std::sqrt(double(Dim)) * 0x1p-24 * extent;
        const double allowed =
            0.5 * (listRadius_ - radius_) - stored - 1e-10 * (listRadius_ + extent);
        allowed2_ = allowed > 0 ? allowed * allowed : 0;
    }

    double radius_ = 0, listRadius_ = 0, allowed2_ = 0;
    double minSkin_ = 0, maxSkin_ = 0;  // the adaptive skin's range (equal: a fixed skin)
    double speed_ = 0;                  // the fastest displacement per update (adaptive skin)
    std::size_t updates_ = 0;           // updates since the last build
    Domain<Dim> domain_{};
    bool periodic_ = false, valid_ = false;
    std::size_t builds_ = 0;
    std::span<const Vector> x_;
    std::vector<Stored> built_;             // positions at the last build, in float
    std::vector<std::vector<Slot>> parts_;  // the candidates' gaps, chunk by chunk
    // Candidates of i: first_[i], then the gaps from slot start_[i] of parts_[i / kChunk] to the
    // next particle's; those after i from slot start_[i] + selfSlot(i) on, decoded from i.
    std::vector<Index> start_, first_, self_;
    std::vector<double> moved2_;  // per chunk of the displacement test: its largest, squared
};

}  // namespace num
