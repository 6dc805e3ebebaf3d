// A periodic side: the axis wraps, a particle leaving through one side enters through the
// other, and neighbours are found across it (the minimum image of spatial/cell_grid.hpp's
// Domain). Both sides of the axis are periodic; the box length must be a multiple of the
// spacing and at least twice the kernel support (checked with the scene).
#pragma once

#include "sph/boundary/side_boundary.hpp"

namespace num::sph {

template <int Dim>
class PeriodicBoundary : public ISideBoundary<Dim> {
  public:
    const char* type() const override { return "periodic"; }
    void build(FluidGeometry<Dim>& geometry, int axis, int) const override {
        geometry.domain.periodic[axis] = true;
    }
    bool wraps() const override { return true; }
};

}  // namespace num::sph
