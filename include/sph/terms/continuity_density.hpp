// Continuity equation (Monaghan 1992, eq. 2.9, in the volume form of Colagrossi & Landrini 2003):
//   drho_i/dt = rho_i sum_j V_j (v_i - v_j) . grad_i W_ij,   V_j = m_j / rho_j.
// Boundary particles enter with their prescribed wall velocity (the fluid does not flow
// through a wall moving tangentially); only fluid densities evolve.
#pragma once

#include <memory>
#include <vector>

#include "sph/terms/fluid_quantities.hpp"

namespace num::sph {

template <int Dim>
struct ContinuityData {
    std::vector<Vector<Dim>> velocity;  // fluid: v; boundary: prescribed wall velocity
    std::vector<Float> volume;          // m / rho
};

template <int Dim>
class ContinuityDensityPart : public DerivativeTemplate<ContinuityDensityPart<Dim>, Dim> {
  public:
    using Vec = Vector<Dim>;
    explicit ContinuityDensityPart(std::shared_ptr<const ContinuityData<Dim>> data)
        : data_(std::move(data)) {}

    void create(Accumulated<Dim>& r) override {
        r.template insert<Float>(QuantityId::DENSITY, OrderEnum::FIRST);
    }
    void initialize(const Storage<Dim>& s, Accumulated<Dim>& r) override {
        rho_ = s.template getValue<Float>(QuantityId::DENSITY);
        kind_ = s.template getValue<int>(QuantityId::KIND);
        drho_ = r.template getValue<Float>(QuantityId::DENSITY);
    }
    template <bool Symmetric>
    void eval(Size i, Size j, const Vec& grad) {
        const ContinuityData<Dim>& d = *data_;
        const Float div = dot(d.velocity[i] - d.velocity[j], grad);
        if (isFluid(kind_[i])) drho_[i] += rho_[i] * d.volume[j] * div;
        if constexpr (Symmetric)
            if (isFluid(kind_[j])) drho_[j] += rho_[j] * d.volume[i] * div;
    }
    /// Gather (asymmetric) evaluation: the particle's own data read once and its sum kept in a
    /// register, added in the order of eval, so the result is bitwise eval's.
    void gatherNeighbours(Size i, ArrayView<const Size> neighs, ArrayView<const Vec> grads,
                          const NeighbourGeometry<Dim>&) {
        if (!isFluid(kind_[i])) return;
        const ContinuityData<Dim>& d = *data_;
        const Vec vi = d.velocity[i];
        const Float rhoi = rho_[i];
        Float sum = drho_[i];
        for (std::size_t k = 0; k < neighs.size(); ++k) {
            const Size j = neighs[k];
            sum += rhoi * d.volume[j] * dot(vi - d.velocity[j], grads[k]);
        }
        drho_[i] = sum;
    }

  private:
    std::shared_ptr<const ContinuityData<Dim>> data_;
    ArrayView<const Float> rho_;
    ArrayView<const int> kind_;
    ArrayView<Float> drho_;
};

template <int Dim>
class ContinuityDensity : public IEquationTerm<Dim> {
  public:
    using Vec = Vector<Dim>;
    void setDerivatives(DerivativeHolder<Dim>& d, const RunSettings&) override {
        d.template require<ContinuityDensityPart<Dim>>(data_);
    }
    void initialize(IScheduler& scheduler, Storage<Dim>& s, Float) override {
        const auto v = s.template getDt<Vec>(QuantityId::POSITION);
        const auto vw = s.template getValue<Vec>(QuantityId::WALL_VELOCITY);
        const auto m = s.template getValue<Float>(QuantityId::MASS);
        const auto rho = s.template getValue<Float>(QuantityId::DENSITY);
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        ContinuityData<Dim>& d = *data_;
        d.velocity.resize(s.size()), d.volume.resize(s.size());
        scheduler.parallelFor(s.size(), 4096, [&](Size b, Size e) {
            for (Size i = b; i < e; ++i) {
                d.velocity[i] = isFluid(kind[i]) ? v[i] : vw[i];
                d.volume[i] = m[i] / rho[i];
            }
        });
    }
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}
    void create(Storage<Dim>& s, IMaterial& material) const override {
        s.template insert<Float>(QuantityId::DENSITY, OrderEnum::FIRST,
                                 material.params().template get<double>("density"));
        s.template insert<Vec>(QuantityId::WALL_VELOCITY, OrderEnum::ZERO, Vec{});
    }

  private:
    std::shared_ptr<ContinuityData<Dim>> data_ = std::make_shared<ContinuityData<Dim>>();
};

}  // namespace num::sph
