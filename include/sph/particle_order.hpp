// The order of the particles in a storage, which fixes the order of every sum over neighbours
// (the neighbour lists come in increasing index): by ORDER_KEY, then PARTICLE_ID. ORDER_KEY is
// the particle's cell on a grid fixed by the domain and the kernel radius, set at each
// reordering (Run's "reorder_every"); particles added since (emitters) carry kNewParticleKey and
// come last, by id. A key depends on the particle alone, never on which particles a storage
// holds, so the particles of any subset (one process's share and its halo,
// parallel/domain_decomposition.hpp) are in the same relative order as in the whole: the sums,
// and so the results, are bitwise those of a single process.
#pragma once

#include <algorithm>
#include <climits>
#include <cmath>
#include <numeric>
#include <tuple>
#include <vector>

#include "spatial/cell_grid.hpp"
#include "sph/storage.hpp"

namespace num::sph {

/// ORDER_KEY of particles added since the last reordering: after every cell.
inline constexpr int kNewParticleKey = INT_MAX;

/// Adds PARTICLE_ID (0, 1, ... in storage order) and ORDER_KEY (0: the storage order) to a
/// storage that lacks them.
template <int Dim>
void ensureParticleIds(Storage<Dim>& s) {
    if (!s.has(QuantityId::PARTICLE_ID)) {
        std::vector<int> id(s.size());
        std::iota(id.begin(), id.end(), 0);
        s.template insert<int>(QuantityId::PARTICLE_ID, OrderEnum::ZERO, std::move(id));
    }
    if (!s.has(QuantityId::ORDER_KEY))
        s.template insert<int>(QuantityId::ORDER_KEY, OrderEnum::ZERO, 0);
}

/// The ordering grid: cells of the kernel's support radius (doubled while there would be more
/// than 2^30) over the domain widened by 8 radii; positions beyond fall in the edge cells.
template <int Dim>
class OrderGrid {
  public:
    OrderGrid(const Domain<Dim>& domain, double radius) {
        double cell = radius;
        for (;;) {
            double total = 1;
            for (int k = 0; k < Dim; ++k) {
                origin_[k] = domain.min[k] - 8 * radius;
                cells_[k] = std::max(1.0, std::ceil((domain.length(k) + 16 * radius) / cell));
                total *= cells_[k];
            }
            if (total <= double(1 << 30)) break;
            cell *= 2;
        }
        cell_ = cell;
    }
    /// The cell of position x, x fastest.
    int key(const Vec<double, Dim>& x) const {
        long long key = 0;
        for (int k = Dim - 1; k >= 0; --k) {
            const double c = std::floor((x[k] - origin_[k]) / cell_);
            const double clamped = std::isfinite(c) ? std::clamp(c, 0.0, cells_[k] - 1) : 0.0;
            key = key * (long long)cells_[k] + (long long)clamped;
        }
        return int(key);
    }

  private:
    Vec<double, Dim> origin_{};
    std::array<double, Dim> cells_{};
    double cell_ = 1;
};

/// Sorts the particles by (ORDER_KEY, PARTICLE_ID); returns the permutation applied (new
/// particle k is old particle permutation[k]).
template <int Dim>
std::vector<Size> sortByOrderKey(Storage<Dim>& s) {
    const auto key = s.template getValue<int>(QuantityId::ORDER_KEY);
    const auto id = s.template getValue<int>(QuantityId::PARTICLE_ID);
    std::vector<Size> order(s.size());
    std::iota(order.begin(), order.end(), Size(0));
    std::sort(order.begin(), order.end(),
              [&](Size a, Size b) { return std::tie(key[a], id[a]) < std::tie(key[b], id[b]); });
    bool sorted = true;
    for (Size k = 0; k < order.size() && sorted; ++k) sorted = order[k] == k;
    if (!sorted) s.reorder(order);
    return order;
}

/// Sets every particle's ORDER_KEY to its cell now and sorts the storage by it.
template <int Dim>
std::vector<Size> reorderByKey(Storage<Dim>& s, const Domain<Dim>& domain, double radius) {
    const OrderGrid<Dim> grid(domain, radius);
    const auto x = s.template getValue<Vec<double, Dim>>(QuantityId::POSITION);
    auto key = s.template getValue<int>(QuantityId::ORDER_KEY);
    for (Size i = 0; i < s.size(); ++i) key[i] = grid.key(x[i]);
    return sortByOrderKey(s);
}

}  // namespace num::sph
