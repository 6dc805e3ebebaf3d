// What the solver and the run loop ask of a domain decomposition over several processes
// (parallel/domain_decomposition.hpp). A solver without one holds every particle and owns them
// all. With one, a storage holds the particles this process owns and halo copies of other
// processes' particles near them, in the order of sph/particle_order.hpp; the pair loops run over
// the owned particles only, and the halo copies are refreshed from their owners where a step
// reads what another process computed.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <tuple>
#include <vector>

#include "sph/equation_term.hpp"
#include "sph/storage.hpp"

namespace num::sph {

template <int Dim>
class IDecomposition {
  public:
    virtual ~IDecomposition() = default;

    /// Copies the quantities `only` (every quantity when empty) of the halo particles from their
    /// owners. The solver calls it after each term's initialize for what the term prepares
    /// (later terms may read it of a neighbour), for every quantity after all terms' initialize
    /// (before the pair loop reads neighbours) and after each pass's finalize, and after the
    /// post-step phase: a halo copy then equals its owner between steps.
    virtual void exchangeHalo(Storage<Dim>& storage, std::span<const QuantityId> only = {}) = 0;
    /// Per particle: 1 where this process owns it, 0 for a halo copy.
    virtual std::span<const char> owned() const = 0;
    /// Combines the limits of every process: the least time step of each criterion.
    virtual void combine(TimeStepLimits& limits) const = 0;
    /// The sum over every process (exact: integers).
    virtual std::int64_t sum(std::int64_t local) const = 0;
    /// Every process's values, by rank, on every process.
    virtual std::vector<std::vector<double>> allGather(std::span<const double> local) const = 0;
    /// Replaces the particles from `first` on (this process's additions) by every process's
    /// additions, by rank, so that every process holds them alike (as beforeStep expects).
    virtual void shareAdded(Storage<Dim>& storage, Size first) const = 0;
    /// Before a step (Run::step): migrates particles to their owners and rebuilds the halos when
    /// particles moved far enough, were added or removed (particlesChanged), or the storage is
    /// reordered (reorder: every process sets the keys of its particles and sorts them).
    /// Returns whether the storage changed (the solver's neighbour lists are then invalid).
    virtual bool beforeStep(Storage<Dim>& storage, bool reorder, bool particlesChanged) = 0;
};

/// Records of `size` doubles from every process, each beginning with its particle's ORDER_KEY
/// and PARTICLE_ID, in a single process's storage order (sph/particle_order.hpp), on every
/// process; without a decomposition (one process) `mine` itself, in the storage's order already.
template <int Dim>
std::vector<double> inSingleProcessOrder(std::vector<double> mine, std::size_t size,
                                         const IDecomposition<Dim>* decomposition) {
    if (!decomposition) return mine;
    std::vector<std::vector<double>> records;
    for (const std::vector<double>& theirs : decomposition->allGather(mine))
        for (std::size_t r = 0; r + size <= theirs.size(); r += size)
            records.emplace_back(theirs.begin() + std::ptrdiff_t(r),
                                 theirs.begin() + std::ptrdiff_t(r + size));
    std::sort(records.begin(), records.end(), [](const auto& a, const auto& b) {
        return std::tie(a[0], a[1]) < std::tie(b[0], b[1]);
    });
    mine.clear();
    for (const auto& r : records) mine.insert(mine.end(), r.begin(), r.end());
    return mine;
}

}  // namespace num::sph
