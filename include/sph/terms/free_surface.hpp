// Free surfaces: the kernel sum C_i = sum_j V_j W_ij (1 inside the fluid, about 1/2 on a free
// surface, where the kernel support is cut), and a limit on the tension at a free surface.
//
// A weakly-compressible equation of state gives negative pressure wherever the density falls
// below rho0. Inside the fluid that is physical (a pressure below ambient), but at a free
// surface it is not: the surface is at ambient pressure, and an isolated or thinning particle
// whose density drops pulls its neighbours with a tension the liquid does not have (the
// tensile instability at free surfaces, Monaghan 2000, J. Comput. Phys. 159, 290; Colagrossi,
// Antuono & Le Touze 2009, Phys. Rev. E 79, 056701, on the surface condition p = p_ambient).
// So at particles whose support is cut, C_i < 0.9, the density is limited from below by a floor
// f rho0 and the pressure by the equation of state's pressure there:
//   rho_i = max(rho_i, f rho0),   p_i = max(p_i, p(f rho0))   where C_i < 0.9,
// p(f rho0) = p_b - (1 - f) rho0 c0^2 to first order (p_b the background, ambient, pressure).
// f = 1 allows no tension at all; then an impact on a wall rebounds, since the compression of
// the impacting water is released with nothing to hold it: the default f = 0.99 allows a tension
// of about rho0 U^2 with c0 = 10 U, which holds the water at the wall (sph/defaults.hpp).
// Where the density is evolved (continuity), its floor is a constraint on the state
// (FreeSurfaceTensionLimit::constrain, before every evaluation, so the integrator's predicted
// densities are held too); the pressure floor follows the equation of state (initialize). Where
// the density is computed in each evaluation (summation), both floors apply in initialize.
// Inside the fluid (C_i >= 0.9) nothing changes, so closed flows (Taylor-Green, cavities) keep
// their negative gauge pressures. C_i is the sum of the previous evaluation (one step old: a
// particle moves less than 0.25 h per step); before the first it is taken as 1.
// The formulas: sph/formulas/fluid_pairs.hpp and fluid_particles.hpp.
#pragma once

#include <memory>

#include "sph/formulas/fluid_pairs.hpp"
#include "sph/formulas/fluid_particles.hpp"
#include "sph/kernel_choice.hpp"
#include "sph/terms/equation_of_state.hpp"
#include "sph/terms/fluid_quantities.hpp"

namespace num::sph {

/// sum_{j != i} V_j W_ij into KERNEL_SUM, and the same sum over the neighbours that were
/// free-surface particles in the previous evaluation into SURFACE_NEIGHBOURS.
template <int Dim>
class KernelSumPart : public DerivativeTemplate<KernelSumPart<Dim>, Dim> {
  public:
    using Vec = Vector<Dim>;

    /// w0: W(0), for the particles' own term of their kernel sums.
    explicit KernelSumPart(Float w0) : w0_(w0) {}

    bool needsKernelValues() const override { return true; }
    /// The gather writes fluid particles' sums only: a boundary particle's is never read.
    bool gathersAtBoundary(Size) const override { return false; }
    void create(Accumulated<Dim>& r) override {
        r.template insert<Float>(FluidId::KERNEL_SUM, OrderEnum::ZERO);
        r.template insert<Float>(FluidId::SURFACE_NEIGHBOURS, OrderEnum::ZERO);
    }
    void initialize(const Storage<Dim>& s, Accumulated<Dim>& r) override {
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        const auto previous = s.template getValue<Float>(FluidId::KERNEL_SUM);
        const auto volume = s.template getValue<Float>(FluidId::VOLUME);
        if (!ownsParticles_) particles_ = std::make_shared<PerParticle>(), ownsParticles_ = true;
        std::vector<char>& atSurface = particles_->atSurface;
        atSurface.resize(s.size());
        for (Size i = 0; i < s.size(); ++i)
            atSurface[i] = isFluid(kind[i]) && atFreeSurface(previous[i], volume[i], w0_);
        bindResults(s, r);
    }
    /// Shares the surface flags of block 0's part (computed once per evaluation).
    void initializeLike(const IDerivative<Dim>& first, const Storage<Dim>& s,
                        Accumulated<Dim>& r) override {
        particles_ = static_cast<const KernelSumPart&>(first).particles_;
        ownsParticles_ = false;
        bindResults(s, r);
    }
    template <bool Symmetric>
    void eval(Size i, Size j, const Vec&, const PairGeometry<Dim>& pair) {
        const Float wi = formulas::kernelSumWeight(volume_[j], pair.w);
        c_[i] += wi;
        if (atSurface_[j]) nearSurface_[i] += wi;
        if constexpr (Symmetric) {
            const Float wj = formulas::kernelSumWeight(volume_[i], pair.w);
            c_[j] += wj;
            if (atSurface_[i]) nearSurface_[j] += wj;
        }
    }
    /// Gather (asymmetric) evaluation: the particle's own data read once and its sum kept in a
    /// register, with eval's formula in eval's order, so the result is bitwise eval's.
    void gatherNeighbours(Size i, ArrayView<const Size> neighs, ArrayView<const Vec>,
                          const NeighbourGeometry<Dim>& geometry) {
        Float c = c_[i], near = nearSurface_[i];
        for (std::size_t k = 0; k < neighs.size(); ++k) {
            const Size j = neighs[k];
            const Float weight = formulas::kernelSumWeight(volume_[j], geometry.w[k]);
            c += weight;
            if (atSurface_[j]) near += weight;
        }
        c_[i] = c, nearSurface_[i] = near;
    }

