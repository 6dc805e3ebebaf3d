// The reader of a body's "motion" (bodies[i].motion, docs/scenes.md): fixed, free or
// prescribed, with its keys checked. The keys of a free and of a prescribed motion and of a
// spring are declared once, in key tables (scene/scene_keys.hpp) from which docs/scenes.md's
// tables of them are made (internal to numerics_app).
#pragma once

#include "app/scene.hpp"
#include "scene/json_check.hpp"
#include "scene/scene_keys.hpp"

namespace num::app {

/// The motion at `m` ("fixed" or an object with "type").
template <int Dim>
BodyMotionSpec<Dim> readBodyMotion(const detail::At& m);

/// The keys of a free motion ("type": "free").
template <int Dim>
const KeyTable<BodyMotionSpec<Dim>>& freeMotionKeys();

/// The keys of a prescribed motion ("type": "prescribed").
template <int Dim>
const KeyTable<BodyMotionSpec<Dim>>& prescribedMotionKeys();

/// The keys of each element of a free motion's "springs".
template <int Dim>
const KeyTable<SpringSpec<Dim>>& springKeys();

}  // namespace num::app
