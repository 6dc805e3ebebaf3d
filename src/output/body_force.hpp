// The force the fluid exerts on each solid body or interior wall b, as the engine's pair terms
// give it:
//   F_b = - sum_{fluid i} sum_{j in b} m_i a_ij,
// a_ij the acceleration boundary particle j of b gives fluid particle i
// (sph/formulas/fluid_pairs.hpp):
//   pressure gradient  a_ij = -m_j (p_i / rho_i^2 + p_j / rho_j^2) grad_i W_ij (Monaghan 1992,
//                      eq. 3.3), p_j and rho_j those of the wall condition (Adami et al. 2012,
//                      eq. 27-28);
//   laminar viscosity  a_ij = (mu_i + mu_j) L_ij V_j / rho_i (v_i - v_j) (Morris et al. 1997,
//                      eq. 8), v_j the wall condition's velocity (no-slip particles only);
//   artificial         a_ij = -m_j Pi_ij grad_i W_ij (Monaghan 1992, eq. 4.1-4.2).
// The pair terms are antisymmetric, so this is the reaction of the body on the fluid with its
// sign reversed (Newton's third law). In 2D a force per unit depth [N/m].
// Read from the storage of an output time: the pressures, densities and velocities of the last
// evaluation. Internal to numerics_io.
#pragma once

#include <functional>
#include <vector>

#include "spatial/cell_grid.hpp"
#include "sph/kernel_choice.hpp"
#include "sph/storage.hpp"

namespace num::io {

template <int Dim>
class BodyForces {
  public:
    using Vec = sph::Vector<Dim>;
    /// `targetOf(kind, x)`: which of the `targets` solids a boundary particle of that
    /// ParticleKind at x belongs to (-1: none); `alpha`, `c0`: the artificial viscosity's
    /// (alpha = 0: off).
    BodyForces(const sph::RunSettings& settings, const Domain<Dim>& domain, int targets,
               std::function<int(int, const Vec&)> targetOf, double alpha, double c0)
        : kernel_(settings),
          domain_(domain),
          targets_(targets),
          targetOf_(std::move(targetOf)),
          alphaC0h_(alpha * c0 * kernel_.h) {}

    /// F_b of every target b at the storage's state.
    std::vector<Vec> operator()(const sph::Storage<Dim>& s) const;

  private:
    sph::RunKernel<Dim> kernel_;
    Domain<Dim> domain_;
    int targets_;
    std::function<int(int, const Vec&)> targetOf_;
    double alphaC0h_;
};

}  // namespace num::io
