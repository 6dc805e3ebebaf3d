// What a particle does thermally, stored per particle as int in heat_ids::THERMAL_CONDITION.
//
//   CONDUCTING         exchanges heat by conduction with its own material and evolves its
//                      temperature (fluid, conducting walls and bodies: conjugate heat transfer)
//   FIXED_TEMPERATURE  exchanges heat but keeps its temperature (Dirichlet wall or body)
//   ADIABATIC          exchanges no heat at all (insulated wall: zero normal flux)
//   HEAT_FLUX          conducts like CONDUCTING and receives the power of heat_ids::HEAT_SOURCE;
//                      a layer of such particles is a heater plate that delivers a fixed flux
//                      (see ThermalBoundary::setHeatFlux)
// The enum and conductsHeat live in sph/formulas/heat_pairs.hpp (host and device).
#pragma once

#include <functional>

#include "sph/formulas/heat_pairs.hpp"
#include "sph/terms/thermal_properties.hpp"

namespace num::sph {

/// Sets the thermal condition of every particle for which select(i) is true. Creates the
/// quantity (CONDUCTING everywhere) if the storage does not have it yet.
template <int Dim>
void setThermalCondition(Storage<Dim>& storage, ThermalCondition condition,
                         const std::function<bool(Size)>& select) {
    storage.template insert<int>(heat_ids::THERMAL_CONDITION, OrderEnum::ZERO,
                                 int(ThermalCondition::CONDUCTING));
    auto c = storage.template getValue<int>(heat_ids::THERMAL_CONDITION);
    for (Size i = 0; i < storage.size(); ++i)
        if (select(i)) c[i] = int(condition);
}

/// Sets the thermal condition of every particle of the given kind (QuantityId::KIND).
template <int Dim>
void setThermalCondition(Storage<Dim>& storage, ThermalCondition condition, ParticleKind kind) {
    const auto k = storage.template getValue<int>(QuantityId::KIND);
    setThermalCondition(storage, condition, [&](Size i) { return k[i] == int(kind); });
}

}  // namespace num::sph
