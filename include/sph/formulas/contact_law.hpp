// The contact of a free body's particle j with a particle k of another solid (a wall, the box's
// walls, another body not hinged to it), closer than the spacing dx: a damped spring pushes it
// back and Coulomb friction holds it (a linear spring-dashpot, Cundall & Strack 1979):
//   F_n = max(0, k_n (dx - r) - c_n (v_jk . n)),  n = (x_j - x_k) / r,  v_jk = v_j - v_k,
//   F_jk = F_n n - min(mu F_n, c_n |v_t|) v_t / |v_t|,  v_t = v_jk - (v_jk . n) n.
// The body's law (k_n, c_n, mu) is set by the coupling (bodies/body_coupling.hpp); the CPU
// engine and the device step (device/body_step.hpp) evaluate it here.
#pragma once

#include "sph/host_device.hpp"
#include "sph/types.hpp"

namespace num::sph {

/// The contact law of a free body's particles: spring k_n, dashpot c_n, Coulomb friction mu, at
/// distances below the spacing dx (kn = 0: no contacts, a prescribed body).
template <int Dim>
struct ContactLaw {
    Float kn = 0, cn = 0, mu = 0, dx = 0;

    /// The force on particle j from particle k at d = x_j - x_k, r2 = |d|^2, vjk = v_j - v_k.
    NUMERICS_HD Vector<Dim> force(const Vector<Dim>& d, Float r2, const Vector<Dim>& vjk) const {
        if (!(r2 < dx * dx)) return {};
        const Float r = hd::sqrt(r2);
        const Vector<Dim> n = d / r;
        const Float push = kn * (dx - r) - cn * dot(vjk, n);
        if (!(push > 0)) return {};
        const Vector<Dim> vt = vjk - n * dot(vjk, n);
        const Float slide = norm(vt);
        Vector<Dim> f = n * push;
        if (slide > 0) f -= vt * (hd::min(mu * push, cn * slide) / slide);
        return f;
    }
};

}  // namespace num::sph
