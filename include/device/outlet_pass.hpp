// The outlets' condition on the device: sph::OutletCondition (boundary/flow_boundaries.hpp) as
// a pass of the device step, after the wall condition, before the pair inputs.
#pragma once

#include "device/fluid_passes.hpp"

namespace num::device::passes {

constexpr int outlet = int(sph::ParticleKind::OUTLET);

/// An outlet particle o takes its side's pressure p_out(x_o, t) (pOut, evaluated on the host),
/// the density rho(p_out), and into `mean` the Shepard mean of its fluid and outlet
/// neighbours' velocities, v_o = sum_j v_j W_oj / sum_j W_oj (its own velocity without such a
/// neighbour); every other particle's `mean` is its own velocity. The velocities are read
/// before any is replaced: `mean` then becomes v.
template <int Dim, class Kernel>
struct OutletPass {
    Arrays<Dim> d;
    GridShape<Dim> grid;
    const Index *start, *end;
    sph::KernelValue<Kernel> kernelValue;
    sph::EquationOfState eos;
    const Float* pOut;
    Vector<Dim>* mean;
    NUMERICS_HD void operator()(Index o) const {
        if (d.kind[o] != outlet) {
            mean[o] = d.v[o];
            return;
        }
        Vector<Dim> sum{};
        Float weight = 0;
        forEachNeighbour<Dim>(grid, d.x, start, end, o,
                              [&](Index j, const Vector<Dim>&, double r2) {
                                  if (d.kind[j] != fluid && d.kind[j] != outlet) return;
                                  const Float W = kernelValue.value(hd::sqrt(r2));
                                  sum += d.v[j] * W, weight += W;
                              });
        d.p[o] = pOut[o], d.rho[o] = eos.density(d.p[o]);
        mean[o] = weight > 0 ? sum / weight : d.v[o];
    }
};

}  // namespace num::device::passes
