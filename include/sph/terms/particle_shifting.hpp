// Particle shifting (Lind, Xu, Stansby & Rogers 2012, J. Comput. Phys. 231, 1499, eq. 9, 15
// and 17) in the form of the delta-plus-SPH model (Sun, Colagrossi, Marrone & Zhang 2017,
// Comput. Methods Appl. Mech. Engrg. 315, 25, sec. 3): after each step, fluid particles are
// moved down the gradient of the particle concentration,
//   dr_i = -A h c0 dt sum_j V_j [1 + R max(0, (W_ij / W(dx_ij))^4 - 1.5)] grad_i W_ij,
// A = 0.5, R = 0.6. The displacement scales with the sound speed, not with a guessed flow speed:
// per step of the acoustic limit dt = C h / c0 it is a fixed fraction A C of h^2 grad C.
// The R term (after Monaghan 2000, J. Comput. Phys. 159, 290) pushes apart pairs closer than
// about 0.9 of the local spacing dx_ij (W(dx_ij) the mean of W(V^(1/Dim)) of i and j), which
// stops the clumping at the stagnation points of the Taylor-Green vortex. The threshold 1.5 is
// ours: with Sun et al.'s 1 + 0.2 (W_ij / W(dx))^4 the slight anisotropic compression of water at
// rest under gravity (the walls fix the horizontal spacing) drives particles upwards, and a
// 2D tank at rest churned at 0.4 m/s and collapsed within 3 s.
// Measured on the Taylor-Green vortex, Re = 100, 50 x 50, t = 2 (max|v| error, l1 error of
// the speed): this form -0.2 %, 2.1 %; Sun et al.'s R term +0.6 %, 2.3 % (tank unstable); R
// above the threshold with R = 0.2: -3.5 %, 6.3 %; no R term: -27 %; no shifting: -73 %.
// Velocity and density are corrected to the new position by a Taylor expansion,
//   v_i += (dr_i . grad) v_i,   rho_i += dr_i . grad rho_i,
//   (grad v)_i = sum_j V_j (v_j - v_i) (x) grad_i W_ij,  grad rho_i = sum_j V_j (rho_j - rho_i)
//   grad_i W_ij,
// so the flow field is not carried with the particles. |dr_i| is capped at 0.1 h. Particles at
// a free surface (kernel sum C_i < 0.9, terms/free_surface.hpp) or within a kernel support of
// one are not shifted: there grad C points into the fluid because the support is cut, and
// shifting would push particles out through the surface (measured: a 2D tank at rest rose by
// 2.5 % of its depth and churned at 0.8 m/s within 3 s). Within a kernel support of a wall or
// body, the component of dr along the wall direction n_i = sum_{j wall} V_j grad_i W_ij is
// removed, dr -= n (dr . n) / |n|^2: particles are shifted along walls, never towards or away
// from them, as at a free surface (Lind et al. 2012, sec. 3.3). The wall's dummy particles keep
// a concentration gradient across the boundary layer; shifting along it moves particles
// against the pressure that holds them, which acts as a flow through the wall and damps the
// boundary layer. Measured at 50 x 50 (largest error on the references / their scale):
// lid-driven cavity, Re = 100, t = 20, Ghia et al.'s u and v lines: shifting along n too
// 0.102, not near walls 0.056, along walls only 0.040, no shifting 0.051 (before the lid's mass
// source left the continuity equation; with that fix, along walls only: 0.026); natural
// convection, Ra = 1e4, u_max, v_max, Nu against de Vahl Davis: 6.1, 7.1, 1.7 % with shifting
// along n, 3.2, 4.1, 0.6 % along walls only.
// Phases: the pair sums (grad C, grad rho, grad v, the wall and surface flags) are made in
// every evaluation; particles are moved once per step, in postStep, after the integrator, with
// the step's dt and the sums of the step's last evaluation (at the end of the step).
// The pair formulas: sph/formulas/fluid_pairs.hpp.
#pragma once

#include <algorithm>
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "sph/formulas/fluid_pairs.hpp"
#include "sph/formulas/fluid_particles.hpp"
#include "sph/formulas/post_step.hpp"
#include "sph/kernel_choice.hpp"
#include "sph/terms/fluid_quantities.hpp"
#include "sph/terms/free_surface.hpp"
#include "sph/terms/pair_inputs.hpp"

namespace num::sph {

template <int Dim>
struct ShiftingData {
    std::vector<Float> inverseWAtSpacing;  // 1 / W(dx_i), dx_i = V_i^(1/Dim) the local spacing
};

template <int Dim>
inline QuantityId velocityGradientId(int column) {
    return QuantityId(int(FluidId::VELOCITY_GRADIENT_0) + column);
}

template <int Dim>
class ParticleShiftingPart : public DerivativeTemplate<ParticleShiftingPart<Dim>, Dim> {
  public:
    using Vec = Vector<Dim>;
    explicit ParticleShiftingPart(std::shared_ptr<const ShiftingData<Dim>> data)
        : data_(std::move(data)) {}

