// The pair formulas of the weakly-compressible fluid, written once for the CPU engine (the
// pair parts' symmetric eval and their gathers, include/sph/terms/) and the CUDA kernels.
// Each takes plain values of one pair (i, j) and returns what the pair adds, before the mass or
// volume of the other particle where the symmetric evaluation shares the rest between i and j.
// Notation: dx = x_i - x_j, grad = grad_i W_ij, V = m / rho, PairGeometry (pair_geometry.hpp)
// for laplacian and inverseR2. The arithmetic is in the engine's order: the CPU results are
// bitwise those of the hand-written loops these replace.
#pragma once

#include "sph/host_device.hpp"
#include "sph/types.hpp"

namespace num::sph::formulas {

// --- Continuity (Monaghan 1992, eq. 2.9; volume form of Colagrossi & Landrini 2003) ---------
//   drho_i/dt = rho_i sum_j V_j (v_i - v_j) . grad_i W_ij

/// (v_i - v_j) . grad_i W_ij, shared by both particles of the pair.
template <int Dim>
NUMERICS_HD Float continuityDivergence(const Vector<Dim>& vi, const Vector<Dim>& vj,
                                       const Vector<Dim>& grad) {
    return dot(vi - vj, grad);
}
/// What the pair adds to drho_a/dt: rho_a V_b div (b the other particle).
NUMERICS_HD_INLINE Float continuityRate(Float rhoA, Float volumeB, Float divergence) {
    return rhoA * volumeB * divergence;
}

// --- delta-SPH density diffusion (Molteni & Colagrossi 2009, eq. 10; hydrostatic part of
//     Fourtakas et al. 2019, eq. 12, linear) ----------------------------------------------
//   drho_i/dt += sum_j V_j 2 delta h c0 psi_ij (dx . grad) / (r^2 + eta^2),
//   psi_ij = rho_i - rho_j - (rho0 g / c0^2) . dx

/// 2 delta h c0, the constant factor.
NUMERICS_HD_INLINE Float deltaSphCoefficient(Float delta, Float c0, Float h) {
    return 2 * delta * h * c0;
}
/// rho0 g / c0^2, once per evaluation (g the body force at the time).
template <int Dim>
NUMERICS_HD Vector<Dim> deltaSphGravityTerm(const Vector<Dim>& g, Float rho0, Float c0) {
    return g * (rho0 / (c0 * c0));
}
/// The pair's flux f: drho_i/dt += f V_j, drho_j/dt -= f V_i. gravityTerm = rho0 g / c0^2.
template <int Dim>
NUMERICS_HD Float deltaSphFlux(Float coefficient, Float rhoi, Float rhoj,
                               const Vector<Dim>& gravityTerm, const Vector<Dim>& dx,
                               const Vector<Dim>& grad, Float inverseR2) {
    const Float psi = rhoi - rhoj - dot(gravityTerm, dx);
    return coefficient * psi * dot(dx, grad) * inverseR2;
}

// --- Pressure gradient (Monaghan 1992, eq. 3.3) --------------------------------------------
//   dv_i/dt = - sum_j m_j (p_i / rho_i^2 + p_j / rho_j^2) grad_i W_ij

/// p / rho^2, once per particle before the pair loop.
NUMERICS_HD_INLINE Float pressureOverDensity2(Float p, Float rho) { return p / (rho * rho); }
/// f = (p_i/rho_i^2 + p_j/rho_j^2) grad: dv_i/dt -= f m_j, dv_j/dt += f m_i.
template <int Dim>
NUMERICS_HD Vector<Dim> pressureGradientForce(const Vector<Dim>& grad, Float pOverRho2i,
                                              Float pOverRho2j) {
    return grad * (pOverRho2i + pOverRho2j);
}

// --- Artificial viscosity (Monaghan 1992, eq. 4.1-4.2), linear part ------------------------
//   dv_i/dt = - sum_j m_j Pi_ij grad,  Pi_ij = -alpha c0 h (v_ij . dx) / ((r^2 + eta^2) rho_ij)
//   for approaching pairs (v_ij . dx < 0), rho_ij = (rho_i + rho_j) / 2

/// v_ij . dx: negative for an approaching pair.
template <int Dim>
NUMERICS_HD Float approachRate(const Vector<Dim>& vi, const Vector<Dim>& vj,
                               const Vector<Dim>& dx) {
    return dot(vi - vj, dx);
}
/// Pi_ij for vr = v_ij . dx <= 0 (a receding pair has Pi = 0: pass vr = min(vr, 0) or skip
/// it); alphaC0h = alpha c0 h.
NUMERICS_HD_INLINE Float artificialViscosityPi(Float alphaC0h, Float vr, Float inverseR2,
                                               Float rhoi, Float rhoj) {
    return -alphaC0h * vr * inverseR2 / (0.5 * (rhoi + rhoj));
}

// --- Laminar viscosity (Morris, Fox & Zhu 1997, eq. 8) --------------------------------------
//   dv_i/dt = sum_j (mu_i + mu_j) L_ij V_j / rho_i (v_i - v_j),  L_ij = PairGeometry::laplacian

/// mu = rho nu, once per particle.
NUMERICS_HD_INLINE Float dynamicViscosity(Float rho, Float nu) { return rho * nu; }
/// (mu_i + mu_j) L_ij, shared by both particles.
NUMERICS_HD_INLINE Float laminarViscosityFactor(Float mui, Float muj, Float laplacian) {
    return (mui + muj) * laplacian;
}
/// What the pair adds to dv_a/dt: (v_a - v_b) f V_b / rho_a (b the other particle; the
/// symmetric evaluation subtracts (v_i - v_j) f V_i / rho_j from dv_j/dt).
template <int Dim>
NUMERICS_HD Vector<Dim> laminarViscosityAcceleration(const Vector<Dim>& dv, Float factor,
                                                     Float volumeB, Float inverseRhoA) {
    return dv * (factor * volumeB * inverseRhoA);
}

// --- Kernel sums -------------------------------------------------------------------------

/// V_j W_ij: a term of C_i = sum_j V_j W_ij (free_surface.hpp).
NUMERICS_HD_INLINE Float kernelSumWeight(Float volumeB, Float w) { return volumeB * w; }
/// m_j W_ij: a term of the summation density rho_i = sum_j m_j W_ij (Monaghan 1992, eq. 2.7;
/// summation_density.hpp).
NUMERICS_HD_INLINE Float summationDensityTerm(Float massB, Float w) { return massB * w; }

// --- Particle shifting (Lind et al. 2012, eq. 9, 15, 17; Sun et al. 2017, sec. 3) ----------
//   grad C_i   = sum_j V_j [1 + R max(0, (W_ij / W(dx_ij))^4 - 1.5)] grad,  R = 0.6
//   grad rho_i = sum_j V_j (rho_j - rho_i) grad,   (grad v)_i = sum_j V_j (v_j - v_i) (x) grad

inline constexpr Float shiftingTensileR = 0.6, shiftingTensileThreshold = 1.5;

/// 1 + R max(0, q^4 - 1.5), q = W_ij / W(dx_ij), 1 / W(dx_ij) the mean of i's and j's.
NUMERICS_HD_INLINE Float shiftingTensileFactor(Float w, Float inverseWi, Float inverseWj) {
    const Float q = w * 0.5 * (inverseWi + inverseWj);
    return 1 + shiftingTensileR * hd::max(0.0, (q * q) * (q * q) - shiftingTensileThreshold);
}
/// V_b (rho_j - rho_i) grad: the pair's term of grad rho for either particle b of the pair.
template <int Dim>
NUMERICS_HD Vector<Dim> densityGradientTerm(const Vector<Dim>& grad, Float volumeB, Float drho) {
    return grad * (volumeB * drho);
}
/// Column c of the pair's term of grad v: (v_j - v_i) V_b grad[c].
template <int Dim>
NUMERICS_HD Vector<Dim> velocityGradientTerm(const Vector<Dim>& dv, Float volumeB,
                                             Float gradComponent) {
    return dv * (volumeB * gradComponent);
}

}  // namespace num::sph::formulas
