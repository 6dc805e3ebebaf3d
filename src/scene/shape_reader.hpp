// One shape of a scene ({"shape": "cylinder", ...}) read into a geometry::Solid. The shapes'
// names, the dimensions they exist in and their help come from one table (shape_reader.cpp),
// from which the reader, the choices and the error texts come.
#pragma once

#include <string>
#include <vector>

#include "geometry/rotation.hpp"
#include "geometry/solid.hpp"
#include "scene/json_check.hpp"
#include "scene/scene_keys.hpp"

namespace num::app {

/// A shape's transformation as its keys are read (every shape takes them).
template <int Dim>
struct TransformInput {
    double scale = 1;
    geometry::Angles<Dim> degrees{};
    geometry::Point<Dim> translate{};
};

/// The keys "scale", "rotate" and "translate" of every shape, in the order they apply.
template <int Dim>
const KeyTable<TransformInput<Dim>>& transformKeys();

/// The shape object at `at`: its "shape", the keys of that shape, and the optional "scale",
/// "rotate" (degrees) and "translate" of every shape. Files are relative to `sceneDir`.
/// Mistakes, and shapes that cannot be used (a polygon crossing itself, a mesh with holes), are
/// AppErrors (exit code SCENE) naming the file and the key path.
template <int Dim>
geometry::SolidPtr<Dim> readSolid(const detail::At& at, const std::string& sceneDir);

/// "name (help)" of each shape of a Dim-dimensional scene, in the table's order.
template <int Dim>
std::vector<std::string> shapeHelp();

}  // namespace num::app