    bool needsKernelValues() const override { return true; }
    /// The gather writes fluid particles' sums only: only they are shifted.
    bool gathersAtBoundary(Size) const override { return false; }
    void create(Accumulated<Dim>& r) override {
        r.template insert<Vec>(FluidId::KERNEL_SUM_GRADIENT, OrderEnum::ZERO);
        r.template insert<Vec>(FluidId::DENSITY_GRADIENT, OrderEnum::ZERO);
        r.template insert<Vec>(FluidId::WALL_DIRECTION, OrderEnum::ZERO);
        for (int b = 0; b < Dim; ++b)
            r.template insert<Vec>(velocityGradientId<Dim>(b), OrderEnum::ZERO);
    }
    void initialize(const Storage<Dim>& s, Accumulated<Dim>& r) override {
        rho_ = s.template getValue<Float>(QuantityId::DENSITY);
        kind_ = s.template getValue<int>(QuantityId::KIND);
        volume_ = s.template getValue<Float>(FluidId::VOLUME);
        velocity_ = s.template getValue<Vec>(FluidId::PAIR_VELOCITY);
        gradC_ = r.template getValue<Vec>(FluidId::KERNEL_SUM_GRADIENT);
        gradRho_ = r.template getValue<Vec>(FluidId::DENSITY_GRADIENT);
        wallDirection_ = r.template getValue<Vec>(FluidId::WALL_DIRECTION);
        for (int b = 0; b < Dim; ++b)
            gradV_[b] = r.template getValue<Vec>(velocityGradientId<Dim>(b));
    }
    template <bool Symmetric>
    void eval(Size i, Size j, const Vec& grad, const PairGeometry<Dim>& pair) {
        const ShiftingData<Dim>& d = *data_;
        const Float vi = volume_[i], vj = volume_[j];
        const Vec dv = velocity_[j] - velocity_[i];
        const Float drho = rho_[j] - rho_[i];
        const Vec gradR = grad * formulas::shiftingTensileFactor(pair.w, d.inverseWAtSpacing[i],
                                                                 d.inverseWAtSpacing[j]);
        gradC_[i] += gradR * vj;
        gradRho_[i] += formulas::densityGradientTerm(grad, vj, drho);
        if (!isFluid(kind_[j])) wallDirection_[i] += grad * vj;
        for (int b = 0; b < Dim; ++b)
            gradV_[b][i] += formulas::velocityGradientTerm(dv, vj, grad[b]);
        if constexpr (Symmetric) {
            if (!isFluid(kind_[i])) wallDirection_[j] -= grad * vi;
            gradC_[j] -= gradR * vi;
            gradRho_[j] += formulas::densityGradientTerm(grad, vi, drho);
            for (int b = 0; b < Dim; ++b)
                gradV_[b][j] += formulas::velocityGradientTerm(dv, vi, grad[b]);
        }
    }
    /// Gather (asymmetric) evaluation: the particle's own data read once and its sums kept in
    /// registers, with eval's formulas in eval's order, so the result is bitwise eval's.
    void gatherNeighbours(Size i, ArrayView<const Size> neighs, ArrayView<const Vec> grads,
                          const NeighbourGeometry<Dim>& geometry) {
        const Float* inverseWAtSpacing = data_->inverseWAtSpacing.data();
        const Vec velocityI = velocity_[i];
        const Float rhoI = rho_[i], inverseWI = inverseWAtSpacing[i];
        Vec gradC = gradC_[i], gradRho = gradRho_[i], wallDirection = wallDirection_[i];
        std::array<Vec, Dim> gradV;
        for (int b = 0; b < Dim; ++b) gradV[b] = gradV_[b][i];
        for (std::size_t k = 0; k < neighs.size(); ++k) {
            const Size j = neighs[k];
            const Vec& grad = grads[k];
            const Float vj = volume_[j];
            const Vec dv = velocity_[j] - velocityI;
            const Float drho = rho_[j] - rhoI;
            gradC +=
                grad *
                formulas::shiftingTensileFactor(geometry.w[k], inverseWI, inverseWAtSpacing[j]) *
                vj;
            gradRho += formulas::densityGradientTerm(grad, vj, drho);
            if (!isFluid(kind_[j])) wallDirection += grad * vj;
            for (int b = 0; b < Dim; ++b)
                gradV[b] += formulas::velocityGradientTerm(dv, vj, grad[b]);
        }
        gradC_[i] = gradC, gradRho_[i] = gradRho, wallDirection_[i] = wallDirection;
        for (int b = 0; b < Dim; ++b) gradV_[b][i] = gradV[b];
    }

