// The temperature a wall or body shows to heat conduction (the wall condition of Adami, Hu &
// Adams 2012, J. Comput. Phys. 231, 7057, eq. 22-23, applied to the temperature):
//   T_w = 2 T_wall - T~_w,  T~_w = sum_f T_f W_wf / sum_f W_wf
// for a fixed-temperature boundary particle w (heat_ids::THERMAL_CONDITION, thermal_walls.hpp)
// with fluid neighbours f; every other boundary particle shows its own temperature. The result
// is heat_ids::BOUNDARY_TEMPERATURE, which terms/heat_conduction.hpp reads. Mirroring puts the
// prescribed temperature on the wall surface, not on the boundary particles' centres: holding
// T_wall on every layer instead puts the effective wall about 0.3 dx outside the box, and steady
// conduction between two walls 25 dx apart then carried 2.3 % too little heat.
// Without thermal conditions (no heat conduction) it does nothing.
// The formula: sph/formulas/wall_condition.hpp (host and device).
#pragma once

#include <memory>

#include "sph/boundary/boundary_near_fluid.hpp"
#include "sph/boundary/thermal_condition.hpp"
#include "sph/formulas/wall_condition.hpp"

namespace num::sph {

template <int Dim>
class WallTemperature : public IEquationTerm<Dim> {
  public:
    using Vec = Vector<Dim>;

    WallTemperature(std::shared_ptr<const NeighbourGather<Dim>> gather,
                    std::shared_ptr<BoundaryNearFluid<Dim>> nearFluid)
        : gather_(std::move(gather)), nearFluid_(std::move(nearFluid)) {}

    void setDerivatives(DerivativeHolder<Dim>&, const RunSettings&) override {}

    void initialize(IScheduler& scheduler, Storage<Dim>& s, Float) override {
        if (!s.has(heat_ids::THERMAL_CONDITION) || !s.has(heat_ids::BOUNDARY_TEMPERATURE)) return;
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        const auto T = s.template getValue<Float>(QuantityId::TEMPERATURE);
        const auto cond = s.template getValue<int>(heat_ids::THERMAL_CONDITION);
        auto Tb = s.template getValue<Float>(heat_ids::BOUNDARY_TEMPERATURE);
        nearFluid_->update(scheduler, s, gather_->lists());
        const std::vector<Size>& near = nearFluid_->near();
        const auto fluid = [&](Size j) { return isFluid(kind[j]); };
        // Tb is written for boundary particles only, which the gather never reads.
        gather_->forEachWhere(scheduler, near, fluid, [&](Size w, auto&& visit) {
            const bool fixed = cond[w] == int(ThermalCondition::FIXED_TEMPERATURE);
            formulas::WallSums<Dim> sums;
            if (fixed)
                visit([&](Size f, const Vec&, Float, Float W) { sums.w += W, sums.T += T[f] * W; });
            Tb[w] = sums.any() ? formulas::wallTemperature(sums, T[w], fixed) : T[w];
        });
        const std::vector<Size>& far = nearFluid_->far();
        scheduler.parallelFor(Size(far.size()), 1024, [&](Size b, Size e) {
            for (Size k = b; k < e; ++k) Tb[far[k]] = T[far[k]];
        });
    }
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}

    TermAccess access() const override {
        return {.reads = {QuantityId::TEMPERATURE}, .prepares = {heat_ids::BOUNDARY_TEMPERATURE}};
    }
    void create(Storage<Dim>& s, IMaterial&) const override {
        if (!s.has(QuantityId::TEMPERATURE)) return;
        // Each particle starts showing its own temperature.
        const auto T = s.template getValue<Float>(QuantityId::TEMPERATURE);
        s.template insert<Float>(heat_ids::BOUNDARY_TEMPERATURE, OrderEnum::ZERO,
                                 std::vector<Float>(T.begin(), T.end()));
    }

  private:
    std::shared_ptr<const NeighbourGather<Dim>> gather_;
    std::shared_ptr<BoundaryNearFluid<Dim>> nearFluid_;
};

}  // namespace num::sph
