// A body force: dv_i/dt += g(t) for every fluid particle. g is any acceleration of time:
// gravity, a constant driving force (Poiseuille), or a ramp that brings gravity in smoothly.
#pragma once

#include <functional>

#include "sph/formulas/fluid_particles.hpp"
#include "sph/terms/fluid_quantities.hpp"

namespace num::sph {

template <int Dim>
class BodyForceTerm : public IEquationTerm<Dim> {
  public:
    using Vec = Vector<Dim>;
    explicit BodyForceTerm(std::function<Vec(Float)> force) : force_(std::move(force)) {}

    void setDerivatives(DerivativeHolder<Dim>&, const RunSettings&) override {}
    void initialize(IScheduler&, Storage<Dim>&, Float) override {}
    void finalize(IScheduler& scheduler, Storage<Dim>& s, Float t) override {
        const Vec g = force_(t);
        auto a = s.template getD2t<Vec>(QuantityId::POSITION);
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        scheduler.parallelFor(s.size(), 4096, [&](Size b, Size e) {
            for (Size i = b; i < e; ++i)
                if (isFluid(kind[i])) formulas::addBodyForce(a[i], g);
        });
    }
    void create(Storage<Dim>&, IMaterial&) const override {}

  private:
    std::function<Vec(Float)> force_;
};

}  // namespace num::sph
