// Per-material thermal properties and the quantity ids the heat terms add to the storage.
//
// Materials are num::sph::Material entries of the storage's material table; a particle's
// material is its QuantityId::MATERIAL index (particles without that quantity use entry 0).
// Heat terms read "conductivity" k [W/(m K)], "heat_capacity" c [J/(kg K)], "density" rho0,
// "thermal_expansion" beta [1/K] and "reference_temperature" T0 of each material.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "sph/storage.hpp"

namespace num::sph {

/// Quantity ids of the heat terms (the range 200..299 is theirs; fluid terms use 100..199).
namespace heat_ids {
/// ThermalCondition of each particle (int); see boundary/thermal_condition.hpp.
inline constexpr QuantityId THERMAL_CONDITION = QuantityId(200);
/// Heat source per unit mass [W/kg] (Float), e.g. the particles of a heated wall.
inline constexpr QuantityId HEAT_SOURCE = QuantityId(201);
/// Temperature a FIXED_TEMPERATURE boundary particle shows to conduction (Float), when the wall
/// condition provides it: 2 T_b - T~_b, T~_b the Shepard mean of the fluid temperatures around
/// it, which puts the prescribed T_b on the wall surface (boundary/generalized_wall.hpp).
inline constexpr QuantityId BOUNDARY_TEMPERATURE = QuantityId(202);
}  // namespace heat_ids

/// One material's thermal parameters, read once per evaluation (not per pair).
struct ThermalMaterial {
    Float conductivity = 0;          ///< k [W/(m K)]
    Float heatCapacity = 1;          ///< c [J/(kg K)]
    Float density = 1;               ///< rho0 [kg/m^3]
    Float expansion = 0;             ///< beta [1/K]
    Float referenceTemperature = 0;  ///< T0

    Float diffusivity() const { return conductivity / (density * heatCapacity); }
};

/// The thermal parameters of every material of a material table, indexed like it.
inline std::vector<ThermalMaterial> thermalMaterials(
    const std::vector<std::shared_ptr<IMaterial>>& materials) {
    if (materials.empty())
        throw std::invalid_argument(
            "heat terms: the storage has no material table (add a Material to "
            "storage.materials(); QuantityId::MATERIAL indexes it)");
    std::vector<ThermalMaterial> out;
    out.reserve(materials.size());
    for (const auto& m : materials) {
        if (!m) throw std::invalid_argument("heat terms: empty entry in the material table");
        const ParameterSet& p = m->params();
        ThermalMaterial t;
        t.conductivity = p.get<double>("conductivity");
        t.heatCapacity = p.get<double>("heat_capacity");
        t.density = p.get<double>("density");
        t.expansion = p.get<double>("thermal_expansion");
        t.referenceTemperature = p.get<double>("reference_temperature");
        out.push_back(t);
    }
    return out;
}

/// The thermal parameters of every material in the storage's table, indexed like it.
template <int Dim>
std::vector<ThermalMaterial> thermalMaterials(const Storage<Dim>& storage) {
    return thermalMaterials(storage.materials());
}

/// Material index of every particle (0 when the storage has no QuantityId::MATERIAL), checked
/// against the table size.
template <int Dim>
std::vector<int> materialIndices(const Storage<Dim>& storage, std::size_t tableSize) {
    std::vector<int> idx(storage.size(), 0);
    if (storage.has(QuantityId::MATERIAL)) {
        const auto mat = storage.template getValue<int>(QuantityId::MATERIAL);
        idx.assign(mat.begin(), mat.end());
    }
    for (int m : idx)
        if (m < 0 || std::size_t(m) >= tableSize)
            throw std::out_of_range("heat terms: particle material index " + std::to_string(m) +
                                    " outside the material table of " + std::to_string(tableSize) +
                                    " entries");
    return idx;
}

}  // namespace num::sph
