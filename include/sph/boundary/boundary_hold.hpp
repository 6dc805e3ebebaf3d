// Holds boundary particles (walls and bodies) in place: after every other term, their
// acceleration and density rate are set to zero. Their velocity stays what the set-up gave
// them (zero), so they never move; a moving wall is a prescribed surface velocity
// (WALL_VELOCITY) seen by the fluid through the wall condition.
#pragma once

#include "sph/terms/fluid_quantities.hpp"

namespace num::sph {

template <int Dim>
class BoundaryHold : public IEquationTerm<Dim> {
  public:
    using Vec = Vector<Dim>;
    void setDerivatives(DerivativeHolder<Dim>&, const RunSettings&) override {}
    void initialize(IScheduler&, Storage<Dim>&, Float) override {}
    void finalize(IScheduler& scheduler, Storage<Dim>& s, Float) override {
        auto a = s.template getD2t<Vec>(QuantityId::POSITION);
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        const bool densityRate = s.order(QuantityId::DENSITY) >= OrderEnum::FIRST;
        ArrayView<Float> drho;
        if (densityRate) drho = s.template getDt<Float>(QuantityId::DENSITY);
        scheduler.parallelFor(s.size(), 4096, [&](Size b, Size e) {
            for (Size i = b; i < e; ++i) {
                if (isFluid(kind[i])) continue;
                a[i] = Vec{};
                if (densityRate) drho[i] = 0;
            }
        });
    }
    /// The last pass: boundary particles shed every term's rates.
    TermAccess access() const override { return {.placement = PassPlacement::LAST}; }
    void create(Storage<Dim>& s, IMaterial&) const override {
        s.template insert<int>(QuantityId::KIND, OrderEnum::ZERO, int(ParticleKind::FLUID));
    }
};

}  // namespace num::sph
