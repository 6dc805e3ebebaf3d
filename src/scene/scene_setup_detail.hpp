// Internal to the scene_setup parts: scene expressions at a point, the "auto" velocity scale.
#pragma once

#include <string>

#include "app/scene.hpp"

namespace num::app::detail {

/// An expression, or a vector field of them, at the point x and the time t.
template <int Dim>
double at(const Expression& e, const sph::Vector<Dim>& x, double t) {
    return e(x[0], Dim > 1 ? x[1] : 0.0, Dim > 2 ? x[Dim - 1] : 0.0, t);
}

template <int Dim>
sph::Vector<Dim> at(const VectorField<Dim>& f, const sph::Vector<Dim>& x, double t) {
    sph::Vector<Dim> v;
    for (int k = 0; k < Dim; ++k) v[k] = at<Dim>(f[k], x, t);
    return v;
}

/// The velocity scale U of the "auto" sound speed (gravity taken at the end of its ramp), or,
/// where nothing moves the fluid, the one the material's sound speed implies (U = c0 / 10).
/// Checks the sound speed it gives (at most kMaxSoundSpeed).
template <int Dim>
double settledVelocityScale(const Scene<Dim>& scene, const std::string& fluidName);

}  // namespace num::app::detail
