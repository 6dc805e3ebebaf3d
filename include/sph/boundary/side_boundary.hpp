// One side of the container box and its boundary type (a wall, a periodic axis, an open side):
// each type is one module, a header in this folder that implements ISideBoundary, one file
// with one contract (wall_boundary.hpp, periodic_boundary.hpp, open_boundary.hpp). An object
// is one side of one scene, with that side's parameters (a wall's velocity, slip and thermal
// condition). The contract, in the order a run meets it:
//   particle generation  build(): what the side puts into FluidGeometry: wall layers
//                        (FluidGeometry::walls) or a periodic axis (Domain::periodic)
//   thermal set-up       setThermal(): the thermal condition of its boundary particles
//   post-step sink       markLeaving(): fluid particles to remove after a step (open sides)
//   picture              pictureMargin(): how far the 2D picture shows beyond the side
//   what the set-up and the checks ask: closes(), wraps(), letsFluidOut(), surfaceSpeed(),
//                        heldTemperature()
// Terms: the types here add none of their own. A wall's terms (the wall condition, its
// temperature, the boundary hold, containment: makeFluidEquations in fluid_model.hpp) follow
// from the boundary particles, which bodies make too.
// Scene keys: the engine reads no scene file (the dependency runs engine <- app), so each type's
// keys are read app-side, by its entry in the one table of boundary types
// (src/scene/boundary_types.cpp): its `type` name, its keys beside "type" and the function that
// reads them into this module. The reader's allowed `type` values and their error text come
// from that table. A new type touches three files: its header here, its table entry, and its
// row in docs/scenes.md.
#pragma once

#include <optional>
#include <vector>

#include "sph/equation_term.hpp"
#include "sph/setup/fluid_geometry.hpp"

namespace num::sph {

template <int Dim>
class ISideBoundary {
  public:
    virtual ~ISideBoundary() = default;
    /// The scene's name of the type ("wall", "periodic", "open").
    virtual const char* type() const = 0;

    /// Particle generation: sets side `high` (0: at domain.min, 1: at domain.max) of `axis` in
    /// the geometry (walls[axis][high], domain.periodic[axis]). The side arrives as no wall
    /// (present = false) with the fluid's reference temperature and material.
    virtual void build(FluidGeometry<Dim>& geometry, int axis, int high) const = 0;
    /// Thermal set-up, with heat: the boundary particles that lie beyond this side (storage
    /// indices; `depth` their distance beyond it [m]) of a side of `area` [m^2] (in 2D a
    /// length) take their thermal condition (thermal_condition.hpp).
    virtual void setThermal(Storage<Dim>&, const std::vector<Size>& /*beyond*/,
                            const std::vector<Float>& /*depth*/, Float /*area*/,
                            Float /*spacing*/) const {}
    /// Post-step sink: sets leaving[i] for each fluid particle i to be removed after the step;
    /// `bound` is the side's coordinate on its axis.
    virtual void markLeaving(const Storage<Dim>&, int /*axis*/, int /*high*/, Float /*bound*/,
                             std::vector<char>& /*leaving*/) const {}
    /// The picture: how far beyond the side the 2D picture shows [m], given the wall layers.
    virtual Float pictureMargin(int /*wallLayers*/, Float /*spacing*/) const { return 0; }

    /// The side keeps fluid in: a closed box has no other sides; fluid beyond it is a failure.
    virtual bool closes() const { return false; }
    /// The side wraps to the opposite one (both sides of its axis must then be of its type).
    virtual bool wraps() const { return false; }
    /// Fluid can leave through the side (a free surface; markLeaving removes what leaves).
    virtual bool letsFluidOut() const { return false; }
    /// The speed the side moves fluid at [m/s] (a velocity scale of the flow).
    virtual Float surfaceSpeed() const { return 0; }
    /// The temperature the side holds [degC], if it holds one.
    virtual std::optional<Float> heldTemperature() const { return std::nullopt; }
};

}  // namespace num::sph
