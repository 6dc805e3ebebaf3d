// A wall side: layers of boundary particles outside the box, seen by the fluid through the
// generalised wall condition (Adami, Hu & Adams 2012; generalized_wall.hpp) and, with heat, as
// adiabatic, held at a temperature (wall_temperature.hpp) or delivering a heat flux
// (thermal_walls.hpp). It may slide along itself at a prescribed velocity (a Couette or cavity
// lid) and be no-slip or free-slip.
#pragma once

#include "sph/boundary/side_boundary.hpp"
#include "sph/boundary/thermal_walls.hpp"

namespace num::sph {

/// A wall's thermal side: ADIABATIC, FIXED_TEMPERATURE (`value` held) or HEAT_FLUX (`value`
/// into the fluid; its particles conduct).
struct WallThermal {
    ThermalCondition condition = ThermalCondition::ADIABATIC;
    Float value = 0;  ///< temperature [degC] or heat flux into the fluid [W/m^2]
};

template <int Dim>
class WallBoundary : public ISideBoundary<Dim> {
  public:
    WallBoundary(Vector<Dim> velocity, WallSlip slip, WallThermal thermal)
        : velocity_(velocity), slip_(slip), thermal_(thermal) {}

    const char* type() const override { return "wall"; }
    void build(FluidGeometry<Dim>& geometry, int axis, int high) const override {
        WallSide<Dim>& w = geometry.walls[axis][high];
        w.present = true;
        w.velocity = velocity_;
        w.slip = slip_;
        if (const auto held = heldTemperature()) w.temperature = *held;
    }
    /// Adiabatic, fixed temperature, or conducting with the heat flux spread over the layer
    /// next to the fluid (depth below one spacing): q'' A enters the domain.
    void setThermal(Storage<Dim>& s, const std::vector<Size>& beyond,
                    const std::vector<Float>& depth, Float area, Float spacing) const override {
        const bool flux = thermal_.condition == ThermalCondition::HEAT_FLUX;
        const ThermalCondition condition = flux ? ThermalCondition::CONDUCTING : thermal_.condition;
        const auto cond = s.template getValue<int>(heat_ids::THERMAL_CONDITION);
        std::vector<char> layer(s.size(), 0);
        bool anyLayer = false;
        for (std::size_t k = 0; k < beyond.size(); ++k) {
            cond[beyond[k]] = int(condition);
            if (depth[k] < spacing) layer[beyond[k]] = 1, anyLayer = true;
        }
        if (!flux || !anyLayer) return;
        ThermalBoundary<Dim>::setHeatFlux(s, thermal_.value, area,
                                          [&](Size i) { return layer[i] != 0; });
    }
    Float pictureMargin(int wallLayers, Float spacing) const override {
        return wallLayers * spacing;
    }
    bool closes() const override { return true; }
    Float surfaceSpeed() const override { return norm(velocity_); }
    std::optional<Float> heldTemperature() const override {
        if (thermal_.condition != ThermalCondition::FIXED_TEMPERATURE) return std::nullopt;
        return thermal_.value;
    }

    const Vector<Dim>& velocity() const { return velocity_; }
    WallSlip slip() const { return slip_; }
    const WallThermal& thermal() const { return thermal_; }

  private:
    Vector<Dim> velocity_;
    WallSlip slip_;
    WallThermal thermal_;
};

}  // namespace num::sph
