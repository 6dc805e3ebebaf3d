// Quantity ids and particle-kind helpers shared by the fluid terms and the wall conditions.
//
// The engine's ids (types.hpp) cover position, mass, density, pressure, temperature, material,
// kind, wall velocity and normal. The fluid terms add the few below, in the range 100..199
// (heat terms use 200..299; users keep >= USER_FIRST and negative ids).
#pragma once

#include "sph/equation_term.hpp"
#include "sph/storage.hpp"
#include "sph/types.hpp"

namespace num::sph {

namespace FluidId {
/// Slip condition of a boundary particle (int): 0 no-slip, 1 free-slip.
inline constexpr QuantityId WALL_SLIP = QuantityId(101);
/// Kinematic viscosity nu of each particle [m^2/s] (Float); a term may change it per step
/// (e.g. a temperature-dependent viscosity) before the pair loop.
inline constexpr QuantityId KINEMATIC_VISCOSITY = QuantityId(102);
/// Kernel sum over the neighbours, sum_{j != i} V_j W_ij, of the last evaluation (Float); the
/// kernel sum is C_i = KERNEL_SUM_i + V_i W(0) (terms/free_surface.hpp).
inline constexpr QuantityId KERNEL_SUM = QuantityId(103);
/// Gradient of the kernel sum, sum_j V_j grad_i W_ij (Vector), from particle shifting.
inline constexpr QuantityId KERNEL_SUM_GRADIENT = QuantityId(104);
/// Column b of the velocity gradient, sum_j V_j (v_j - v_i) d_b W_ij (Vector), b = 0..Dim-1,
/// and the density gradient (Vector), from particle shifting (for its Taylor correction).
inline constexpr QuantityId VELOCITY_GRADIENT_0 = QuantityId(105);
inline constexpr QuantityId DENSITY_GRADIENT = QuantityId(108);
/// sum_j V_j W_ij over the neighbours j that were at a free surface (C_j < 0.9) in the previous
/// evaluation (Float): > 0 within one kernel support of a free surface.
inline constexpr QuantityId SURFACE_NEIGHBOURS = QuantityId(109);
/// sum_j V_j grad_i W_ij over the boundary neighbours j (walls and bodies) of the last
/// evaluation (Vector): points towards the walls within one kernel support of them, zero
/// elsewhere; from particle shifting.
inline constexpr QuantityId WALL_DIRECTION = QuantityId(110);
/// Per-particle inputs of the pair terms, prepared once per evaluation: the volume m / rho
/// (Float, by PairInputs, terms/pair_inputs.hpp) and the velocity a particle shows its
/// neighbours in the viscous terms and in shifting (Vector): v for fluid (by PairInputs), for a
/// boundary particle the wall condition's 2 v_wall - v~ (no-slip) or v_wall (free-slip; Adami,
/// Hu & Adams 2012, eq. 22-23). Id 100 was the boundary particles' velocity in an array of its
/// own, now the boundary entries of PAIR_VELOCITY.
inline constexpr QuantityId VOLUME = QuantityId(111);
inline constexpr QuantityId PAIR_VELOCITY = QuantityId(112);
}  // namespace FluidId

enum class WallSlip : int { NO_SLIP = 0, FREE_SLIP = 1 };

}  // namespace num::sph
