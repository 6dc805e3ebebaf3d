// Continuity equation (Monaghan 1992, eq. 2.9, in the volume form of Colagrossi & Landrini 2003):
//   drho_i/dt = rho_i sum_j V_j (v_i - v_j) . grad_i W_ij,   V_j = m_j / rho_j
// (FluidId::VOLUME, terms/pair_inputs.hpp). The formula: sph/formulas/fluid_pairs.hpp.
// Only fluid densities evolve. Boundary particles enter with their own velocity: zero for walls
// and fixed bodies, held in place (boundary_hold.hpp), a moving body's rigid velocity for its
// particles (sph/bodies/body_coupling.hpp); the equation is the time derivative of the kernel
// sum, in which only their motion appears. A wall's prescribed surface velocity (a sliding lid,
// WALL_VELOCITY) is a no-slip condition for the viscous terms, not a motion of its particles.
// It used to enter here, which made a lid a mass source where its particle rows end: in the
// lid-driven cavity the corner blocks of wall particles are split along the diagonal between
// the lid (sliding at U) and the side walls (at rest), a jump of U / sqrt(2) normal to the
// diagonal, so at t = 0 the fluid particle in the upstream top corner expanded at 0.45 U / L
// and the one in the downstream corner was compressed at 2.5 U / L (relative density rates;
// 25 x 25, fluid at rest; away from the corners the uniform lid rows cancel). At Re = 1000 the
// upstream corner emptied (densities down to 0.78 rho0) and the runs stopped unstable (exit 9
// at t = 0.9 to 28 s at spacings 0.08 to 0.04); now they run the 40 s (docs/validation.md).
#pragma once

#include "sph/formulas/fluid_pairs.hpp"
#include "sph/terms/fluid_quantities.hpp"
#include "sph/terms/pair_inputs.hpp"

namespace num::sph {

template <int Dim>
class ContinuityDensityPart : public DerivativeTemplate<ContinuityDensityPart<Dim>, Dim> {
  public:
    using Vec = Vector<Dim>;
    /// The gather writes fluid particles only (walls and bodies hold their density).
    bool gathersAtBoundary(Size) const override { return false; }
    void create(Accumulated<Dim>& r) override {
        r.template insert<Float>(QuantityId::DENSITY, OrderEnum::FIRST);
    }
    void initialize(const Storage<Dim>& s, Accumulated<Dim>& r) override {
        rho_ = s.template getValue<Float>(QuantityId::DENSITY);
        kind_ = s.template getValue<int>(QuantityId::KIND);
        v_ = s.template getDt<Vec>(QuantityId::POSITION);
        volume_ = s.template getValue<Float>(FluidId::VOLUME);
        drho_ = r.template getValue<Float>(QuantityId::DENSITY);
    }
    template <bool Symmetric>
    void eval(Size i, Size j, const Vec& grad) {
        const Float div = formulas::continuityDivergence(velocity(i), velocity(j), grad);
        if (isFluid(kind_[i])) drho_[i] += formulas::continuityRate(rho_[i], volume_[j], div);
        if constexpr (Symmetric)
            if (isFluid(kind_[j])) drho_[j] += formulas::continuityRate(rho_[j], volume_[i], div);
    }
    /// Gather (asymmetric) evaluation: the particle's own data read once and its sum kept in a
    /// register, with eval's formula in eval's order, so the result is bitwise eval's.
    void gatherNeighbours(Size i, ArrayView<const Size> neighs, ArrayView<const Vec> grads,
                          const NeighbourGeometry<Dim>&) {
        if (!isFluid(kind_[i])) return;
        const Vec vi = v_[i];
        const Float rhoi = rho_[i];
        Float sum = drho_[i];
        for (std::size_t k = 0; k < neighs.size(); ++k) {
            const Size j = neighs[k];
            sum += formulas::continuityRate(
                rhoi, volume_[j], formulas::continuityDivergence(vi, velocity(j), grads[k]));
        }
        drho_[i] = sum;
    }

  private:
    /// Every particle's own velocity (a held boundary particle's is zero).
    Vec velocity(Size j) const { return v_[j]; }

    ArrayView<const Float> rho_, volume_;
    ArrayView<const int> kind_;
    ArrayView<const Vec> v_;
    ArrayView<Float> drho_;
};

template <int Dim>
class ContinuityDensity : public IEquationTerm<Dim> {
  public:
    void setDerivatives(DerivativeHolder<Dim>& d, const RunSettings&) override {
        d.template require<ContinuityDensityPart<Dim>>();
    }
    void initialize(IScheduler&, Storage<Dim>&, Float) override {}
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}
    TermAccess access() const override {
        return {.reads = {QuantityId::DENSITY}, .needs = {pairVolume}};
    }
    void create(Storage<Dim>& s, IMaterial& material) const override {
        s.template insert<Float>(QuantityId::DENSITY, OrderEnum::FIRST,
                                 material.params().template get<double>("density"));
    }
};

}  // namespace num::sph
