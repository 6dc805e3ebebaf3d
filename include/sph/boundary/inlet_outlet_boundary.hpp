// An inlet or an outlet side: its layers are the buffer of an open boundary
// (flow_boundaries.hpp says what the buffers do). An inlet imposes a velocity (of the position
// on the side and of time) and optionally a temperature; an outlet a pressure. Either may open
// a part of the side only (FlowSide::openFrom, openTo), the rest being a wall. The run's
// FlowBoundaries is made from these sides (FlowBoundaries::sides), each side's spec completed
// with its place (flowSide()).
#pragma once

#include <optional>

#include "sph/boundary/flow_boundaries.hpp"
#include "sph/boundary/side_boundary.hpp"

namespace num::sph {

template <int Dim>
class InletOutletBoundary : public ISideBoundary<Dim> {
  public:
    /// spec: its kind and imposed values (axis, side, plane and depth are set by flowSide);
    /// heldTemperature: an inlet's temperature where it is one number.
    InletOutletBoundary(FlowSide<Dim> spec, std::optional<Float> heldTemperature)
        : spec_(std::move(spec)), held_(heldTemperature) {}

    const char* type() const override {
        return spec_.kind == ParticleKind::INLET ? "inlet" : "outlet";
    }
    void build(FluidGeometry<Dim>& geometry, int axis, int high) const override {
        WallSide<Dim>& w = geometry.walls[axis][high];
        w.present = true;
        w.layers = spec_.kind;
        w.openFrom = spec_.openFrom, w.openTo = spec_.openTo;
        if (held_) w.temperature = *held_;
    }
    Float pictureMargin(int wallLayers, Float spacing) const override {
        return wallLayers * spacing;
    }
    std::optional<Float> heldTemperature() const override { return held_; }

    /// The side's spec at side `high` of `axis` of the domain, with a buffer `depth` deep.
    FlowSide<Dim> flowSide(const Domain<Dim>& domain, int axis, int high, Float depth) const {
        FlowSide<Dim> side = spec_;
        side.axis = axis, side.high = high, side.depth = depth;
        side.plane = high ? domain.max[axis] : domain.min[axis];
        return side;
    }
    ParticleKind kind() const { return spec_.kind; }
    const FlowSide<Dim>& spec() const { return spec_; }

  private:
    FlowSide<Dim> spec_;
    std::optional<Float> held_;
};

}  // namespace num::sph
