// The time-step criteria, written once for the CPU engine (the solver and the terms that offer
// limits) and the CUDA back end's device run (device/fluid_run.hpp). Monaghan 1992 (Courant and
// acceleration), Morris et al. 1997 (viscous), the explicit diffusion limit for conduction
// (Cleary & Monaghan 1999). h: the smoothing length.
#pragma once

#include <cmath>

#include "sph/types.hpp"

namespace num::sph::formulas {

/// Acceleration: dt = factor sqrt(h / |a|max), from |a|max^2.
inline Float accelerationStep(Float factor, Float h, Float a2max) {
    return factor * std::sqrt(h / std::sqrt(a2max));
}

/// Courant: dt = cfl h / (c0 + |v|max), from |v|max^2 of the fluid.
inline Float courantStep(Float cfl, Float h, Float c0, Float v2max) {
    return cfl * h / (c0 + std::sqrt(v2max));
}

/// Viscous: dt = factor h^2 / nu_max.
inline Float viscousStep(Float factor, Float h, Float nuMax) { return factor * h * h / nuMax; }

/// Diffusion: dt = factor h^2 / alpha_max, alpha = k / (rho c) the thermal diffusivity.
inline Float diffusionStep(Float factor, Float h, Float alphaMax) {
    return factor * h * h / alphaMax;
}

}  // namespace num::sph::formulas
