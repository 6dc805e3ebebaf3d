// Boussinesq buoyancy: the thermal part of gravity as a body force on fluid particles.
//
//   dv_a/dt += -beta (T_a - T0) g
//
// (Boussinesq 1903; e.g. Kundu & Cohen, Fluid Mechanics, sec. 4.18: density variations
// rho = rho0 (1 - beta (T - T0)) are kept only where they multiply g). With g pointing down, a
// particle warmer than T0 is pushed up: warm water rises. beta (thermal_expansion) and T0
// (reference_temperature) come from each particle's material. Add it beside the gravity term
// (which gives rho0 g and the hydrostatic pressure), or alone in a reduced-gravity setting
// where the hydrostatic part is subtracted. Only fluid particles (QuantityId::KIND = FLUID, or
// every particle when the storage has no KIND) feel it.
#pragma once

#include <functional>
#include <vector>

#include "sph/equation_term.hpp"
#include "sph/formulas/fluid_particles.hpp"
#include "sph/terms/thermal_properties.hpp"

namespace num::sph {

template <int Dim>
class BoussinesqBuoyancy : public IEquationTerm<Dim> {
  public:
    /// gravity: the gravitational acceleration g [m/s^2] (e.g. (0, -9.81)), constant or of
    /// time (the same ramp as the gravity term).
    explicit BoussinesqBuoyancy(Vector<Dim> gravity) : g_([gravity](Float) { return gravity; }) {}
    explicit BoussinesqBuoyancy(std::function<Vector<Dim>(Float)> gravity)
        : g_(std::move(gravity)) {}

    void setDerivatives(DerivativeHolder<Dim>&, const RunSettings&) override {}
    void initialize(IScheduler&, Storage<Dim>&, Float) override {}

    void finalize(IScheduler& scheduler, Storage<Dim>& s, Float t) override {
        const Vector<Dim> g = g_(t);
        const std::vector<ThermalMaterial> table = thermalMaterials(s);
        const auto T = s.template getValue<Float>(QuantityId::TEMPERATURE);
        const auto a = s.template getD2t<Vector<Dim>>(QuantityId::POSITION);
        const bool hasKind = s.has(QuantityId::KIND), hasMat = s.has(QuantityId::MATERIAL);
        const ArrayView<const int> kind =
            hasKind ? s.template getValue<int>(QuantityId::KIND) : ArrayView<const int>();
        const ArrayView<const int> mat =
            hasMat ? s.template getValue<int>(QuantityId::MATERIAL) : ArrayView<const int>();
        scheduler.parallelFor(s.size(), 4096, [&](Size b, Size e) {
            for (Size i = b; i < e; ++i) {
                if (hasKind && kind[i] != int(ParticleKind::FLUID)) continue;
                const ThermalMaterial& m = table[hasMat ? mat[i] : 0];
                a[i] +=
                    formulas::boussinesqAcceleration(g, m.expansion, T[i], m.referenceTemperature);
            }
        });
    }

    void create(Storage<Dim>& storage, IMaterial& material) const override {
        storage.template insert<Float>(QuantityId::TEMPERATURE, OrderEnum::FIRST,
                                       material.params().get<double>("reference_temperature"));
    }

    Vector<Dim> gravity(Float t) const { return g_(t); }

  private:
    std::function<Vector<Dim>(Float)> g_;
};

}  // namespace num::sph
