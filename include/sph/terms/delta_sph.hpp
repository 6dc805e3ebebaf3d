// Density diffusion of delta-SPH (Molteni & Colagrossi 2009, eq. 10), added to the continuity
// equation to damp spurious pressure oscillations:
//   drho_i/dt += 2 delta h c0 sum_j V_j psi_ij (r_ij . grad_i W_ij) / (r_ij^2 + eta^2),
//   psi_ij = rho_i - rho_j - rho0 (g . r_ij) / c0^2   (hydrostatic part removed),
// r_ij = x_i - x_j, V_j = m_j / rho_j (FluidId::VOLUME, terms/pair_inputs.hpp), eta^2 = 0.01 h^2,
// delta ~ 0.1. The last term of psi subtracts the density difference of hydrostatic equilibrium
// under the body force g, as in Fourtakas et al. (2019, Comput. Fluids 190, eq. 12) in its linear
// form, so a tank at rest is not diffused away from hydrostatics. Applied between fluid particles
// only. The formula: sph/formulas/fluid_pairs.hpp.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "sph/formulas/fluid_pairs.hpp"
#include "sph/terms/fluid_quantities.hpp"
#include "sph/terms/pair_inputs.hpp"

namespace num::sph {

template <int Dim>
struct DeltaSphData {
    Vector<Dim> gravityTerm{};  // rho0 g / c0^2 at the current time
};

template <int Dim>
class DeltaSphPart : public DerivativeTemplate<DeltaSphPart<Dim>, Dim> {
  public:
    using Vec = Vector<Dim>;
    DeltaSphPart(std::shared_ptr<const DeltaSphData<Dim>> data, Float delta, Float c0, Float h)
        : data_(std::move(data)), coefficient_(formulas::deltaSphCoefficient(delta, c0, h)) {}

    /// The gather writes fluid particles only.
    bool gathersAtBoundary(Size) const override { return false; }
    void create(Accumulated<Dim>& r) override {
        r.template insert<Float>(QuantityId::DENSITY, OrderEnum::FIRST);
    }
    void initialize(const Storage<Dim>& s, Accumulated<Dim>& r) override {
        rho_ = s.template getValue<Float>(QuantityId::DENSITY);
        kind_ = s.template getValue<int>(QuantityId::KIND);
        volume_ = s.template getValue<Float>(FluidId::VOLUME);
        drho_ = r.template getValue<Float>(QuantityId::DENSITY);
    }
    template <bool Symmetric>
    void eval(Size i, Size j, const Vec& grad, const PairGeometry<Dim>& pair) {
        if (!isFluid(kind_[i]) || !isFluid(kind_[j])) return;
        const DeltaSphData<Dim>& d = *data_;
        const Float f = formulas::deltaSphFlux(coefficient_, rho_[i], rho_[j], d.gravityTerm,
                                               pair.dx, grad, pair.inverseR2);
        drho_[i] += f * volume_[j];
        if constexpr (Symmetric) drho_[j] -= f * volume_[i];
    }
    /// Gather (asymmetric) evaluation: the particle's own data read once and its sum kept in a
    /// register, with eval's formula in eval's order, so the result is bitwise eval's.
    void gatherNeighbours(Size i, ArrayView<const Size> neighs, ArrayView<const Vec> grads,
                          const NeighbourGeometry<Dim>& geometry) {
        if (!isFluid(kind_[i])) return;
        const DeltaSphData<Dim>& d = *data_;
        const Float rhoi = rho_[i];
        Float sum = drho_[i];
        for (std::size_t k = 0; k < neighs.size(); ++k) {
            const Size j = neighs[k];
            if (!isFluid(kind_[j])) continue;
            sum += formulas::deltaSphFlux(coefficient_, rhoi, rho_[j], d.gravityTerm,
                                          geometry.dx[k], grads[k], geometry.inverseR2[k]) *
                   volume_[j];
        }
        drho_[i] = sum;
    }

  private:
    std::shared_ptr<const DeltaSphData<Dim>> data_;
    Float coefficient_;
    ArrayView<const Float> rho_, volume_;
    ArrayView<const int> kind_;
    ArrayView<Float> drho_;
};

template <int Dim>
class DeltaSph : public IEquationTerm<Dim> {
  public:
    using Vec = Vector<Dim>;
    /// bodyForce may be empty (no hydrostatic correction).
    DeltaSph(Float delta, Float rho0, Float c0, std::function<Vec(Float)> bodyForce)
        : delta_(delta), rho0_(rho0), c0_(c0), bodyForce_(std::move(bodyForce)) {}

    void setDerivatives(DerivativeHolder<Dim>& d, const RunSettings& settings) override {
        d.template require<DeltaSphPart<Dim>>(data_, delta_, c0_,
                                              settings.get<double>("smoothing_length"));
    }
    void initialize(IScheduler&, Storage<Dim>&, Float t) override {
        data_->gravityTerm =
            bodyForce_ ? formulas::deltaSphGravityTerm(bodyForce_(t), rho0_, c0_) : Vec{};
    }
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}
    TermAccess access() const override {
        return {.reads = {QuantityId::DENSITY}, .needs = {pairVolume}};
    }
    void create(Storage<Dim>& s, IMaterial& material) const override {
        s.template insert<Float>(QuantityId::DENSITY, OrderEnum::FIRST,
                                 material.params().template get<double>("density"));
    }

  private:
    Float delta_, rho0_, c0_;
    std::function<Vec(Float)> bodyForce_;
    std::shared_ptr<DeltaSphData<Dim>> data_ = std::make_shared<DeltaSphData<Dim>>();
};

}  // namespace num::sph
