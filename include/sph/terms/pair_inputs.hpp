// The per-particle values that several pair terms read, computed once per evaluation instead
// of by each term:
//   V_i = m_i / rho_i                      (FluidId::VOLUME: continuity's and delta-SPH's
//                                           volumes, shifting's and the kernel sum's weights)
//   u_i = v_i (fluid, open boundaries' buffers) (FluidId::PAIR_VELOCITY: the velocity a particle
//                                           shows in the viscous terms and in shifting; the
//                                           wall condition writes the boundary particles' own,
//                                           Adami et al. 2012, eq. 22-23)
// It runs after the wall condition, which sets the walls' density and velocity, and before the
// terms that read these: the fluid model adds it there, and a term that reads them lists
// pairVolume or pairVelocity in TermAccess::needs, so that the solver refuses it without
// PairInputs added before it.
#pragma once

#include "sph/formulas/fluid_particles.hpp"
#include "sph/terms/fluid_quantities.hpp"

namespace num::sph {

/// For TermAccess::needs of the terms that read FluidId::VOLUME or FluidId::PAIR_VELOCITY.
inline const PreparedInput pairVolume{FluidId::VOLUME, "PairInputs"};
inline const PreparedInput pairVelocity{FluidId::PAIR_VELOCITY, "PairInputs"};

template <int Dim>
class PairInputs : public IEquationTerm<Dim> {
  public:
    using Vec = Vector<Dim>;

    void setDerivatives(DerivativeHolder<Dim>&, const RunSettings&) override {}
    void initialize(IScheduler& scheduler, Storage<Dim>& s, Float) override {
        const auto m = s.template getValue<Float>(QuantityId::MASS);
        const auto rho = s.template getValue<Float>(QuantityId::DENSITY);
        const auto v = s.template getDt<Vec>(QuantityId::POSITION);
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        auto volume = s.template getValue<Float>(FluidId::VOLUME);
        auto velocity = s.template getValue<Vec>(FluidId::PAIR_VELOCITY);
        scheduler.parallelFor(s.size(), 4096, [&](Size b, Size e) {
            for (Size i = b; i < e; ++i) {
                volume[i] = formulas::particleVolume(m[i], rho[i]);
                if (isFluid(kind[i]) || isBuffer(kind[i])) velocity[i] = v[i];
            }
        });
    }
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}
    TermAccess access() const override {
        return {.reads = {QuantityId::DENSITY},
                .prepares = {FluidId::VOLUME, FluidId::PAIR_VELOCITY}};
    }
    void create(Storage<Dim>& s, IMaterial&) const override {
        s.template insert<Float>(FluidId::VOLUME, OrderEnum::ZERO, 0.0);
        s.template insert<Vec>(FluidId::PAIR_VELOCITY, OrderEnum::ZERO, Vec{});
    }
};

}  // namespace num::sph
