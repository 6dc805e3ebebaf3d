// One shape of a scene ({"shape": "cylinder", ...}) read into a geometry::Solid. The shapes'
// names and their help come from one table (shape_reader.cpp), from which the choices and the
// error texts come; the dimensions each exists in, its keys and the maker of its solid from its
// type (ShapeType, shape_key_tables.cpp), from which the reader and docs/geometry.md's tables
// come.
#pragma once

#include <string>
#include <string_view>
#include <utility>
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

/// A shape's keys (beside "shape" and the transformations) as they are read: each shape's key
/// table fills those it has; the shape's object and the scene's directory (relative files).
template <int Dim>
struct ShapeInput {
    geometry::Point<Dim> min{}, max{}, center{}, point{}, normal{}, base{}, top{};
    double radius = 0, thickness = 0, baseRadius = 0, topRadius = 0, at = 0;
    std::vector<geometry::Point<Dim>> points;
    std::string file, axis;
    std::vector<geometry::SolidPtr<Dim>> shapes;
    const detail::At* object = nullptr;
    const std::string* sceneDir = nullptr;
};

/// A type of shape: its keys beside "shape" and the transformations (docs/geometry.md's table of
/// the shape is made from them), those of them read first (a shape whose keys were read in
/// another order than its messages list them, before the table) and the maker of its solid
/// from them.
template <int Dim>
struct ShapeType {
    KeyTable<ShapeInput<Dim>> keys;
    std::vector<std::string> readFirst;
    geometry::SolidPtr<Dim> (*make)(const ShapeInput<Dim>& shape);
};

/// The type of the shape `name` in a Dim-dimensional scene; nullptr where there is none (a 3D
/// shape in 2D, an unknown name). Defined in shape_key_tables.cpp.
template <int Dim>
const ShapeType<Dim>* shapeType(std::string_view name);

/// Each shape of a Dim-dimensional scene and its type's keys, in the order of shapeHelp.
template <int Dim>
std::vector<std::pair<std::string, const KeyTable<ShapeInput<Dim>>*>> shapeKeyTables();

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
