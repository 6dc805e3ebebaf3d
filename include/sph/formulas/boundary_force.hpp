// The acceleration a_ij that boundary particle j (of a wall or body) gives fluid particle i,
// as the engine's pair terms give it (sph/formulas/fluid_pairs.hpp):
//   pressure gradient  a_ij = -m_j (p_i / rho_i^2 + p_j / rho_j^2) grad_i W_ij (Monaghan 1992,
//                      eq. 3.3), p_j and rho_j those of the wall condition (Adami et al. 2012,
//                      eq. 27-28);
//   laminar viscosity  a_ij = (mu_i + mu_j) L_ij V_j / rho_i (v_i - v_j) (Morris et al. 1997,
//                      eq. 8), v_j the wall condition's velocity (no-slip particles only);
//   artificial         a_ij = -m_j Pi_ij grad_i W_ij (Monaghan 1992, eq. 4.1-4.2).
// The pair terms are antisymmetric, so -m_i a_ij is the force of fluid i on boundary particle j
// (Newton's third law): summed over a body's particles, the fluid's force on the body.
// Reads the storage as the last evaluation left it (pressures, densities, pair velocities).
// The per-pair formula is boundary_pair.hpp's, shared with the device step.
#pragma once

#include <cmath>

#include "sph/defaults.hpp"
#include "sph/formulas/boundary_pair.hpp"
#include "sph/formulas/fluid_pairs.hpp"
#include "sph/formulas/pair_geometry.hpp"
#include "sph/kernel_choice.hpp"
#include "sph/storage.hpp"
#include "sph/terms/fluid_quantities.hpp"

namespace num::sph::formulas {

template <int Dim>
class BoundaryPairForce {
  public:
    using Vec = Vector<Dim>;

    /// alpha, c0: the artificial viscosity's (alpha = 0: off).
    BoundaryPairForce(const Storage<Dim>& s, const RunKernel<Dim>& kernel, Float alpha, Float c0)
        : kernel_(kernel),
          alphaC0h_(alpha * c0 * kernel.h),
          laplacianEta2_(defaults::laplacianEta2 * kernel.h * kernel.h),
          inverseR2Eta2_(defaults::inverseR2Eta2 * kernel.h * kernel.h) {
        m_ = s.template getValue<Float>(QuantityId::MASS);
        rho_ = s.template getValue<Float>(QuantityId::DENSITY);
        p_ = s.template getValue<Float>(QuantityId::PRESSURE);
        v_ = s.template getValue<Vec>(FluidId::PAIR_VELOCITY);
        if (s.has(FluidId::KINEMATIC_VISCOSITY))
            nu_ = s.template getValue<Float>(FluidId::KINEMATIC_VISCOSITY);
        if (s.has(FluidId::WALL_SLIP)) slip_ = s.template getValue<int>(FluidId::WALL_SLIP);
    }

    /// The force of fluid particle i on boundary particle j, dx = x_i - x_j, r = |dx| > 0.
    Vec onBoundary(Size i, Size j, const Vec& dx, Float r) const {
        return onBoundary(i, j, dx, r, kernel_.dW_dr(r));
    }
    /// The same with the kernel's dW/dr at r given (a loop that holds the kernel's type).
    Vec onBoundary(Size i, Size j, const Vec& dx, Float r, Float dWdr) const {
        const bool noSlip = slip_.empty() || slip_[j] == int(WallSlip::NO_SLIP);
        const BoundaryPairTerms terms{!nu_.empty() && noSlip, alphaC0h_, laplacianEta2_,
                                      inverseR2Eta2_};
        return boundaryPairForce<Dim>(side(i), side(j), terms, dx, r, dWdr);
    }

  private:
    PairSide<Dim> side(Size i) const {
        return {m_[i], rho_[i], p_[i], nu_.empty() ? 0.0 : nu_[i], v_[i]};
    }

    RunKernel<Dim> kernel_;
    Float alphaC0h_, laplacianEta2_, inverseR2Eta2_;
    ArrayView<const Float> m_, rho_, p_, nu_;
    ArrayView<const Vec> v_;
    ArrayView<const int> slip_;
};

}  // namespace num::sph::formulas
