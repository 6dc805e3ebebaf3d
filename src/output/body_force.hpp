// The force the fluid exerts on each solid body or interior wall b, as the engine's pair terms
// give it:
//   F_b = - sum_{fluid i} sum_{j in b} m_i a_ij,
// a_ij the acceleration boundary particle j of b gives fluid particle i
// (sph/formulas/boundary_force.hpp). In 2D a force per unit depth [N/m].
// Read from the storage of an output time: the pressures, densities and velocities of the last
// evaluation. Internal to numerics_app.
#pragma once

#include <functional>
#include <vector>

#include "spatial/cell_grid.hpp"
#include "sph/kernel_choice.hpp"
#include "sph/storage.hpp"

namespace num::app {

template <int Dim>
class BodyForces {
  public:
    using Vec = sph::Vector<Dim>;
    /// Which of the `targets` solids boundary particle j belongs to (-1: none).
    using TargetOf = std::function<int(const sph::Storage<Dim>&, sph::Size j)>;
    /// `alpha`, `c0`: the artificial viscosity's (alpha = 0: off).
    BodyForces(const sph::RunSettings& settings, const Domain<Dim>& domain, int targets,
               TargetOf targetOf, double alpha, double c0)
        : kernel_(settings),
          domain_(domain),
          targets_(targets),
          targetOf_(std::move(targetOf)),
          alpha_(alpha),
          c0_(c0) {}

    /// F_b of every target b at the storage's state.
    std::vector<Vec> operator()(const sph::Storage<Dim>& s) const;

  private:
    sph::RunKernel<Dim> kernel_;
    Domain<Dim> domain_;
    int targets_;
    TargetOf targetOf_;
    double alpha_, c0_;
};

}  // namespace num::app
