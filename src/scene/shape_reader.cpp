// The table of shapes and the reading of each: every shape's keys are checked and read from its
// kind's table (shape_key_tables.cpp), then its "scale", "rotate" and "translate" applied (scaled
// about the origin, rotated about the origin, then moved).
#include "scene/shape_reader.hpp"

#include <array>
#include <memory>
#include <optional>
#include <stdexcept>

#include "geometry/transformed.hpp"
#include "sph/choice_table.hpp"

namespace num::app {

namespace {

using detail::At;
using geometry::SolidPtr;

/// A shape a scene can name: its name and help (which dimensions it exists in and its keys are
/// its type's: shapeType).
struct ShapeName {
    std::string_view name, help;
};

/// Every shape a scene can name.
constexpr std::array shapes{
    ShapeName{"box", "axis-aligned: min, max"},
    ShapeName{"circle", "2D: center, radius"},
    ShapeName{"sphere", "3D: center, radius"},
    ShapeName{"polygon", "2D: points of a closed outline, either orientation"},
    ShapeName{"polyline", "2D wall: points of an open line, thickness"},
    ShapeName{"cylinder", "3D: base, top, radius"},
    ShapeName{"cone", "3D: base, top, base_radius, top_radius"},
    ShapeName{"mesh", "3D: a closed triangle mesh file (STL, OBJ, PLY)"},
    ShapeName{"section", "2D: the section of a closed mesh file by the plane axis = at"},
    ShapeName{"plane", "the half-space behind a plane: point, outward normal"},
    ShapeName{"union", "shapes: every point in any"},
    ShapeName{"intersection", "shapes: the points in all"},
    ShapeName{"difference", "shapes: the first minus the others"},
};

/// The names of the shapes of a Dim-dimensional scene.
template <int Dim>
std::vector<std::string> namesIn() {
    std::vector<std::string> names;
    for (const ShapeName& s : shapes)
        if (shapeType<Dim>(s.name)) names.emplace_back(s.name);
    return names;
}

/// The shape of type `type` at `at`: its keys checked (beside "shape" and the transformations),
/// read and made into its solid.
template <int Dim>
SolidPtr<Dim> readShapeOfType(const At& at, const ShapeType<Dim>& type,
                              const std::string& sceneDir) {
    std::vector<std::string> names{"shape"};
    for (const std::string& name : keyNames(transformKeys<Dim>())) names.push_back(name);
    for (const std::string& name : keyNames(type.keys)) names.push_back(name);
    at.object(names, keyNames(type.keys, true));
    ShapeInput<Dim> in;
    in.object = &at;
    in.sceneDir = &sceneDir;
    readKeyValues(at, type.keys, in, type.readFirst);
    return type.make(in);
}

template <int Dim>
void readRotate(const At& a, TransformInput<Dim>& t) {
    if constexpr (Dim == 2)
        t.degrees[0] = a.number(-1e300, 1e300, false, "degrees");
    else
        t.degrees = detail::readVec<3>(a, "degrees");
}

template <int Dim>
void readTranslate(const At& a, TransformInput<Dim>& t) {
    t.translate = detail::readVec<Dim>(a, "m");
}

template <int Dim>
const KeyTable<TransformInput<Dim>> kTransformKeys{
    {.name = "scale",
     .type = KeyType::NUMBER,
     .field = &TransformInput<Dim>::scale,
     .fallback = 1.0,
     .lo = 0,
     .loOpen = true,
     .meaning = "about the origin, first"},
    {.name = "rotate",
     .type = KeyType::CUSTOM,
     .unit = "degrees",
     .meaning = "about the origin, then: in 2D one angle, counter-clockwise; in 3D `[ax, ay, az]`, "
                "about x, then y, then z (the fixed axes)",
     .read = readRotate<Dim>,
     .shownDefault = "none"},
    {.name = "translate",
     .type = KeyType::CUSTOM,
     .unit = "m",
     .meaning = "a vector, last",
     .read = readTranslate<Dim>,
     .shownDefault = "zero"},
};

/// The shape's "scale", "rotate" and "translate", when given.
template <int Dim>
SolidPtr<Dim> transform(const At& a, SolidPtr<Dim> solid) {
    if (!a.has("scale") && !a.has("rotate") && !a.has("translate")) return solid;
    TransformInput<Dim> t;
    readKeyValues(a, kTransformKeys<Dim>, t);
    return std::make_shared<geometry::Transformed<Dim>>(
        solid, t.scale, geometry::Rotation<Dim>(t.degrees), t.translate);
}

}  // namespace

template <int Dim>
SolidPtr<Dim> readSolid(const At& at, const std::string& sceneDir) {
    if (!at.v.is_object()) at.fail("a shape object ({\"shape\": \"box\", ...})");
    const At shape = at.required("shape");
    const std::vector<std::string> here = namesIn<Dim>();
    const std::optional<std::size_t> known =
        shape.v.is_string() ? sph::choiceIndex(shapes, shape.v.get<std::string>()) : std::nullopt;
    if (known && !shapeType<Dim>(shapes[*known].name))
        shape.fail("a shape of a " + std::to_string(Dim) + "D scene: " + sph::choiceList(here),
                   "\"" + std::string(shapes[*known].name) + "\" is a " + std::to_string(5 - Dim) +
                       "D shape");
    const ShapeType<Dim>& type = *shapeType<Dim>(shape.choice(here));
    try {
        return transform<Dim>(at, readShapeOfType<Dim>(at, type, sceneDir));
    } catch (const std::invalid_argument& e) {
        throw AppError(ExitCode::SCENE, at.file + ": " + at.path + ": " + e.what());
    }
}

template <int Dim>
std::vector<std::string> shapeHelp() {
    std::vector<std::string> help;
    for (const ShapeName& s : shapes)
        if (shapeType<Dim>(s.name))
            help.push_back(std::string(s.name) + " (" + std::string(s.help) + ")");
    return help;
}

template <int Dim>
std::vector<std::pair<std::string, const KeyTable<ShapeInput<Dim>>*>> shapeKeyTables() {
    std::vector<std::pair<std::string, const KeyTable<ShapeInput<Dim>>*>> tables;
    for (const ShapeName& s : shapes)
        if (const ShapeType<Dim>* type = shapeType<Dim>(s.name))
            tables.emplace_back(std::string(s.name), &type->keys);
    return tables;
}

template <int Dim>
const KeyTable<TransformInput<Dim>>& transformKeys() {
    return kTransformKeys<Dim>;
}

template const KeyTable<TransformInput<2>>& transformKeys<2>();
template const KeyTable<TransformInput<3>>& transformKeys<3>();
template SolidPtr<2> readSolid<2>(const At&, const std::string&);
template SolidPtr<3> readSolid<3>(const At&, const std::string&);
template std::vector<std::string> shapeHelp<2>();
template std::vector<std::string> shapeHelp<3>();
template std::vector<std::pair<std::string, const KeyTable<ShapeInput<2>>*>> shapeKeyTables<2>();
template std::vector<std::pair<std::string, const KeyTable<ShapeInput<3>>*>> shapeKeyTables<3>();

}  // namespace num::app
