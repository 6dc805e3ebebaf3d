// Particle shifting (Lind, Xu, Stansby & Rogers 2012, J. Comput. Phys. 231, 1499, eq. 9, 15
// and 17): after each step, fluid particles are moved down the gradient of the particle
// concentration,
//   C_i = sum_j V_j W_ij,   dr_i = -A h U dt grad C_i,   grad C_i = sum_j V_j grad_i W_ij,
// and their velocity and density are corrected to the new position by a Taylor expansion,
//   v_i += (dr_i . grad) v_i,   rho_i += dr_i . grad rho_i,
//   (grad v)_i = sum_j V_j (v_j - v_i) (x) grad_i W_ij,  grad rho_i = sum_j V_j (rho_j - rho_i)
//   grad_i W_ij,
// which keeps the particle distribution regular in long runs (Taylor-Green vortex, shear
// flows) without transporting the flow field with the particles. U is the flow's velocity
// scale and dt the step just taken (the time between two evaluations). Lind et al. quote
// A = 1 to 6 for incompressible SPH; with weakly-compressible SPH the Taylor-Green vortex
// needs A = 10 to 30 (measured: at A = 2 the lattice still collapses at the hyperbolic
// stagnation points near t = 0.15 for U = 1). |dr_i| is capped at 0.1 h. Particles with C_i < 0.9
// (a free surface nearby) are not shifted, so surfaces do not diffuse. The displacement per unit
// time is kept in SHIFT.
#pragma once

#include <algorithm>
#include <memory>
#include <optional>
#include <vector>

#include "sph/kernel_choice.hpp"
#include "sph/terms/fluid_quantities.hpp"

namespace num::sph {

template <int Dim>
struct ShiftingData {
    std::vector<Float> volume;
    std::vector<Vector<Dim>> velocity;  // fluid: v; boundary: the wall condition's velocity
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
    void create(Accumulated<Dim>& r) override {
        r.template insert<Float>(FluidId::KERNEL_SUM, OrderEnum::ZERO);
        r.template insert<Vec>(FluidId::KERNEL_SUM_GRADIENT, OrderEnum::ZERO);
        r.template insert<Vec>(FluidId::DENSITY_GRADIENT, OrderEnum::ZERO);
        for (int b = 0; b < Dim; ++b)
            r.template insert<Vec>(velocityGradientId<Dim>(b), OrderEnum::ZERO);
    }
    void initialize(const Storage<Dim>& s, Accumulated<Dim>& r) override {
        rho_ = s.template getValue<Float>(QuantityId::DENSITY);
        c_ = r.template getValue<Float>(FluidId::KERNEL_SUM);
        gradC_ = r.template getValue<Vec>(FluidId::KERNEL_SUM_GRADIENT);
        gradRho_ = r.template getValue<Vec>(FluidId::DENSITY_GRADIENT);
        for (int b = 0; b < Dim; ++b)
            gradV_[b] = r.template getValue<Vec>(velocityGradientId<Dim>(b));
    }
    template <bool Symmetric>
    void eval(Size i, Size j, const Vec& grad, const PairGeometry<Dim>& pair) {
        const ShiftingData<Dim>& d = *data_;
        const Float vi = d.volume[i], vj = d.volume[j];
        const Vec dv = d.velocity[j] - d.velocity[i];
        const Float drho = rho_[j] - rho_[i];
        c_[i] += vj * pair.w;
        gradC_[i] += grad * vj;
        gradRho_[i] += grad * (vj * drho);
        for (int b = 0; b < Dim; ++b) gradV_[b][i] += dv * (vj * grad[b]);
        if constexpr (Symmetric) {
            c_[j] += vi * pair.w;
            gradC_[j] -= grad * vi;
            gradRho_[j] += grad * (vi * drho);
            for (int b = 0; b < Dim; ++b) gradV_[b][j] += dv * (vi * grad[b]);
        }
    }

  private:
    std::shared_ptr<const ShiftingData<Dim>> data_;
    ArrayView<const Float> rho_;
    ArrayView<Float> c_;
    ArrayView<Vec> gradC_, gradRho_;
    std::array<ArrayView<Vec>, Dim> gradV_;
};

template <int Dim>
class ParticleShifting : public IEquationTerm<Dim> {
  public:
    using Vec = Vector<Dim>;
    /// coefficient: A; velocityScale: U.
    ParticleShifting(Float coefficient, Float velocityScale)
        : coefficient_(coefficient), velocityScale_(velocityScale) {}

