// Particle shifting (Lind, Xu, Stansby & Rogers 2012, J. Comput. Phys. 231, 1499, eq. 9, 15
// and 17) in the form of the delta-plus-SPH model (Sun, Colagrossi, Marrone & Zhang 2017,
// Comput. Methods Appl. Mech. Engrg. 315, 25, sec. 3): after each step, fluid particles are
// moved down the gradient of the particle concentration,
//   dr_i = -A h c0 dt sum_j V_j [1 + R (W_ij / W(dx))^n] grad_i W_ij,   R = 0.2, n = 4,
// where the R term (Monaghan 2000, J. Comput. Phys. 159, 290) keeps close pairs apart. The
// displacement scales with the sound speed, not with a guessed flow speed: per step of the
// acoustic limit dt = C h / c0 it is a fixed fraction A C of h^2 grad C. A = 0.5 was chosen on
// the Taylor-Green vortex at Re = 100, 50 x 50, t = 2 (max|v| error / l1 velocity error):
// A = 0.4: +1.0 % / 2.7 %; 0.5: +1.6 % / 1.8 %; 0.6: +2.7 % / 1.4 %; and, measured before the
// Laplacian's eta was lowered, 1.2: +4.5 % / 4.0 %; 2.4: unstable; no shifting: -73 %, the
// lattice collapses at the stagnation points.
// Velocity and density are corrected to the new position by a Taylor expansion,
//   v_i += (dr_i . grad) v_i,   rho_i += dr_i . grad rho_i,
//   (grad v)_i = sum_j V_j (v_j - v_i) (x) grad_i W_ij,  grad rho_i = sum_j V_j (rho_j - rho_i)
//   grad_i W_ij,
// so the flow field is not carried with the particles. |dr_i| is capped at 0.1 h. Near a free
// surface (kernel sum C_i < 0.9, terms/free_surface.hpp) particles are not shifted, so surfaces
// do not diffuse. The displacement per unit time is kept in SHIFT.
#pragma once

#include <algorithm>
#include <memory>
#include <optional>
#include <vector>

#include "sph/kernel_choice.hpp"
#include "sph/terms/fluid_quantities.hpp"
#include "sph/terms/free_surface.hpp"

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
    /// wAtSpacing: W(dx), the kernel at the particle spacing (for the R term).
    ParticleShiftingPart(std::shared_ptr<const ShiftingData<Dim>> data, Float wAtSpacing)
        : data_(std::move(data)), inverseWdx_(1 / wAtSpacing) {}

    bool needsKernelValues() const override { return true; }
    void create(Accumulated<Dim>& r) override {
        r.template insert<Vec>(FluidId::KERNEL_SUM_GRADIENT, OrderEnum::ZERO);
        r.template insert<Vec>(FluidId::DENSITY_GRADIENT, OrderEnum::ZERO);
        for (int b = 0; b < Dim; ++b)
            r.template insert<Vec>(velocityGradientId<Dim>(b), OrderEnum::ZERO);
    }
    void initialize(const Storage<Dim>& s, Accumulated<Dim>& r) override {
        rho_ = s.template getValue<Float>(QuantityId::DENSITY);
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
        const Float q = pair.w * inverseWdx_, q2 = q * q;
        const Vec gradR = grad * (1 + tensileR * q2 * q2);
        gradC_[i] += gradR * vj;
        gradRho_[i] += grad * (vj * drho);
        for (int b = 0; b < Dim; ++b) gradV_[b][i] += dv * (vj * grad[b]);
        if constexpr (Symmetric) {
            gradC_[j] -= gradR * vi;
            gradRho_[j] += grad * (vi * drho);
            for (int b = 0; b < Dim; ++b) gradV_[b][j] += dv * (vi * grad[b]);
        }
    }

    static constexpr Float tensileR = 0.2;

  private:
    std::shared_ptr<const ShiftingData<Dim>> data_;
    Float inverseWdx_;
    ArrayView<const Float> rho_;
    ArrayView<Vec> gradC_, gradRho_;
    std::array<ArrayView<Vec>, Dim> gradV_;
};

template <int Dim>
class ParticleShifting : public IEquationTerm<Dim> {
  public:
    using Vec = Vector<Dim>;
    /// coefficient: A in dr = -A h c0 dt grad C; soundSpeed: c0; spacing: dx.
    ParticleShifting(Float coefficient, Float soundSpeed, Float spacing)
        : coefficient_(coefficient), soundSpeed_(soundSpeed), spacing_(spacing) {}

    void setDerivatives(DerivativeHolder<Dim>& d, const RunSettings& settings) override {
        kernel_.emplace(settings);
        d.template require<ParticleShiftingPart<Dim>>(data_, kernel_->W(spacing_));
        d.template require<KernelSumPart<Dim>>();
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
        const auto c = s.template getValue<Float>(FluidId::KERNEL_SUM);
        const auto gradC = s.template getValue<Vec>(FluidId::KERNEL_SUM_GRADIENT);
        const auto gradRho = s.template getValue<Vec>(FluidId::DENSITY_GRADIENT);
        std::array<ArrayView<const Vec>, Dim> gradV;
        for (int b = 0; b < Dim; ++b)
            gradV[b] = s.template getValue<Vec>(velocityGradientId<Dim>(b));
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        const Float h = kernel_->h, w0 = kernel_->W(0);
        const Float diffusion = coefficient_ * h * soundSpeed_ * dt, cap = 0.1 * h;
        const bool continuity = s.order(QuantityId::DENSITY) >= OrderEnum::FIRST;
        scheduler.parallelFor(s.size(), 4096, [&](Size b, Size e) {
            for (Size i = b; i < e; ++i) {
                shift[i] = Vec{};
                const Float kernelSum = c[i] + data_->volume[i] * w0;
                if (!isFluid(kind[i]) || kernelSum < surfaceKernelSum || !(dt > 0)) continue;
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
        s.template insert<Float>(FluidId::KERNEL_SUM, OrderEnum::ZERO, 1.0);
        s.template insert<Vec>(FluidId::KERNEL_SUM_GRADIENT, OrderEnum::ZERO, Vec{});
        s.template insert<Vec>(FluidId::DENSITY_GRADIENT, OrderEnum::ZERO, Vec{});
        for (int b = 0; b < Dim; ++b)
            s.template insert<Vec>(velocityGradientId<Dim>(b), OrderEnum::ZERO, Vec{});
    }

  private:
    static constexpr Float surfaceKernelSum = FreeSurfaceNoTension<Dim>::surfaceKernelSum;
    Float coefficient_, soundSpeed_, spacing_;
    std::optional<RunKernel<Dim>> kernel_;
    std::optional<Float> lastTime_;
    std::shared_ptr<ShiftingData<Dim>> data_ = std::make_shared<ShiftingData<Dim>>();
};

}  // namespace num::sph
