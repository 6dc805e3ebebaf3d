// Equation of state of a weakly-compressible fluid, callable on host and device.
//
// Tait (Monaghan 1994, eq. 3.5; Batchelor 1967):  p = B ((rho / rho0)^gamma - 1) + p_b,
//                                                  B = rho0 c0^2 / gamma, gamma = 7.
// Linear (Morris, Fox & Zhu 1997, eq. 10):        p = c0^2 (rho - rho0) + p_b.
// p_b is an optional background pressure. Both have the sound speed c0 at rho = rho0.
#pragma once

#include "sph/defaults.hpp"
#include "sph/host_device.hpp"
#include "sph/types.hpp"

namespace num::sph {

enum class EosType { TAIT, LINEAR };

/// x^gamma; by squaring where gamma is a whole number up to 16 (the Tait gamma = 7: four
/// multiplications, a few units in the last place from pow, at a fraction of its cost, and the
/// same on host and device, where pow's rounding may differ).
NUMERICS_HD_INLINE Float power(Float x, Float gamma) {
    if (gamma != hd::floor(gamma) || gamma < 1 || gamma > 16) return hd::pow(x, gamma);
    Float result = 1, square = x;
    for (int n = int(gamma);; square *= square) {
        if (n & 1) result *= square;
        if ((n >>= 1) == 0) return result;
    }
}

struct EquationOfState {
    EosType type = EosType::TAIT;
    Float rho0 = defaults::density;
    Float c0 = defaults::materialSoundSpeed;
    Float gamma = defaults::taitExponent;
    Float backgroundPressure = 0;

    NUMERICS_HD Float stiffness() const { return rho0 * c0 * c0 / gamma; }

    NUMERICS_HD Float pressure(Float rho) const {
        if (type == EosType::LINEAR) return c0 * c0 * (rho - rho0) + backgroundPressure;
        return stiffness() * (power(rho / rho0, gamma) - 1) + backgroundPressure;
    }
    /// The inverse, rho(p); Tait is clamped where (p - p_b) / B <= -1 has no density (the wall
    /// condition's density, Adami et al. 2012, eq. 28).
    NUMERICS_HD Float density(Float p) const {
        const Float dp = p - backgroundPressure;
        if (type == EosType::LINEAR) return rho0 + dp / (c0 * c0);
        return rho0 * hd::pow(hd::max(1 + dp / stiffness(), 1e-3), 1 / gamma);
    }
};

namespace formulas {

/// A fluid particle's pressure, p = max(p(rho), pMin), pMin = p_b - T_max (the tension the
/// liquid holds before it cavitates; terms/equation_of_state.hpp).
NUMERICS_HD_INLINE Float fluidPressure(const EquationOfState& eos, Float rho, Float pMin) {
    return hd::max(eos.pressure(rho), pMin);
}

}  // namespace formulas
}  // namespace num::sph
