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
//   T_w = 2 T_wall - T~_w,  T~_w = sum_f T_f W_wf / sum_f W_wf  (fixed-temperature particles;
//         the temperature conduction sees, heat_ids::BOUNDARY_TEMPERATURE)
// The temperature follows eq. 22-23 as the velocity does: it puts the prescribed temperature on
// the wall surface, not on the boundary particles' centres. Holding T_wall on every layer
// instead puts the effective wall about 0.3 dx outside the box: steady conduction between two
// walls 25 dx apart then carried 2.3 % too little heat.
// g is the body force at time t; boundaries here are held fixed or slide tangentially at a
// prescribed surface velocity v_wall (WALL_VELOCITY; without that quantity every v_wall is
// zero), so a_w = 0. The pressure gradient then treats boundary particles as ordinary
// neighbours, which keeps fluid out of walls.
// A boundary particle with no fluid particle among its neighbour-list candidates has no fluid
// neighbour while the lists are kept (sum_f W_wf = 0): it takes the values of an empty sum,
// background pressure and v_w = v_wall, without a gather. Most of a tank's wall particles are
// such (the shipped 3D dam break: 13,116 of its 16,491 particles are walls); which are is found
// again at each build of the lists.
// The formulas: sph/formulas/wall_condition.hpp (host and device).
#pragma once

#include <functional>
#include <memory>

#include "sph/boundary/thermal_condition.hpp"
#include "sph/formulas/wall_condition.hpp"
#include "sph/terms/equation_of_state.hpp"
#include "sph/terms/fluid_quantities.hpp"
#include "sph/terms/neighbour_gather.hpp"

namespace num::sph {

template <int Dim>
class GeneralizedWall : public IEquationTerm<Dim> {
  public:
    using Vec = Vector<Dim>;

    GeneralizedWall(std::shared_ptr<const NeighbourGather<Dim>> gather, EquationOfState eos,
                    std::function<Vec(Float)> bodyForce)
        : gather_(std::move(gather)), eos_(eos), bodyForce_(std::move(bodyForce)) {}

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
        const bool heat =
            s.has(heat_ids::THERMAL_CONDITION) && s.has(heat_ids::BOUNDARY_TEMPERATURE);
        const auto T = s.template getValue<Float>(QuantityId::TEMPERATURE);
        const auto cond =
            heat ? s.template getValue<int>(heat_ids::THERMAL_CONDITION) : ArrayView<const int>();
        auto Tb =
            heat ? s.template getValue<Float>(heat_ids::BOUNDARY_TEMPERATURE) : ArrayView<Float>();
        const Vec g = bodyForce_ ? bodyForce_(t) : Vec{};
        findBoundaryNearFluid(scheduler, s);
        // Pressure, density and the pair velocity are written for boundary particles only,
        // which the gather never reads, so the passes are free of races.
        const auto emptySum = [&](Size w) {  // no fluid neighbour: sum_f W_wf = 0
            p[w] = eos_.backgroundPressure;
            vb[w] = sliding ? wallVelocity[w] : Vec{};
            rho[w] = eos_.density(p[w]);
            if (heat) Tb[w] = T[w];
        };
        const auto fluid = [&](Size j) { return isFluid(kind[j]); };
        gather_->forEachWhere(scheduler, nearFluid_, fluid, [&](Size w, auto&& visit) {
            formulas::WallSums<Dim> sums;
            visit([&](Size f, const Vec& dx, Float, Float W) {
                sums.add(p[f], rho[f], v[f], heat ? T[f] : 0.0, heat, dx, W);
            });
            if (!sums.any()) return emptySum(w);
            const Vec wall = sliding ? wallVelocity[w] : Vec{};
            p[w] = formulas::wallPressure(sums, g);
            vb[w] = formulas::wallVelocity(sums, wall, slip[w] == int(WallSlip::NO_SLIP));
            rho[w] = eos_.density(p[w]);
            if (heat)
                Tb[w] = formulas::wallTemperature(
                    sums, T[w], cond[w] == int(ThermalCondition::FIXED_TEMPERATURE));
        });
        scheduler.parallelFor(Size(farFromFluid_.size()), 1024, [&](Size b, Size e) {
            for (Size k = b; k < e; ++k) emptySum(farFromFluid_[k]);
        });
    }
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}

    TermAccess access() const override {
        return {.reads = {QuantityId::PRESSURE, QuantityId::DENSITY, QuantityId::TEMPERATURE},
                .prepares = {QuantityId::PRESSURE, QuantityId::DENSITY, FluidId::PAIR_VELOCITY,
                             heat_ids::BOUNDARY_TEMPERATURE}};
    }
    void create(Storage<Dim>& s, IMaterial&) const override {
        s.template insert<Vec>(FluidId::PAIR_VELOCITY, OrderEnum::ZERO, Vec{});
        s.template insert<int>(FluidId::WALL_SLIP, OrderEnum::ZERO, int(WallSlip::NO_SLIP));
        if (s.has(QuantityId::TEMPERATURE)) {  // each particle starts showing its own temperature
            const auto T = s.template getValue<Float>(QuantityId::TEMPERATURE);
            s.template insert<Float>(heat_ids::BOUNDARY_TEMPERATURE, OrderEnum::ZERO,
                                     std::vector<Float>(T.begin(), T.end()));
        }
    }

  private:
    /// Splits the boundary particles by whether a fluid particle is among their candidates, once
    /// per build of the lists (a reordering or a new particle count rebuilds them).
    void findBoundaryNearFluid(IScheduler& scheduler, const Storage<Dim>& s) {
        const VerletList<Dim>& lists = gather_->lists();
        const ListBuild build{&lists, lists.builds(), s.size()};
        if (build == sortedFor_) return;
        sortedFor_ = build;
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        const std::vector<Size> boundary = particlesWhere(s, [](int k) { return !isFluid(k); });
        std::vector<char> near(boundary.size(), 0);
        scheduler.parallelFor(Size(boundary.size()), 256, [&](Size b, Size e) {
            for (Size k = b; k < e; ++k)
                lists.forEachCandidate(boundary[k], [&](Size j) { near[k] |= isFluid(kind[j]); });
        });
        nearFluid_.clear(), farFromFluid_.clear();
        for (std::size_t k = 0; k < boundary.size(); ++k)
            (near[k] ? nearFluid_ : farFromFluid_).push_back(boundary[k]);
    }

    struct ListBuild {
        const VerletList<Dim>* lists = nullptr;
        std::size_t builds = 0;
        Size particles = 0;
        bool operator==(const ListBuild&) const = default;
    };

    std::shared_ptr<const NeighbourGather<Dim>> gather_;
    EquationOfState eos_;
    std::function<Vec(Float)> bodyForce_;
    ListBuild sortedFor_;                         // the build the split below was made for
    std::vector<Size> nearFluid_, farFromFluid_;  // boundary particles with(out) fluid candidates
};

}  // namespace num::sph