    void setDerivatives(DerivativeHolder<Dim>& d, const RunSettings& settings) override {
        d.template require<ParticleShiftingPart<Dim>>(data_);
        kernel_.emplace(settings);
    }
    void initialize(IScheduler& scheduler, Storage<Dim>& s, Float) override {
        const auto m = s.template getValue<Float>(QuantityId::MASS);
        const auto rho = s.template getValue<Float>(QuantityId::DENSITY);
        const auto v = s.template getDt<Vec>(QuantityId::POSITION);
        const auto vb = s.template getValue<Vec>(FluidId::BOUNDARY_VELOCITY);
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        ShiftingData<Dim>& d = *data_;
        d.volume.resize(s.size()), d.velocity.resize(s.size());
        scheduler.parallelFor(s.size(), 4096, [&](Size b, Size e) {
            for (Size i = b; i < e; ++i) {
                d.volume[i] = m[i] / rho[i];
                d.velocity[i] = isFluid(kind[i]) ? v[i] : vb[i];
            }
        });
    }
    void finalize(IScheduler& scheduler, Storage<Dim>& s, Float t) override {
        const Float dt = lastTime_ ? t - *lastTime_ : 0.0;
        lastTime_ = t;
        auto x = s.template getValue<Vec>(QuantityId::POSITION);
        auto v = s.template getDt<Vec>(QuantityId::POSITION);
        auto rho = s.template getValue<Float>(QuantityId::DENSITY);
        auto shift = s.template getValue<Vec>(QuantityId::SHIFT);
        auto c = s.template getValue<Float>(FluidId::KERNEL_SUM);
        const auto gradC = s.template getValue<Vec>(FluidId::KERNEL_SUM_GRADIENT);
        const auto gradRho = s.template getValue<Vec>(FluidId::DENSITY_GRADIENT);
        std::array<ArrayView<const Vec>, Dim> gradV;
        for (int b = 0; b < Dim; ++b)
            gradV[b] = s.template getValue<Vec>(velocityGradientId<Dim>(b));
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        const Float h = kernel_->h, w0 = kernel_->W(0);
        const Float diffusion = coefficient_ * h * velocityScale_ * dt, cap = 0.1 * h;
        const bool continuity = s.order(QuantityId::DENSITY) >= OrderEnum::FIRST;
        scheduler.parallelFor(s.size(), 4096, [&](Size b, Size e) {
            for (Size i = b; i < e; ++i) {
                c[i] += data_->volume[i] * w0;
                shift[i] = Vec{};
                if (!isFluid(kind[i]) || c[i] < 0.9 || !(dt > 0)) continue;
                Vec dr = gradC[i] * (-diffusion);
                const Float len = norm(dr);
                if (len > cap) dr *= cap / len;
                x[i] += dr;
                for (int k = 0; k < Dim; ++k) v[i] += gradV[k][i] * dr[k];
                if (continuity) rho[i] += dot(gradRho[i], dr);
                shift[i] = dr / dt;
            }
        });
    }
    void create(Storage<Dim>& s, IMaterial&) const override {
        s.template insert<Vec>(QuantityId::SHIFT, OrderEnum::ZERO, Vec{});
        s.template insert<Vec>(FluidId::BOUNDARY_VELOCITY, OrderEnum::ZERO, Vec{});
        s.template insert<Float>(FluidId::KERNEL_SUM, OrderEnum::ZERO, 0.0);
        s.template insert<Vec>(FluidId::KERNEL_SUM_GRADIENT, OrderEnum::ZERO, Vec{});
        s.template insert<Vec>(FluidId::DENSITY_GRADIENT, OrderEnum::ZERO, Vec{});
        for (int b = 0; b < Dim; ++b)
            s.template insert<Vec>(velocityGradientId<Dim>(b), OrderEnum::ZERO, Vec{});
    }

  private:
    Float coefficient_, velocityScale_;
    std::optional<RunKernel<Dim>> kernel_;
    std::optional<Float> lastTime_;
    std::shared_ptr<ShiftingData<Dim>> data_ = std::make_shared<ShiftingData<Dim>>();
};

}  // namespace num::sph
