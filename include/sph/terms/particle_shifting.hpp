// Particle shifting (Lind, Xu, Stansby & Rogers 2012, J. Comput. Phys. 231, eq. 9 and 15):
// after each step, fluid particles are moved down the gradient of the particle concentration
//   C_i = sum_j V_j W_ij,   dr_i = -A h U dt grad C_i,   grad C_i = sum_j V_j grad_i W_ij,
// which keeps the particle distribution regular in long runs (Taylor-Green vortex, shear
// flows) without changing the momentum equation. A ~ 2 (Lind et al. use 1 to 6), U is the
// flow's velocity scale and dt the step just taken (the time between two evaluations).
// |dr_i| is capped at 0.1 h. Particles with C_i < 0.9 (a free surface nearby) are not
// shifted, so surfaces do not diffuse. The displacement per unit time is kept in SHIFT.
#pragma once

#include <algorithm>
#include <memory>
#include <optional>
#include <vector>

#include "sph/kernel_choice.hpp"
#include "sph/terms/fluid_quantities.hpp"

namespace num::sph {

template <int Dim>
class ParticleShiftingPart : public DerivativeTemplate<ParticleShiftingPart<Dim>, Dim> {
  public:
    using Vec = Vector<Dim>;
    explicit ParticleShiftingPart(std::shared_ptr<const std::vector<Float>> volume)
        : volume_(std::move(volume)) {}

    bool needsKernelValues() const override { return true; }
    void create(Accumulated<Dim>& r) override {
        r.template insert<Float>(FluidId::KERNEL_SUM, OrderEnum::ZERO);
        r.template insert<Vec>(FluidId::KERNEL_SUM_GRADIENT, OrderEnum::ZERO);
    }
    void initialize(const Storage<Dim>&, Accumulated<Dim>& r) override {
        c_ = r.template getValue<Float>(FluidId::KERNEL_SUM);
        gradC_ = r.template getValue<Vec>(FluidId::KERNEL_SUM_GRADIENT);
    }
    template <bool Symmetric>
    void eval(Size i, Size j, const Vec& grad, const PairGeometry<Dim>& pair) {
        const std::vector<Float>& vol = *volume_;
        c_[i] += vol[j] * pair.w;
        gradC_[i] += grad * vol[j];
        if constexpr (Symmetric) {
            c_[j] += vol[i] * pair.w;
            gradC_[j] -= grad * vol[i];
        }
    }

  private:
    std::shared_ptr<const std::vector<Float>> volume_;
    ArrayView<Float> c_;
    ArrayView<Vec> gradC_;
};

template <int Dim>
class ParticleShifting : public IEquationTerm<Dim> {
  public:
    using Vec = Vector<Dim>;
    /// coefficient: A; velocityScale: U.
    ParticleShifting(Float coefficient, Float velocityScale)
        : coefficient_(coefficient), velocityScale_(velocityScale) {}

    void setDerivatives(DerivativeHolder<Dim>& d, const RunSettings& settings) override {
        d.template require<ParticleShiftingPart<Dim>>(volume_);
        kernel_.emplace(settings);
    }
    void initialize(IScheduler& scheduler, Storage<Dim>& s, Float) override {
        const auto m = s.template getValue<Float>(QuantityId::MASS);
        const auto rho = s.template getValue<Float>(QuantityId::DENSITY);
        volume_->resize(s.size());
        scheduler.parallelFor(s.size(), 4096, [&](Size b, Size e) {
            for (Size i = b; i < e; ++i) (*volume_)[i] = m[i] / rho[i];
        });
    }
    void finalize(IScheduler& scheduler, Storage<Dim>& s, Float t) override {
        const Float dt = lastTime_ ? t - *lastTime_ : 0.0;
        lastTime_ = t;
        auto x = s.template getValue<Vec>(QuantityId::POSITION);
        auto shift = s.template getValue<Vec>(QuantityId::SHIFT);
        auto c = s.template getValue<Float>(FluidId::KERNEL_SUM);
        const auto gradC = s.template getValue<Vec>(FluidId::KERNEL_SUM_GRADIENT);
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        const Float h = kernel_->h, w0 = kernel_->W(0);
        const Float diffusion = coefficient_ * h * velocityScale_ * dt, cap = 0.1 * h;
        scheduler.parallelFor(s.size(), 4096, [&](Size b, Size e) {
            for (Size i = b; i < e; ++i) {
                c[i] += (*volume_)[i] * w0;
                shift[i] = Vec{};
                if (!isFluid(kind[i]) || c[i] < 0.9 || !(dt > 0)) continue;
                Vec dr = gradC[i] * (-diffusion);
                const Float len = norm(dr);
                if (len > cap) dr *= cap / len;
                x[i] += dr;
                shift[i] = dr / dt;
            }
        });
    }
    void create(Storage<Dim>& s, IMaterial&) const override {
        s.template insert<Vec>(QuantityId::SHIFT, OrderEnum::ZERO, Vec{});
        s.template insert<Float>(FluidId::KERNEL_SUM, OrderEnum::ZERO, 0.0);
        s.template insert<Vec>(FluidId::KERNEL_SUM_GRADIENT, OrderEnum::ZERO, Vec{});
    }

  private:
    Float coefficient_, velocityScale_;
    std::optional<RunKernel<Dim>> kernel_;
    std::optional<Float> lastTime_;
    std::shared_ptr<std::vector<Float>> volume_ = std::make_shared<std::vector<Float>>();
};

}  // namespace num::sph
