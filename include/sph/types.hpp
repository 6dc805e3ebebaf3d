// Basic types of the SPH engine: precision, indices, quantity ids and derivative orders.
#pragma once

#include <cmath>
#include <cstdint>
#include <span>

#include "spatial/vec.hpp"

namespace num::sph {

/// Precision of quantities and pair arithmetic.
using Float = double;
/// Particle index.
using Size = std::uint32_t;
/// A view of contiguous memory (the seed's ArrayView).
template <class T>
using ArrayView = std::span<T>;
template <int Dim>
using Vector = Vec<Float, Dim>;

/// Ids of the quantities the engine and its built-in terms know. Users add their own ids
/// by casting any other integer (negative values are reserved for users):
///     enum class AdditionalId { ENERGY_LAPLACIAN = -1 };
///     storage.insert<Float>(QuantityId(AdditionalId::ENERGY_LAPLACIAN), OrderEnum::ZERO, 0.0);
enum class QuantityId : int {
    POSITION = 0,  ///< second order: value x, dt velocity, d2t acceleration
    MASS,          ///< particle mass [kg]
    DENSITY,       ///< mass density [kg/m^3]
    PRESSURE,      ///< pressure [Pa]
    ENERGY,        ///< specific internal energy [J/kg]
    TEMPERATURE,   ///< temperature [degC or K, as the scene uses]
    MATERIAL,      ///< index into the storage's material table (int)
    KIND,          ///< ParticleKind as int: fluid, wall, body, inlet or outlet buffer
    SOUND_SPEED,   ///< local sound speed [m/s]
    // 9 was particle shifting's displacement per unit time and 10 the boundary particles'
    // normal, which no term read; checkpoints hold the ids, so an id is never given another
    // meaning.
    WALL_VELOCITY = 11,  ///< prescribed velocity of boundary particles
    NEIGHBOUR_COUNT,     ///< number of neighbours found in the last evaluation (int)
    OWNER,               ///< the process that owns the particle (int; -1: not yet assigned)
    PARTICLE_ID,         ///< stable particle id (int): never changes, never reused
    ORDER_KEY,           ///< the particle's cell at the last reordering (int, particle_order.hpp)
    BODY_INDEX,          ///< the moving body a particle belongs to (int; -1: none; sph/bodies/)
    BODY_OFFSET,         ///< a body particle's offset from its body's reference point, body frame
    USER_FIRST = 1000    ///< first id free for user quantities (or use negative ids)
};

/// Highest time derivative a quantity carries.
enum class OrderEnum : int { ZERO = 0, FIRST = 1, SECOND = 2 };

/// What a particle is; stored as int in QuantityId::KIND.
/// INLET and OUTLET: the buffer particles of an open boundary (boundary/flow_boundaries.hpp).
enum class ParticleKind : int { FLUID = 0, WALL = 1, BODY = 2, INLET = 3, OUTLET = 4 };
/// The number of kinds: a stored KIND lies in [0, kParticleKinds).
constexpr int kParticleKinds = 5;

/// Whether a stored KIND is a fluid particle (not a wall or body).
NUMERICS_HD_INLINE bool isFluid(int kind) { return kind == int(ParticleKind::FLUID); }

/// The box that holds a set of particles (min > max for none).
template <int Dim>
struct FluidExtent {
    Vector<Dim> min = Vector<Dim>::filled(HUGE_VAL), max = Vector<Dim>::filled(-HUGE_VAL);
    NUMERICS_HD void add(const Vector<Dim>& x) {
        for (int k = 0; k < Dim; ++k)
            min[k] = x[k] < min[k] ? x[k] : min[k], max[k] = x[k] > max[k] ? x[k] : max[k];
    }
};

/// Whether a stored KIND is an inlet's or an outlet's buffer particle.
NUMERICS_HD_INLINE bool isBuffer(int kind) {
    return kind == int(ParticleKind::INLET) || kind == int(ParticleKind::OUTLET);
}

}  // namespace num::sph
