// One shape of a scene ({"shape": "cylinder", ...}) read into a geometry::Solid. The shapes'
// names, the dimensions they exist in and their help come from one table (shape_reader.cpp),
// from which the reader, the choices and the error texts come.
#pragma once

#include <string>
#include <vector>

#include "geometry/solid.hpp"
#include "scene/json_check.hpp"

namespace num::app {

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
