#include "output/body_force.hpp"

#include "sph/formulas/boundary_force.hpp"

namespace num::app {

template <int Dim>
std::vector<typename BodyForces<Dim>::Vec> BodyForces<Dim>::operator()(
    const sph::Storage<Dim>& s) const {
    using sph::QuantityId;
    std::vector<Vec> force(targets_, Vec{});
    const auto x = s.template getValue<Vec>(QuantityId::POSITION);
    const auto kind = s.template getValue<int>(QuantityId::KIND);
    const sph::formulas::BoundaryPairForce<Dim> pair(s, kernel_, alpha_, c0_);
    CellGrid<Dim> grid;
    grid.build(x, kernel_.supportRadius(), domain_);
    for (sph::Size j = 0; j < s.size(); ++j) {
        if (sph::isFluid(kind[j])) continue;
        const int b = targetOf_(s, j);
        if (b < 0 || b >= targets_) continue;
        grid.forEachNeighbour(x[j], [&](sph::Size i, const Vec& dxji, double r2) {
            if (!sph::isFluid(kind[i]) || r2 <= 0) return;
            force[b] += pair.onBoundary(i, j, -dxji, std::sqrt(r2));
        });
    }
    return force;
}

template class BodyForces<2>;
template class BodyForces<3>;

}  // namespace num::app
