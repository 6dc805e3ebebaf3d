// The post-step formulas of the fluid, written once for the CPU engine (ParticleShifting and
// ParticleContainment's postStep) and the CUDA back end's device step.
#pragma once

#include "sph/host_device.hpp"
#include "sph/setup/shapes.hpp"
#include "sph/types.hpp"

namespace num::sph::formulas {

// --- Particle shifting (terms/particle_shifting.hpp; its displacement dr:
//     shiftingDisplacement, fluid_particles.hpp) ----------------------------------------------

/// Moves a particle by dr and corrects its velocity and (continuity) density by the Taylor
/// expansion; gradV: the Dim columns of (grad v)_i.
template <int Dim>
NUMERICS_HD void shiftParticle(Vector<Dim>& x, Vector<Dim>& v, Float& rho, bool continuity,
                               const Vector<Dim>& dr, const Vector<Dim>& gradRho,
                               const Vector<Dim> (&gradV)[Dim]) {
    x += dr;
    for (int k = 0; k < Dim; ++k) v += gradV[k] * dr[k];
    if (continuity) rho += dot(gradRho, dr);
}

// --- Containment (boundary/particle_containment.hpp) ---------------------------------------

/// Whether x lies across the opening [from, to] of a side on `axis`: its coordinates along the
/// side within it (the side's own axis ignored).
template <int Dim>
NUMERICS_HD bool acrossOpening(const Vector<Dim>& x, int axis, const Vector<Dim>& from,
                               const Vector<Dim>& to) {
    for (int k = 0; k < Dim; ++k)
        if (k != axis && (x[k] < from[k] || x[k] > to[k])) return false;
    return true;
}

/// An outlet's opening on a side of the box (boundary/flow_boundaries.hpp): fluid across it
/// passes through the side, which reflects it elsewhere; `present` false: no outlet there.
template <int Dim>
struct OutletOpening {
    bool present = false;
    Vector<Dim> from{}, to{};
    NUMERICS_HD bool letsThrough(const Vector<Dim>& x, int axis) const {
        return present && acrossOpening<Dim>(x, axis, from, to);
    }
};

/// One axis of a fluid particle against the box's walls [lo, hi]: reflected back inside, the
/// velocity component into the wall removed.
NUMERICS_HD_INLINE void containInWalls(Float& x, Float& v, Float lo, Float hi, bool wallLow,
                                       bool wallHigh) {
    if (wallLow && x < lo) {
        x = hd::min(2 * lo - x, hi);
        v = hd::max(v, 0.0);
    }
    if (wallHigh && x > hi) {
        x = hd::max(2 * hi - x, lo);
        v = hd::min(v, 0.0);
    }
}

/// A fluid particle against a solid (a body's or an interior wall's shape: anything with
/// signedDistance and outwardNormal): a particle inside, at signed distance d < 0, is
/// reflected back across the nearest surface to x - 2 d n, the velocity component into the
/// solid removed.
template <int Dim, class Solid>
NUMERICS_HD void containOutsideBody(Vector<Dim>& x, Vector<Dim>& v, const Solid& body) {
    const Float d = body.signedDistance(x);
    if (d >= 0) return;
    const Vector<Dim> n = body.outwardNormal(x);
    x -= n * (2 * d);
    const Float vn = dot(v, n);
    if (vn < 0) v -= n * vn;
}

}  // namespace num::sph::formulas
