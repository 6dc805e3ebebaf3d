// What a fluid case is made of, as particles: the container box with its walls (or periodic
// axes), fluid regions, and solid bodies. makeFluidStorage (fluid_model.hpp) turns it into a
// Storage on one lattice of spacing dx.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "spatial/cell_grid.hpp"
#include "sph/defaults.hpp"
#include "sph/setup/shapes.hpp"
#include "sph/terms/fluid_quantities.hpp"

namespace num::sph {

/// One side of the container box. On a periodic axis the sides are ignored.
template <int Dim>
struct WallSide {
    bool present = true;     ///< false: an open side (e.g. a free surface tank top)
    Vector<Dim> velocity{};  ///< prescribed surface velocity (a Couette or cavity lid)
    WallSlip slip = WallSlip::NO_SLIP;
    Float temperature =
        defaults::temperature;  ///< initial (or fixed, for thermal walls) temperature
    int material = 0;           ///< index into FluidModel::materials
};

/// Fluid filling a shape (the part inside the box and outside every body).
template <int Dim>
struct FluidRegion {
    Shape<Dim> shape;
    Float temperature = defaults::temperature;
    int material = 0;
    /// Initial velocity at a position; empty means at rest.
    std::function<Vector<Dim>(const Vector<Dim>&)> velocity;

    static FluidRegion filling(const Shape<Dim>& s, Float temperature = defaults::temperature) {
        FluidRegion r;
        r.shape = s, r.temperature = temperature;
        return r;
    }
};

/// A solid body inside the fluid, held fixed, made of boundary particles.
template <int Dim>
struct SolidBody {
    Shape<Dim> shape;
    Float temperature = defaults::temperature;
    int material = 0;
    WallSlip slip = WallSlip::NO_SLIP;
    /// Thickness of the particle shell below the surface; 0 fills the whole body.
    Float thickness = 0;
};

template <int Dim>
struct FluidGeometry {
    /// The container box [min, max]: fluid lives inside; walls lie outside its non-periodic
    /// sides; periodic axes wrap. Also the solver's Domain.
    Domain<Dim> domain;
    /// Particle spacing dx; box lengths should be multiples of it.
    Float spacing = 0;
    /// walls[axis][0] is the side at domain.min[axis], walls[axis][1] the side at domain.max.
    std::array<std::array<WallSide<Dim>, 2>, Dim> walls{};
    /// Layers of wall particles; 0 chooses enough to cover the kernel support.
    int wallLayers = 0;
    std::vector<FluidRegion<Dim>> fluid;
    std::vector<SolidBody<Dim>> bodies;

    bool hasWall(int axis, int side) const {
        return !domain.periodic[axis] && walls[axis][side].present;
    }
};

}  // namespace num::sph
