// Generalised wall boundary condition (Adami, Hu & Adams 2012, J. Comput. Phys. 231, 7057).
//
// Walls and bodies are layers of boundary particles w whose pressure and velocity are
// extrapolated from the fluid particles f around them (Shepard interpolation), before the
// pair loop:
//   p_w = [ sum_f p_f W_wf + (g - a_w) . sum_f rho_f (x_w - x_f) W_wf ] / sum_f W_wf   (eq. 27)
//   v~_w = sum_f v_f W_wf / sum_f W_wf                                                 (eq. 22)
//   no-slip:   v_w = 2 v_wall - v~_w   (eq. 23; used by the viscous terms and shifting only,
//                                     FluidId::PAIR_VELOCITY)
//   free-slip: the viscous terms skip the boundary particle
//   rho_w = rho(p_w) from the inverse equation of state                               (eq. 28)
// The temperature they show to conduction follows the same extrapolation in its own term
// (wall_temperature.hpp).
// g is the body force at time t; boundaries here are held fixed or slide tangentially at a
// prescribed surface velocity v_wall (WALL_VELOCITY; without that quantity every v_wall is
// zero), so a_w = 0. The pressure gradient then treats boundary particles as ordinary
// neighbours, which keeps fluid out of walls.
// A boundary particle with no fluid particle among its neighbour-list candidates has no fluid
// neighbour while the lists are kept (sum_f W_wf = 0): it takes the values of an empty sum,
// background pressure and v_w = v_wall, without a gather (boundary_near_fluid.hpp).
// The formulas: sph/formulas/wall_condition.hpp (host and device).
#pragma once

#include <functional>
#include <memory>

#include "sph/boundary/boundary_near_fluid.hpp"
#include "sph/formulas/wall_condition.hpp"
#include "sph/terms/equation_of_state.hpp"
#include "sph/terms/fluid_quantities.hpp"
#include "sph/terms/neighbour_gather.hpp"

namespace num::sph {

template <int Dim>
class GeneralizedWall : public IEquationTerm<Dim> {
  public:
    using Vec = Vector<Dim>;

    /// nearFluid: the split of the boundary particles, shared with the wall temperature.
    GeneralizedWall(std::shared_ptr<const NeighbourGather<Dim>> gather, EquationOfState eos,
                    std::function<Vec(Float)> bodyForce,
                    std::shared_ptr<BoundaryNearFluid<Dim>> nearFluid =
                        std::make_shared<BoundaryNearFluid<Dim>>())
        : gather_(std::move(gather)),
          eos_(eos),
          bodyForce_(std::move(bodyForce)),
          nearFluid_(std::move(nearFluid)) {}

    void setDerivatives(DerivativeHolder<Dim>&, const RunSettings&) override {}

    void initialize(IScheduler& scheduler, Storage<Dim>& s, Float t) override {
        const auto v = s.template getDt<Vec>(QuantityId::POSITION);
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        const bool sliding = s.has(QuantityId::WALL_VELOCITY);
        const auto wallVelocity =
            sliding ? s.template getValue<Vec>(QuantityId::WALL_VELOCITY) : ArrayView<const Vec>();
        const auto slip = s.template getValue<int>(FluidId::WALL_SLIP);
        auto rho = s.template getValue<Float>(QuantityId::DENSITY);
        auto p = s.template getValue<Float>(QuantityId::PRESSURE);
        auto vb = s.template getValue<Vec>(FluidId::PAIR_VELOCITY);
        const Vec g = bodyForce_ ? bodyForce_(t) : Vec{};
        nearFluid_->update(scheduler, s, gather_->lists());
        // Pressure, density and the pair velocity are written for boundary particles only,
        // which the gather never reads, so the passes are free of races.
        const auto emptySum = [&](Size w) {  // no fluid neighbour: sum_f W_wf = 0
            p[w] = eos_.backgroundPressure;
            vb[w] = sliding ? wallVelocity[w] : Vec{};
            rho[w] = eos_.density(p[w]);
        };
        const auto fluid = [&](Size j) { return isFluid(kind[j]); };
        gather_->forEachWhere(scheduler, nearFluid_->near(), fluid, [&](Size w, auto&& visit) {
            formulas::WallSums<Dim> sums;
            visit([&](Size f, const Vec& dx, Float, Float W) {
                sums.add(p[f], rho[f], v[f], 0.0, false, dx, W);
            });
            if (!sums.any()) return emptySum(w);
            const Vec wall = sliding ? wallVelocity[w] : Vec{};
            p[w] = formulas::wallPressure(sums, g);
            vb[w] = formulas::wallVelocity(sums, wall, slip[w] == int(WallSlip::NO_SLIP));
            rho[w] = eos_.density(p[w]);
        });
        const std::vector<Size>& far = nearFluid_->far();
        scheduler.parallelFor(Size(far.size()), 1024, [&](Size b, Size e) {
            for (Size k = b; k < e; ++k) emptySum(far[k]);
        });
    }
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}

    TermAccess access() const override {
        return {.reads = {QuantityId::PRESSURE, QuantityId::DENSITY},
                .prepares = {QuantityId::PRESSURE, QuantityId::DENSITY, FluidId::PAIR_VELOCITY}};
    }
    void create(Storage<Dim>& s, IMaterial&) const override {
        s.template insert<Vec>(FluidId::PAIR_VELOCITY, OrderEnum::ZERO, Vec{});
        s.template insert<int>(FluidId::WALL_SLIP, OrderEnum::ZERO, int(WallSlip::NO_SLIP));
    }

  private:
    std::shared_ptr<const NeighbourGather<Dim>> gather_;
    EquationOfState eos_;
    std::function<Vec(Float)> bodyForce_;
    std::shared_ptr<BoundaryNearFluid<Dim>> nearFluid_;
};

}  // namespace num::sph
