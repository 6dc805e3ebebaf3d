// Heat conduction between particles (terms/heat_conduction.hpp), callable on host and device.
// Brookshaw (1985) Laplacian with the harmonic mean of the conductivities (Cleary & Monaghan
// 1999, J. Comput. Phys. 148, eq. 10):
//   c_a dT_a/dt = sum_b 4 m_b k_a k_b / (rho_a rho_b (k_a + k_b)) (T_a - T_b) L_ab,
// L_ab = PairGeometry::laplacian (formulas/pair_geometry.hpp).
#pragma once

#include "sph/host_device.hpp"
#include "sph/types.hpp"

namespace num::sph {

/// What a particle does thermally (boundary/thermal_condition.hpp), stored as int in
/// heat_ids::THERMAL_CONDITION.
enum class ThermalCondition : int {
    CONDUCTING = 0,
    FIXED_TEMPERATURE = 1,
    ADIABATIC = 2,
    HEAT_FLUX = 3
};

/// True if the pair (a, b) exchanges heat by conduction.
NUMERICS_HD_INLINE bool conductsHeat(int conditionA, int conditionB) {
    return conditionA != int(ThermalCondition::ADIABATIC) &&
           conditionB != int(ThermalCondition::ADIABATIC);
}

namespace formulas {

/// The temperature a particle shows to conduction: a fixed-temperature particle's wall value
/// (heat_ids::BOUNDARY_TEMPERATURE), else its own.
NUMERICS_HD_INLINE Float conductionTemperature(int condition, Float T, Float Tfixed) {
    return condition == int(ThermalCondition::FIXED_TEMPERATURE) ? Tfixed : T;
}

/// The pair's exchange per unit mass and heat capacity: 4 k_a k_b / ((k_a + k_b) rho_a rho_b)
/// (T_a - T_b) L_ab. Only for pairs with k_a + k_b > 0.
NUMERICS_HD_INLINE Float heatExchange(Float ka, Float kb, Float rhoA, Float rhoB, Float Ta,
                                      Float Tb, Float laplacian) {
    return 4.0 * ka * kb / ((ka + kb) * rhoA * rhoB) * (Ta - Tb) * laplacian;
}

/// What the pair adds to dT_a/dt: m_b f / c_a (and dT_b/dt -= m_a f / c_b).
NUMERICS_HD_INLINE Float heatRate(Float massB, Float exchange, Float inverseHeatCapacityA) {
    return massB * exchange * inverseHeatCapacityA;
}

}  // namespace formulas
}  // namespace num::sph
