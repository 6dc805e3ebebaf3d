// Monaghan's artificial viscosity (Monaghan 1992, eq. 4.1-4.2), linear part:
//   dv_i/dt = - sum_j m_j Pi_ij grad_i W_ij,
//   Pi_ij = -alpha c0 mu_ij / rho_ij  if v_ij . r_ij < 0, else 0,
//   mu_ij = h v_ij . r_ij / (r_ij^2 + eta^2),  rho_ij = (rho_i + rho_j) / 2,  eta^2 = 0.01 h^2
//   (1 / (r_ij^2 + eta^2) is PairGeometry::inverseR2).
// Acts only between approaching particles; antisymmetric, so momentum is conserved. For a
// viscous flow it corresponds to nu = alpha h c0 / (2 (Dim + 2)) (Monaghan 2005, sec. 5.4).
// Boundary particles show the wall condition's velocity (FluidId::PAIR_VELOCITY,
// terms/pair_inputs.hpp). The formula: sph/formulas/fluid_pairs.hpp.
#pragma once

#include "sph/formulas/fluid_pairs.hpp"
#include "sph/terms/fluid_quantities.hpp"
#include "sph/terms/pair_inputs.hpp"

namespace num::sph {

template <int Dim>
class ArtificialViscosityPart : public DerivativeTemplate<ArtificialViscosityPart<Dim>, Dim> {
  public:
    using Vec = Vector<Dim>;
    ArtificialViscosityPart(Float alpha, Float c0, Float h) : alphaC0h_(alpha * c0 * h) {}

    /// The gather writes fluid particles only.
    bool gathersAtBoundary(Size) const override { return false; }
    void create(Accumulated<Dim>& r) override {
        r.template insert<Vec>(QuantityId::POSITION, OrderEnum::SECOND);
    }
    void initialize(const Storage<Dim>& s, Accumulated<Dim>& r) override {
        m_ = s.template getValue<Float>(QuantityId::MASS);
        rho_ = s.template getValue<Float>(QuantityId::DENSITY);
        kind_ = s.template getValue<int>(QuantityId::KIND);
        v_ = s.template getValue<Vec>(FluidId::PAIR_VELOCITY);
        a_ = r.template getValue<Vec>(QuantityId::POSITION);
    }
    template <bool Symmetric>
    void eval(Size i, Size j, const Vec& grad, const PairGeometry<Dim>& pair) {
        const bool fi = isFluid(kind_[i]), fj = isFluid(kind_[j]);
        if (!(fi || (Symmetric && fj))) return;
        const Float vr = formulas::approachRate(v_[i], v_[j], pair.dx);
        if (vr >= 0) return;
        const Float pi =
            formulas::artificialViscosityPi(alphaC0h_, vr, pair.inverseR2, rho_[i], rho_[j]);
        const Vec f = grad * pi;
        if (fi) a_[i] -= f * m_[j];
        if constexpr (Symmetric)
            if (fj) a_[j] += f * m_[i];
    }
    /// Gather (asymmetric) evaluation: the particle's own data read once and its sum kept in a
    /// register, with eval's formula in eval's order, so the result is bitwise eval's.
    void gatherNeighbours(Size i, ArrayView<const Size> neighs, ArrayView<const Vec> grads,
                          const NeighbourGeometry<Dim>& geometry) {
        if (!isFluid(kind_[i])) return;
        const Vec vi = v_[i];
        const Float rhoi = rho_[i];
        Vec sum = a_[i];
        for (std::size_t k = 0; k < neighs.size(); ++k) {
            const Size j = neighs[k];
            // min(vr, 0) instead of a branch: receding pairs add a zero (an unpredictable
            // branch per pair costs more than the arithmetic it skips).
            const Float vr = std::min(formulas::approachRate(vi, v_[j], geometry.dx[k]), Float(0));
            const Float pi = formulas::artificialViscosityPi(alphaC0h_, vr, geometry.inverseR2[k],
                                                             rhoi, rho_[j]);
            sum -= grads[k] * pi * m_[j];
        }
        a_[i] = sum;
    }

  private:
    Float alphaC0h_;
    ArrayView<const Float> m_, rho_;
    ArrayView<const int> kind_;
    ArrayView<const Vec> v_;
    ArrayView<Vec> a_;
};

template <int Dim>
class ArtificialViscosity : public IEquationTerm<Dim> {
  public:
    using Vec = Vector<Dim>;
    ArtificialViscosity(Float alpha, Float c0) : alpha_(alpha), c0_(c0) {}

    void setDerivatives(DerivativeHolder<Dim>& d, const RunSettings& settings) override {
        d.template require<ArtificialViscosityPart<Dim>>(alpha_, c0_,
                                                         settings.get<double>("smoothing_length"));
    }
    void initialize(IScheduler&, Storage<Dim>&, Float) override {}
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}
    TermAccess access() const override {
        return {.reads = {QuantityId::DENSITY}, .needs = {pairVelocity}};
    }
    void create(Storage<Dim>&, IMaterial&) const override {}

  private:
    Float alpha_, c0_;
};

}  // namespace num::sph
