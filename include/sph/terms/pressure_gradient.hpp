// Pressure gradient in the symmetric, momentum-conserving form (Monaghan 1992, eq. 3.3):
//   dv_i/dt = - sum_j m_j (p_i / rho_i^2 + p_j / rho_j^2) grad_i W_ij.
// The pair contribution is antisymmetric, so sum_i m_i dv_i/dt = 0 to round-off. Boundary
// particles take part with the pressure and density of the wall condition; only fluid
// particles are accelerated. p / rho^2 is computed once per particle before the pair loop.
// The formulas: sph/formulas/fluid_pairs.hpp.
#pragma once

#include <memory>
#include <vector>

#include "sph/formulas/fluid_pairs.hpp"
#include "sph/terms/fluid_quantities.hpp"

namespace num::sph {

/// Per-particle data the pair parts read, filled by their term's initialize().
struct PressureGradientData {
    std::vector<Float> pOverRho2;
};

template <int Dim>
class PressureGradientPart : public DerivativeTemplate<PressureGradientPart<Dim>, Dim> {
  public:
    using Vec = Vector<Dim>;
    explicit PressureGradientPart(std::shared_ptr<const PressureGradientData> data)
        : data_(std::move(data)) {}

    /// The gather writes fluid particles only.
    bool gathersAtBoundary(Size) const override { return false; }
    void create(Accumulated<Dim>& r) override {
        r.template insert<Vec>(QuantityId::POSITION, OrderEnum::SECOND);
    }
    void initialize(const Storage<Dim>& s, Accumulated<Dim>& r) override {
        m_ = s.template getValue<Float>(QuantityId::MASS);
        kind_ = s.template getValue<int>(QuantityId::KIND);
        pr2_ = data_->pOverRho2.data();
        a_ = r.template getValue<Vec>(QuantityId::POSITION);
    }
    template <bool Symmetric>
    void eval(Size i, Size j, const Vec& grad) {
        const Vec f = formulas::pressureGradientForce(grad, pr2_[i], pr2_[j]);
        if (isFluid(kind_[i])) a_[i] -= f * m_[j];
        if constexpr (Symmetric)
            if (isFluid(kind_[j])) a_[j] += f * m_[i];
    }
    /// Gather (asymmetric) evaluation: the particle's own data read once and its sum kept in a
    /// register, with eval's formula in eval's order, so the result is bitwise eval's.
    void gatherNeighbours(Size i, ArrayView<const Size> neighs, ArrayView<const Vec> grads,
                          const NeighbourGeometry<Dim>&) {
        if (!isFluid(kind_[i])) return;
        const Float pr2i = pr2_[i];
        Vec sum = a_[i];
        for (std::size_t k = 0; k < neighs.size(); ++k) {
            const Size j = neighs[k];
            sum -= formulas::pressureGradientForce(grads[k], pr2i, pr2_[j]) * m_[j];
        }
        a_[i] = sum;
    }

  private:
    std::shared_ptr<const PressureGradientData> data_;
    ArrayView<const Float> m_;
    ArrayView<const int> kind_;
    const Float* pr2_ = nullptr;
    ArrayView<Vec> a_;
};

template <int Dim>
class PressureGradient : public IEquationTerm<Dim> {
  public:
    void setDerivatives(DerivativeHolder<Dim>& d, const RunSettings&) override {
        d.template require<PressureGradientPart<Dim>>(data_);
    }
    void initialize(IScheduler& scheduler, Storage<Dim>& s, Float) override {
        const auto p = s.template getValue<Float>(QuantityId::PRESSURE);
        const auto rho = s.template getValue<Float>(QuantityId::DENSITY);
        data_->pOverRho2.resize(s.size());
        scheduler.parallelFor(s.size(), 4096, [&](Size b, Size e) {
            for (Size i = b; i < e; ++i)
                data_->pOverRho2[i] = formulas::pressureOverDensity2(p[i], rho[i]);
        });
    }
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}
    TermAccess access() const override {
        return {.reads = {QuantityId::PRESSURE, QuantityId::DENSITY}};
    }
    void create(Storage<Dim>& s, IMaterial&) const override {
        s.template insert<Float>(QuantityId::PRESSURE, OrderEnum::ZERO, 0.0);
    }

  private:
    std::shared_ptr<PressureGradientData> data_ = std::make_shared<PressureGradientData>();
};

}  // namespace num::sph