  private:
    struct PerParticle {
        std::vector<char> atSurface;  ///< a fluid particle at a free surface last evaluation
    };
    void bindResults(const Storage<Dim>& s, Accumulated<Dim>& r) {
        volume_ = s.template getValue<Float>(FluidId::VOLUME);
        atSurface_ = particles_->atSurface.data();
        c_ = r.template getValue<Float>(FluidId::KERNEL_SUM);
        nearSurface_ = r.template getValue<Float>(FluidId::SURFACE_NEIGHBOURS);
    }

    Float w0_;
    std::shared_ptr<PerParticle> particles_;
    bool ownsParticles_ = false;  ///< false: particles_ is block 0's, read only
    ArrayView<const Float> volume_;
    const char* atSurface_ = nullptr;
    ArrayView<Float> c_, nearSurface_;
};

/// Limits density and pressure at free-surface particles (see the top of this file). Place it
/// after the equation of state and before the wall condition.
template <int Dim>
class FreeSurfaceTensionLimit : public IEquationTerm<Dim> {
  public:
    /// densityFloor: f, the lowest density of a free-surface particle over rho0, in (0, 1].
    FreeSurfaceTensionLimit(EquationOfState eos, Float densityFloor)
        : rhoMin_(densityFloor * eos.rho0), pMin_(eos.pressure(rhoMin_)) {}

    void setDerivatives(DerivativeHolder<Dim>& d, const RunSettings& settings) override {
        w0_ = RunKernel<Dim>(settings).W(0);
        d.template require<KernelSumPart<Dim>>(w0_);
    }
    /// The density floor where the density is evolved (continuity).
    void constrain(IScheduler& scheduler, Storage<Dim>& s) override {
        if (s.order(QuantityId::DENSITY) != OrderEnum::ZERO) limit(scheduler, s, true, false);
    }
    /// The pressure floor, and the density floor where the density is computed (summation).
    void initialize(IScheduler& scheduler, Storage<Dim>& s, Float) override {
        limit(scheduler, s, s.order(QuantityId::DENSITY) == OrderEnum::ZERO, true);
    }
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}
    TermAccess access() const override {
        return {.reads = {QuantityId::PRESSURE, QuantityId::DENSITY},
                .prepares = {QuantityId::PRESSURE, QuantityId::DENSITY},
                .produces = {FluidId::KERNEL_SUM, FluidId::SURFACE_NEIGHBOURS}};
    }
    void create(Storage<Dim>& s, IMaterial&) const override {
        s.template insert<Float>(FluidId::KERNEL_SUM, OrderEnum::ZERO, 1.0);
        s.template insert<Float>(FluidId::SURFACE_NEIGHBOURS, OrderEnum::ZERO, 0.0);
    }

  private:
    /// The floors at fluid particles whose support is cut (C_i < 0.9).
    void limit(IScheduler& scheduler, Storage<Dim>& s, bool density, bool pressure) const {
        const auto c = s.template getValue<Float>(FluidId::KERNEL_SUM);
        const auto m = s.template getValue<Float>(QuantityId::MASS);
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        auto p = s.template getValue<Float>(QuantityId::PRESSURE);
        auto rho = s.template getValue<Float>(QuantityId::DENSITY);
        scheduler.parallelFor(s.size(), 4096, [&](Size b, Size e) {
            for (Size i = b; i < e; ++i) {
                if (!isFluid(kind[i]) ||
                    !atFreeSurface(c[i], formulas::particleVolume(m[i], rho[i]), w0_))
                    continue;
                if (density) rho[i] = formulas::surfaceDensityFloor(rho[i], rhoMin_);
                if (pressure) p[i] = formulas::surfacePressureFloor(p[i], pMin_);
            }
        });
    }

    Float rhoMin_, pMin_;  ///< f rho0 and p(f rho0)
    Float w0_ = 0;
};

}  // namespace num::sph
