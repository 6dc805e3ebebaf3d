// Per-particle formulas of the fluid model, callable on host and device: what the terms
// compute once per particle before or after the pair loop (terms/*.hpp name the sources).
#pragma once

#include "sph/defaults.hpp"
#include "sph/host_device.hpp"
#include "sph/types.hpp"

namespace num::sph {

/// The kernel sum below which a particle's support is cut: the particle is at a free surface.
inline constexpr Float surfaceKernelSum = 0.9;

/// Whether a particle is at a free surface, from KERNEL_SUM (its neighbours' sum), its volume
/// V_i and W(0): C_i = KERNEL_SUM_i + V_i W(0) < 0.9 (terms/free_surface.hpp).
NUMERICS_HD_INLINE bool atFreeSurface(Float neighbourSum, Float volume, Float w0) {
    return neighbourSum + volume * w0 < surfaceKernelSum;
}

enum class ViscosityLaw { EXPONENTIAL, WATER_VOGEL };

/// Kinematic viscosity of temperature (terms/temperature_viscosity.hpp):
///   Exponential (Reynolds 1886):  nu(T) = nu0 exp(-b (T - T0));
///   Water (Vogel 1921 fit, T in degC):  nu = A exp(B / (T + 273.15 - C)) / rho0,
///       A = 2.939e-5 Pa s, B = 507.88 K, C = 149.3 K.
struct ViscosityOfTemperature {
    ViscosityLaw law = ViscosityLaw::EXPONENTIAL;
    Float coefficient = defaults::viscosityTemperatureCoefficient;  ///< b [1/K]

    /// nu at temperature T for a material with viscosity nu0 at T0 and rest density rho0.
    NUMERICS_HD Float operator()(Float T, Float nu0, Float T0, Float rho0) const {
        if (law == ViscosityLaw::WATER_VOGEL)
            return 2.939e-5 * hd::exp(507.88 / (T + 273.15 - 149.3)) / rho0;
        return nu0 * hd::exp(-coefficient * (T - T0));
    }
};

namespace formulas {

/// V = m / rho (terms/pair_inputs.hpp).
NUMERICS_HD_INLINE Float particleVolume(Float m, Float rho) { return m / rho; }

/// The free-surface tension limit (terms/free_surface.hpp; Colagrossi et al. 2009), at a
/// particle with C_i < 0.9: the density floor rho = max(rho, f rho0), a constraint on the state
/// before each evaluation, ...
NUMERICS_HD_INLINE Float surfaceDensityFloor(Float rho, Float rhoMin) {
    return hd::max(rho, rhoMin);
}
/// ... and the pressure floor p = max(p, p(f rho0)) after the equation of state.
NUMERICS_HD_INLINE Float surfacePressureFloor(Float p, Float pMin) { return hd::max(p, pMin); }

/// dx_i = V_i^(1/Dim), the local particle spacing; particle shifting compares W_ij with
/// W(dx_ij) (terms/particle_shifting.hpp).
template <int Dim>
NUMERICS_HD Float particleSpacing(Float volume) {
    return hd::pow(volume, 1.0 / Dim);
}

/// Particle shifting's move of a fluid particle away from free surfaces (Lind et al. 2012,
/// eq. 9, 15, 17; terms/particle_shifting.hpp): dr = -A h c0 dt grad C (diffusion = A h c0 dt),
/// without its component along the wall direction n unless normalToWalls, capped at |dr| = cap.
template <int Dim>
NUMERICS_HD Vector<Dim> shiftingDisplacement(const Vector<Dim>& gradC,
                                             const Vector<Dim>& wallDirection, Float diffusion,
                                             Float cap, bool normalToWalls) {
    Vector<Dim> dr = gradC * (-diffusion);
    const Vector<Dim>& n = wallDirection;
    if (const Float nn = normSqr(n); !normalToWalls && nn > 0) dr -= n * (dot(dr, n) / nn);
    const Float len = norm(dr);
    if (len > cap) dr *= cap / len;
    return dr;
}

/// Boussinesq buoyancy (Boussinesq 1903; Kundu & Cohen sec. 4.18):
///   dv/dt += -beta (T - T0) g.
template <int Dim>
NUMERICS_HD Vector<Dim> boussinesqAcceleration(const Vector<Dim>& g, Float beta, Float T,
                                               Float T0) {
    return g * (-beta * (T - T0));
}

/// A body force: dv/dt += g(t) for a fluid particle (terms/body_force.hpp).
template <int Dim>
NUMERICS_HD void addBodyForce(Vector<Dim>& a, const Vector<Dim>& g) {
    a += g;
}

}  // namespace formulas
}  // namespace num::sph
