// The scene's body motions for the engine (sph/bodies/): internal to numerics_app.
#pragma once

#include <memory>
#include <string>

#include "app/scene.hpp"
#include "sph/bodies/moving_bodies.hpp"

namespace num::app {

/// Every body with its motion, in scene order; nullptr when every body is fixed.
template <int Dim>
std::shared_ptr<sph::MovingBodies<Dim>> makeMovingBodies(const Scene<Dim>& scene);

/// The body's name in outputs and messages: its "name", else "bodies[i]".
template <int Dim>
std::string bodyName(const Scene<Dim>& scene, std::size_t i);

/// The body's volume [m^3; 2D: m^2] as its mass properties use it.
template <int Dim>
double bodyVolume(const Body<Dim>& body, double dx);

}  // namespace num::app
