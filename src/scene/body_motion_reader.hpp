// The reader of a body's "motion" (bodies[i].motion, docs/scenes.md): fixed, free or
// prescribed, with its keys checked (internal to numerics_app).
#pragma once

#include "app/scene.hpp"
#include "scene/json_check.hpp"

namespace num::app {

/// The motion at `m` ("fixed" or an object with "type").
template <int Dim>
BodyMotionSpec<Dim> readBodyMotion(const detail::At& m);

}  // namespace num::app
