// A moving body must stay in the domain: a particle of it beyond a side by more than half a
// spacing (it passed through a wall, or left through an open side) stops the run (exit 9),
// naming the body. Periodic axes are not checked. Internal to numerics_app.
#pragma once

#include <string>

#include "app/errors.hpp"
#include "app/formatted.hpp"
#include "app/scene.hpp"
#include "sph/bodies/moving_bodies.hpp"
#include "sph/storage.hpp"

namespace num::app {

template <int Dim>
void checkBodiesInside(const sph::Storage<Dim>& s, const Scene<Dim>& scene,
                       const sph::MovingBodies<Dim>& bodies, double t) {
    using sph::QuantityId;
    const auto x = s.template getValue<sph::Vector<Dim>>(QuantityId::POSITION);
    const auto body = s.template getValue<int>(QuantityId::BODY_INDEX);
    const double margin = 0.5 * scene.spacing;
    for (sph::Size j = 0; j < s.size(); ++j) {
        if (!bodies.moves(body[j])) continue;
        for (int k = 0; k < Dim; ++k)
            for (int hi = 0; hi < 2; ++hi) {
                if (scene.sides[k][hi]->wraps()) continue;
                const double beyond =
                    hi ? x[j][k] - scene.domainMax[k] : scene.domainMin[k] - x[j][k];
                if (!(beyond <= margin))
                    throw AppError(
                        ExitCode::UNSTABLE,
                        bodies.bodies[body[j]].name +
                            formatted(" left the domain at t = %.6g s", t) + " through its " +
                            sideName(k, hi) + " side" +
                            (scene.sides[k][hi]->closes() ? " (it passed through the wall)" : "") +
                            ": keep the body inside the domain, or slow it down (a stiffer spring, "
                            "a lower prescribed velocity)");
            }
    }
}

}  // namespace num::app
