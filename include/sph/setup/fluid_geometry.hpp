// What a fluid case is made of, as particles: the container box with its walls (or periodic
// axes), fluid regions, solid bodies and walls inside the box. makeFluidStorage
// (fluid_model.hpp) turns it into a Storage on one lattice of spacing dx. Regions, bodies and
// walls are boxes or balls (BoxOrBall) or any solid (PlacedShape::solid; include/geometry/); the
// CUDA back end flattens the solids of bodies and walls (device/containment.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <functional>
#include <vector>

#include "spatial/cell_grid.hpp"
#include "sph/defaults.hpp"
#include "sph/formulas/post_step.hpp"
#include "sph/setup/placed_shape.hpp"
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
    /// What the layers beyond the side are: WALL, or the INLET or OUTLET buffer of an open
    /// boundary (boundary/flow_boundaries.hpp).
    ParticleKind layers = ParticleKind::WALL;
    /// An inlet's or outlet's opening: the box [openFrom, openTo] on the side (the side's own
    /// axis ignored); the rest of the side is a wall. The default: the whole side.
    Vector<Dim> openFrom = Vector<Dim>::filled(-1e300), openTo = Vector<Dim>::filled(1e300);

    /// Whether x lies across the opening (its coordinates along the side within it).
    bool inOpening(const Vector<Dim>& x, int axis) const {
        return formulas::acrossOpening<Dim>(x, axis, openFrom, openTo);
    }
};

/// Fluid filling a shape (the part inside the box and outside every body and wall).
template <int Dim>
struct FluidRegion : PlacedShape<Dim> {
    Float temperature = defaults::temperature;
    int material = 0;
    /// Initial velocity at a position; empty means at rest.
    std::function<Vector<Dim>(const Vector<Dim>&)> velocity;

    static FluidRegion filling(const BoxOrBall<Dim>& s, Float temperature = defaults::temperature) {
        FluidRegion r;
        r.shape = s, r.temperature = temperature;
        return r;
    }
};

/// A solid body inside the fluid, held fixed, made of boundary particles.
template <int Dim>
struct SolidBody : PlacedShape<Dim> {
    Float temperature = defaults::temperature;
    int material = 0;
    WallSlip slip = WallSlip::NO_SLIP;
    /// Thickness of the particle shell below the surface; 0 fills the whole body.
    Float thickness = 0;
};

/// A wall inside the box: boundary particles in a layer under the surface of its solid, as
/// thick as the box walls' layers (covering the kernel support); deeper inside, nothing.
template <int Dim>
struct InteriorWall : PlacedShape<Dim> {
    Vector<Dim> velocity{};  ///< prescribed surface velocity
    WallSlip slip = WallSlip::NO_SLIP;
    Float temperature = defaults::temperature;  ///< initial (or held) temperature
    int material = 0;
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
    std::vector<InteriorWall<Dim>> interiorWalls;

    /// Whether the side has layers of particles beyond it (a wall, an inlet or an outlet).
    bool hasWall(int axis, int side) const {
        return !domain.periodic[axis] && walls[axis][side].present;
    }
    /// Whether the side is a solid wall (not an inlet or outlet).
    bool isSolidWall(int axis, int side) const {
        return hasWall(axis, side) && walls[axis][side].layers == ParticleKind::WALL;
    }
    /// The kind of the particle at x beyond side `side` of `axis` alone: an inlet's or
    /// outlet's buffer across its opening where the water can reach the side (x moved onto the
    /// side is in no body or interior wall: a pipe entering through the side), else a wall.
    ParticleKind kindBeyond(int axis, int side, const Vector<Dim>& x) const {
        const WallSide<Dim>& w = walls[axis][side];
        if (w.layers == ParticleKind::WALL || !w.inOpening(x, axis)) return ParticleKind::WALL;
        Vector<Dim> onSide = x;
        onSide[axis] = side ? domain.max[axis] - 0.5 * spacing : domain.min[axis] + 0.5 * spacing;
        const auto holds = [&](const auto& solids) {
            return std::any_of(solids.begin(), solids.end(),
                               [&](const auto& b) { return b.contains(onSide); });
        };
        return holds(bodies) || holds(interiorWalls) ? ParticleKind::WALL : w.layers;
    }
    /// Whether any boundary particles exist: box walls, bodies or interior walls.
    bool hasBoundaries() const {
        bool any = !bodies.empty() || !interiorWalls.empty();
        for (int k = 0; k < Dim; ++k) any |= hasWall(k, 0) || hasWall(k, 1);
        return any;
    }
};

}  // namespace num::sph
