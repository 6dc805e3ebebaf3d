// A safety net that guarantees no fluid particle is ever inside a wall or a solid body. The
// wall condition's pressure normally keeps fluid away; if a particle still ends up beyond a
// wall surface (the container box side), inside a body or inside an interior wall's solid (of
// any shape: its signed distance and outward normal), it is reflected back across the surface
// and the velocity component into the solid is removed. Runs in the post-step phase
// (postStep(), once per step after the integrator and after particle shifting), so the
// velocity a step ends with has no component into the solid.
#pragma once

#include <vector>

#include "sph/formulas/post_step.hpp"
#include "sph/setup/fluid_geometry.hpp"

namespace num::sph {

template <int Dim>
class ParticleContainment : public IEquationTerm<Dim> {
  public:
    using Vec = Vector<Dim>;
    explicit ParticleContainment(const FluidGeometry<Dim>& geometry) : geometry_(geometry) {}

    void setDerivatives(DerivativeHolder<Dim>&, const RunSettings&) override {}
    void initialize(IScheduler&, Storage<Dim>&, Float) override {}
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}
    void postStep(IScheduler& scheduler, Storage<Dim>& s, Float, Float) override {
        auto x = s.template getValue<Vec>(QuantityId::POSITION);
        auto v = s.template getDt<Vec>(QuantityId::POSITION);
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        const FluidGeometry<Dim>& g = geometry_;
        scheduler.parallelFor(s.size(), 4096, [&](Size b, Size e) {
            for (Size i = b; i < e; ++i) {
                if (!isFluid(kind[i])) continue;
                for (int k = 0; k < Dim; ++k)
                    formulas::containInWalls(x[i][k], v[i][k], g.domain.min[k], g.domain.max[k],
                                             g.hasWall(k, 0), g.hasWall(k, 1));
                for (const SolidBody<Dim>& body : g.bodies)
                    if (body.mayContain(x[i])) formulas::containOutsideBody<Dim>(x[i], v[i], body);
                for (const InteriorWall<Dim>& wall : g.interiorWalls)
                    if (wall.mayContain(x[i])) formulas::containOutsideBody<Dim>(x[i], v[i], wall);
            }
        });
    }
    void create(Storage<Dim>&, IMaterial&) const override {}

  private:
    FluidGeometry<Dim> geometry_;
};

}  // namespace num::sph