  private:
    std::shared_ptr<const ShiftingData<Dim>> data_;
    ArrayView<const Float> rho_, volume_;
    ArrayView<const int> kind_;
    ArrayView<const Vec> velocity_;
    ArrayView<Vec> gradC_, gradRho_;
    ArrayView<Vec> wallDirection_;
    std::array<ArrayView<Vec>, Dim> gradV_;
};

template <int Dim>
class ParticleShifting : public IEquationTerm<Dim> {
  public:
    using Vec = Vector<Dim>;
    /// coefficient: A in dr = -A h c0 dt grad C; soundSpeed: c0; normalToWalls: keep the
    /// component of dr towards or away from walls and bodies (see the top of this file).
    ParticleShifting(Float coefficient, Float soundSpeed, bool normalToWalls)
        : coefficient_(coefficient), soundSpeed_(soundSpeed), normalToWalls_(normalToWalls) {}

    void setDerivatives(DerivativeHolder<Dim>& d, const RunSettings& settings) override {
        kernel_.emplace(settings);
        d.template require<ParticleShiftingPart<Dim>>(data_);
        d.template require<KernelSumPart<Dim>>(kernel_->W(0));
    }
    void initialize(IScheduler& scheduler, Storage<Dim>& s, Float) override {
        const auto volume = s.template getValue<Float>(FluidId::VOLUME);
        ShiftingData<Dim>& d = *data_;
        d.inverseWAtSpacing.resize(s.size());
        scheduler.parallelFor(s.size(), 4096, [&](Size b, Size e) {
            for (Size i = b; i < e; ++i)
                d.inverseWAtSpacing[i] = 1 / kernel_->W(formulas::particleSpacing<Dim>(volume[i]));
        });
    }
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}
    /// Moves the fluid particles by dr (the equation at the top) with the sums of the step's
    /// last evaluation; dt is the step.
    void postStep(IScheduler& scheduler, Storage<Dim>& s, Float, Float dt) override {
        auto x = s.template getValue<Vec>(QuantityId::POSITION);
        auto v = s.template getDt<Vec>(QuantityId::POSITION);
        auto rho = s.template getValue<Float>(QuantityId::DENSITY);
        const auto c = s.template getValue<Float>(FluidId::KERNEL_SUM);
        const auto nearSurface = s.template getValue<Float>(FluidId::SURFACE_NEIGHBOURS);
        const auto wallDirection = s.template getValue<Vec>(FluidId::WALL_DIRECTION);
        const auto gradC = s.template getValue<Vec>(FluidId::KERNEL_SUM_GRADIENT);
        const auto gradRho = s.template getValue<Vec>(FluidId::DENSITY_GRADIENT);
        std::array<ArrayView<const Vec>, Dim> gradV;
        for (int b = 0; b < Dim; ++b)
            gradV[b] = s.template getValue<Vec>(velocityGradientId<Dim>(b));
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        const auto volume = s.template getValue<Float>(FluidId::VOLUME);
        const Float h = kernel_->h, w0 = kernel_->W(0);
        const Float diffusion = coefficient_ * h * soundSpeed_ * dt, cap = 0.1 * h;
        const bool continuity = s.order(QuantityId::DENSITY) >= OrderEnum::FIRST;
        scheduler.parallelFor(s.size(), 4096, [&](Size b, Size e) {
            for (Size i = b; i < e; ++i) {
                if (!isFluid(kind[i]) || atFreeSurface(c[i], volume[i], w0) || nearSurface[i] > 0 ||
                    !(dt > 0))
                    continue;
                const Vec dr = formulas::shiftingDisplacement(gradC[i], wallDirection[i], diffusion,
                                                              cap, normalToWalls_);
                Vec columns[Dim];
                for (int k = 0; k < Dim; ++k) columns[k] = gradV[k][i];
                formulas::shiftParticle<Dim>(x[i], v[i], rho[i], continuity, dr, gradRho[i],
                                             columns);
            }
        });
    }
    TermAccess access() const override {
        return {.reads = {QuantityId::DENSITY},
                .needs = {pairVolume, pairVelocity},
                .produces = {FluidId::KERNEL_SUM_GRADIENT, FluidId::DENSITY_GRADIENT,
                             FluidId::WALL_DIRECTION}};
    }
    void create(Storage<Dim>& s, IMaterial&) const override {
        s.template insert<Float>(FluidId::KERNEL_SUM, OrderEnum::ZERO, 1.0);
        s.template insert<Float>(FluidId::SURFACE_NEIGHBOURS, OrderEnum::ZERO, 0.0);
        s.template insert<Vec>(FluidId::KERNEL_SUM_GRADIENT, OrderEnum::ZERO, Vec{});
        s.template insert<Vec>(FluidId::DENSITY_GRADIENT, OrderEnum::ZERO, Vec{});
        s.template insert<Vec>(FluidId::WALL_DIRECTION, OrderEnum::ZERO, Vec{});
        for (int b = 0; b < Dim; ++b)
            s.template insert<Vec>(velocityGradientId<Dim>(b), OrderEnum::ZERO, Vec{});
    }

  private:
    Float coefficient_, soundSpeed_;
    bool normalToWalls_;
    std::optional<RunKernel<Dim>> kernel_;
    std::shared_ptr<ShiftingData<Dim>> data_ = std::make_shared<ShiftingData<Dim>>();
};

}  // namespace num::sph
