// The force of a fluid particle i on a boundary particle j (of a wall or body), -m_i a_ij, per
// pair: the formula of sph/formulas/boundary_force.hpp (which states it), on host and device (the
// CPU's RigidBodyCoupling through BoundaryPairForce, the device step's body loads in
// device/body_step.hpp).
#pragma once

#include "sph/formulas/fluid_pairs.hpp"
#include "sph/formulas/pair_geometry.hpp"
#include "sph/host_device.hpp"

namespace num::sph::formulas {

/// What the boundary force reads of one particle of the pair: mass, density, pressure,
/// kinematic viscosity and pair velocity.
template <int Dim>
struct PairSide {
    Float m, rho, p, nu;
    Vector<Dim> v;
};

/// The numbers of the pair terms: laminar (nu known, j no-slip), alpha c0 h of the artificial
/// viscosity (0: off), eta^2 of the Laplacian and of 1/r^2.
struct BoundaryPairTerms {
    bool laminar;
    Float alphaC0h, laplacianEta2, inverseR2Eta2;
};

/// The force of fluid particle i on boundary particle j (the file comment): -m_i a_ij, with
/// dx = x_i - x_j, r = |dx| > 0 and the kernel's dW/dr at r.
template <int Dim>
NUMERICS_HD Vector<Dim> boundaryPairForce(const PairSide<Dim>& i, const PairSide<Dim>& j,
                                          const BoundaryPairTerms& t, const Vector<Dim>& dx,
                                          Float r, Float dWdr) {
    const Vector<Dim> grad = dx * (dWdr / r);
    Vector<Dim> a = -pressureGradientForce(grad, pressureOverDensity2(i.p, i.rho),
                                           pressureOverDensity2(j.p, j.rho)) *
                    j.m;
    if (t.laminar) {
        const Float factor =
            laminarViscosityFactor(dynamicViscosity(i.rho, i.nu), dynamicViscosity(j.rho, j.nu),
                                   pairLaplacian(dx, grad, r, t.laplacianEta2));
        a += laminarViscosityAcceleration(i.v - j.v, factor, j.m / j.rho, 1.0 / i.rho);
    }
    const Float vr = approachRate(i.v, j.v, dx);
    if (t.alphaC0h > 0 && vr < 0)
        a -=
            grad *
            artificialViscosityPi(t.alphaC0h, vr, pairInverseR2(r, t.inverseR2Eta2), i.rho, j.rho) *
            j.m;
    return -a * i.m;
}

}  // namespace num::sph::formulas
