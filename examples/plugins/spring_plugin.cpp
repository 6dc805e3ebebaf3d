// The seed's harmonic spring force (examples/spring_force.hpp) as a plugin: a scene names this
// library under "plugins" and the term "spring" with its stiffness k [N/m]; every particle then
// feels a = -k r / m towards the origin, in fluid_sim (2D) and fluid_sim_3d (3D).
#include <tuple>

#include "app/plugin.hpp"
#include "spring_force.hpp"

NUMERICS_PLUGIN(registry) {
    registry.add<examples::SpringForce>("spring", [](const num::app::plugin::Parameters& p) {
        p.allow({"stiffness", "steps_per_radian"});
        return std::tuple{p.positive("stiffness", "N/m"),
                          p.number("steps_per_radian", 20.0, 1, 1e6)};
    });
}
