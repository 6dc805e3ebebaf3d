// The generalised wall condition (Adami, Hu & Adams 2012, J. Comput. Phys. 231, 7057;
// boundary/generalized_wall.hpp), callable on host and device: a boundary particle w gathers
// its fluid neighbours f into WallSums, then takes
//   p_w = [ sum_f p_f W_wf + g . sum_f rho_f (x_w - x_f) W_wf ] / sum_f W_wf   (eq. 27)
//   v~_w = sum_f v_f W_wf / sum_f W_wf                                         (eq. 22)
//   v_w = 2 v_wall - v~_w (no-slip, eq. 23), v_wall (free-slip)
//   rho_w = rho(p_w), the inverse equation of state                            (eq. 28)
//   T_w = 2 T_wall - T~_w, T~_w = sum_f T_f W_wf / sum_f W_wf (fixed temperature)
// A boundary particle with sum_f W_wf = 0 takes the empty sum's values: background pressure,
// v_w = v_wall and its own temperature.
#pragma once

#include "sph/host_device.hpp"
#include "sph/types.hpp"

namespace num::sph::formulas {

/// The sums of one boundary particle over its fluid neighbours.
template <int Dim>
struct WallSums {
    Float w = 0, p = 0, T = 0;
    Vector<Dim> rhoR{}, v{};

    /// Adds fluid neighbour f: dx = x_w - x_f, W = W_wf; its temperature only if heat.
    NUMERICS_HD void add(Float pf, Float rhof, const Vector<Dim>& vf, Float Tf, bool heat,
                         const Vector<Dim>& dx, Float W) {
        w += W;
        p += pf * W;
        rhoR += dx * (rhof * W);
        v += vf * W;
        if (heat) T += Tf * W;
    }
    /// True if the particle has a fluid neighbour within the support.
    NUMERICS_HD bool any() const { return w > 0; }
};

/// p_w (eq. 27) for sums.any(); g the body force.
template <int Dim>
NUMERICS_HD Float wallPressure(const WallSums<Dim>& sums, const Vector<Dim>& g) {
    return (sums.p + dot(g, sums.rhoR)) / sums.w;
}
/// The velocity the boundary particle shows in the viscous terms (eq. 22-23), for sums.any().
template <int Dim>
NUMERICS_HD Vector<Dim> wallVelocity(const WallSums<Dim>& sums, const Vector<Dim>& wall,
                                     bool noSlip) {
    return noSlip ? wall * 2.0 - sums.v / sums.w : wall;
}
/// The temperature a boundary particle shows to conduction, for sums.any(): 2 T_wall - T~_w
/// for a fixed-temperature particle, else its own T.
template <int Dim>
NUMERICS_HD Float wallTemperature(const WallSums<Dim>& sums, Float T, bool fixedTemperature) {
    return fixedTemperature ? 2 * T - sums.T / sums.w : T;
}

}  // namespace num::sph::formulas
