// The boundary particles (walls and bodies) split by whether a fluid particle is among their
// neighbour-list candidates. One without is far from the fluid while the lists are kept: it has
// no fluid neighbour (the empty sum of the wall condition) and needs no gather. Most of a tank's
// wall particles are such (the shipped 3D dam break: 13,116 of its 16,491 particles are walls).
// The split is found again at each build of the lists (a reordering or a new particle count
// rebuilds them); the wall condition and the wall temperature share one.
#pragma once

#include <vector>

#include "sph/terms/neighbour_gather.hpp"

namespace num::sph {

template <int Dim>
class BoundaryNearFluid {
  public:
    /// Splits the boundary particles again if the lists were built since the last split.
    void update(IScheduler& scheduler, const Storage<Dim>& s, const VerletList<Dim>& lists) {
        const ListBuild build{&lists, lists.builds(), s.size()};
        if (build == splitFor_) return;
        splitFor_ = build;
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        const std::vector<Size> boundary = particlesWhere(s, [](int k) { return !isFluid(k); });
        std::vector<char> near(boundary.size(), 0);
        scheduler.parallelFor(Size(boundary.size()), 256, [&](Size b, Size e) {
            for (Size k = b; k < e; ++k)
                lists.forEachCandidate(boundary[k], [&](Size j) { near[k] |= isFluid(kind[j]); });
        });
        near_.clear(), far_.clear();
        for (std::size_t k = 0; k < boundary.size(); ++k)
            (near[k] ? near_ : far_).push_back(boundary[k]);
    }
    /// Boundary particles with a fluid particle among their candidates, in storage order.
    const std::vector<Size>& near() const { return near_; }
    /// Boundary particles without one, in storage order.
    const std::vector<Size>& far() const { return far_; }

  private:
    struct ListBuild {
        const VerletList<Dim>* lists = nullptr;
        std::size_t builds = 0;
        Size particles = 0;
        bool operator==(const ListBuild&) const = default;
    };
    ListBuild splitFor_;  // the build the split was made for
    std::vector<Size> near_, far_;
};

}  // namespace num::sph
