// The scene's inlets and outlets (boundaries.<side>.type "inlet" or "outlet") as the run's
// FlowBoundaries, the speed scale their inflow sets, and the checks of their openings and
// velocities (internal to numerics_app).
#pragma once

#include <memory>

#include "app/scene.hpp"
#include "sph/boundary/flow_boundaries.hpp"
#include "sph/setup/fluid_geometry.hpp"

namespace num::app {

/// The inlets and outlets of the scene's sides, each with a buffer `wallLayers` spacings deep,
/// an outlet without a pressure of its own at the background pressure; null where there are
/// none.
template <int Dim>
std::shared_ptr<sph::FlowBoundaries<Dim>> makeFlowBoundaries(const Scene<Dim>& scene,
                                                             const sph::FluidGeometry<Dim>& geo,
                                                             int wallLayers,
                                                             double backgroundPressure);

/// The largest speed an inlet imposes [m/s]: its velocity on the lattice points of its side at
/// 21 times from 0 to the end time (0 without inlets).
template <int Dim>
double largestInflowSpeed(const Scene<Dim>& scene);

/// Refuses (exit code 5, naming the key) an inlet whose velocity points out of the domain at a
/// point of its opening at one of those times, and an opening ("from", "to") off its side,
/// beyond it or narrower than two spacings.
template <int Dim>
void checkFlowSides(const Scene<Dim>& scene);

}  // namespace num::app
