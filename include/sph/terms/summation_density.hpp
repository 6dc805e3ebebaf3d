// Density by summation (Monaghan 1992, eq. 2.7):  rho_i = sum_j m_j W(|x_i - x_j|, h),
// the sum over every neighbour, boundary particles included, and i itself. Computed before
// the pair loop (a gather pass), so pressure and forces use the density of the same instant.
// Exact mass conservation holds trivially (masses never change); near a free surface the sum
// is truncated, so free-surface cases should use the continuity equation instead.
// The formula: sph/formulas/fluid_pairs.hpp (host and device).
#pragma once

#include <memory>

#include "sph/formulas/fluid_pairs.hpp"
#include "sph/terms/fluid_quantities.hpp"
#include "sph/terms/neighbour_gather.hpp"

namespace num::sph {

template <int Dim>
class SummationDensity : public IEquationTerm<Dim> {
  public:
    explicit SummationDensity(std::shared_ptr<const NeighbourGather<Dim>> gather)
        : gather_(std::move(gather)) {}

    void setDerivatives(DerivativeHolder<Dim>&, const RunSettings&) override {}

    void initialize(IScheduler& scheduler, Storage<Dim>& s, Float) override {
        const auto m = s.template getValue<Float>(QuantityId::MASS);
        auto rho = s.template getValue<Float>(QuantityId::DENSITY);
        fluid_ = particlesWhere(s, isFluid);
        gather_->forEach(scheduler, fluid_, [&](Size i, auto&& visit) {
            Float sum = 0;
            visit([&](Size j, const Vector<Dim>&, Float, Float w) {
                sum += formulas::summationDensityTerm(m[j], w);
            });
            rho[i] = sum;
        });
    }
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}
    TermAccess access() const override { return {.prepares = {QuantityId::DENSITY}}; }
    void create(Storage<Dim>& s, IMaterial& material) const override {
        s.template insert<Float>(QuantityId::DENSITY, OrderEnum::ZERO,
                                 material.params().template get<double>("density"));
    }

  private:
    std::shared_ptr<const NeighbourGather<Dim>> gather_;
    std::vector<Size> fluid_;
};

}  // namespace num::sph
