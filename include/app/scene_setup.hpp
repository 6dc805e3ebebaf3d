// From a checked Scene to what the engine runs: run settings, the fluid model (with heat and
// buoyancy terms), the geometry and the initial particles (emitters: app/emitters.hpp).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "app/scene.hpp"
#include "sph/fluid_model.hpp"

namespace num::app {

template <int Dim>
struct SceneSetup {
    sph::RunSettings settings;
    sph::FluidModel<Dim> model;
    sph::FluidGeometry<Dim> geometry;
    std::map<std::string, int> materialIndex;  ///< scene material name -> storage table index
    int fluidMaterial = 0;                     ///< the material of the equation of state
    int wallLayers = 1;
    double velocityScale = 1;  ///< U of the "auto" sound speed [m/s]
    /// One particle per emitter with every quantity set, to be copied when emitting.
    std::vector<sph::Storage<Dim>> emitterTemplates;
    /// Gravity at time t (expressions of t; x, y, z = 0), ramp included.
    sph::BodyForce<Dim> gravity;
};

/// Builds settings, model and geometry. `threads` goes into the settings; `extraTerms` (a
/// scene's plugin terms) join the model's extraTerms before any particle is made.
template <int Dim>
SceneSetup<Dim> makeSceneSetup(const Scene<Dim>& scene, int threads,
                               const sph::EquationHolder<Dim>& extraTerms = {});

/// The initial particles: the model's particles, then the scene's per-particle expressions
/// (temperature, pressure, velocity of fluid blocks) and thermal conditions of walls and bodies.
template <int Dim>
sph::Storage<Dim> makeInitialStorage(const Scene<Dim>& scene, SceneSetup<Dim>& setup);

}  // namespace num::app
