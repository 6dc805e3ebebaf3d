// Temperature-dependent viscosity: sets each fluid particle's kinematic viscosity from its
// temperature before the pair loop, for the viscous terms that read
// FluidId::KINEMATIC_VISCOSITY.
//
//   Exponential (Reynolds 1886):  nu(T) = nu0 exp(-b (T - T0))
//       nu0 = the material's "viscosity", T0 its "reference_temperature", b [1/K] given.
//   Water (Vogel 1921 fit, T in degC):  mu(T) = A exp(B / (T + 273.15 - C)),
//       A = 2.939e-5 Pa s, B = 507.88 K, C = 149.3 K (mu(20 degC) = 1.003e-3 Pa s),
//       nu = mu / rho0.
// The laws: ViscosityOfTemperature in sph/formulas/fluid_particles.hpp (host and device).
// Boundary particles get the law at their own temperature with their material's parameters:
// in the no-slip condition their viscosity stands for that of the fluid at the wall (a wall
// at T0 + 20 K that kept nu0 made a warm channel's peak velocity 2 % too low). Runs
// in initialize, so it must come before the viscous terms (makeHeatPreEquations); their
// time-step limit reads the updated values.
#pragma once

#include <vector>

#include "sph/equation_term.hpp"
#include "sph/formulas/fluid_particles.hpp"
#include "sph/terms/fluid_quantities.hpp"
#include "sph/terms/thermal_properties.hpp"

namespace num::sph {

template <int Dim>
class TemperatureViscosity : public IEquationTerm<Dim> {
  public:
    explicit TemperatureViscosity(ViscosityOfTemperature law = {}) : law_(law) {}

    void setDerivatives(DerivativeHolder<Dim>&, const RunSettings&) override {}
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}

    void initialize(IScheduler& scheduler, Storage<Dim>& s, Float) override {
        const std::vector<ThermalMaterial> table = thermalMaterials(s);
        std::vector<Float> nu0(table.size());
        for (std::size_t m = 0; m < table.size(); ++m)
            nu0[m] = s.materials()[m]->params().template get<double>("viscosity");
        const auto T = s.template getValue<Float>(QuantityId::TEMPERATURE);
        const auto nu = s.template getValue<Float>(FluidId::KINEMATIC_VISCOSITY);
        const bool hasMat = s.has(QuantityId::MATERIAL);
        const ArrayView<const int> mat =
            hasMat ? s.template getValue<int>(QuantityId::MATERIAL) : ArrayView<const int>();
        scheduler.parallelFor(s.size(), 4096, [&](Size b, Size e) {
            for (Size i = b; i < e; ++i) {
                const int k = hasMat ? mat[i] : 0;
                nu[i] = law_(T[i], nu0[k], table[k].referenceTemperature, table[k].density);
            }
        });
    }

    TermAccess access() const override {
        return {.reads = {QuantityId::TEMPERATURE}, .prepares = {FluidId::KINEMATIC_VISCOSITY}};
    }
    void create(Storage<Dim>& storage, IMaterial& material) const override {
        const ParameterSet& p = material.params();
        storage.template insert<Float>(QuantityId::TEMPERATURE, OrderEnum::FIRST,
                                       p.get<double>("reference_temperature"));
        storage.template insert<Float>(FluidId::KINEMATIC_VISCOSITY, OrderEnum::ZERO,
                                       p.get<double>("viscosity"));
    }

  private:
    ViscosityOfTemperature law_;
};

}  // namespace num::sph
