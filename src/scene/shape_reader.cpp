// The table of shapes and the reading of each: every shape's keys are checked, then its
// "scale", "rotate" and "translate" applied (scaled about the origin, rotated about the origin,
// then moved).
#include "scene/shape_reader.hpp"

#include <array>
#include <filesystem>
#include <memory>
#include <optional>

#include "geometry/combination.hpp"
#include "geometry/mesh_solid.hpp"
#include "geometry/polygon.hpp"
#include "geometry/primitives.hpp"
#include "geometry/revolved.hpp"
#include "sph/choice_table.hpp"

namespace num::app {

namespace {

using detail::At;
using geometry::Point;
using geometry::SolidPtr;

template <int Dim>
using Reader = SolidPtr<Dim> (*)(const At&, const std::string&);

/// How a shape is read in 2D and in 3D (nullptr: the shape does not exist there).
struct ShapeReaders {
    Reader<2> in2D;
    Reader<3> in3D;
};

/// The keys of a shape plus the transformations every shape takes.
std::vector<std::string> keys(std::initializer_list<std::string> own) {
    std::vector<std::string> all{"shape", "scale", "rotate", "translate"};
    all.insert(all.end(), own);
    return all;
}

template <int Dim>
SolidPtr<Dim> readBox(const At& a, const std::string&) {
    a.object(keys({"min", "max"}), {"min", "max"});
    const Point<Dim> mn = detail::readVec<Dim>(a["min"], "m"),
                     mx = detail::readVec<Dim>(a["max"], "m");
    for (int k = 0; k < Dim; ++k)
        if (!(mx[k] > mn[k])) a["max"].fail("max > min on every axis");
    return std::make_shared<geometry::Box<Dim>>(mn, mx);
}

template <int Dim>
SolidPtr<Dim> readBall(const At& a, const std::string&) {
    a.object(keys({"center", "radius"}), {"center", "radius"});
    return std::make_shared<geometry::Ball<Dim>>(detail::readVec<Dim>(a["center"], "m"),
                                                 a["radius"].number(0, 1e300, true, "m"));
}

template <int Dim>
SolidPtr<Dim> readPlane(const At& a, const std::string&) {
    a.object(keys({"point", "normal"}), {"point", "normal"});
    const Point<Dim> n = detail::readVec<Dim>(a["normal"], "");
    if (!(norm(n) > 0)) a["normal"].fail("a nonzero outward normal");
    return std::make_shared<geometry::HalfSpace<Dim>>(detail::readVec<Dim>(a["point"], "m"), n);
}

/// At least `least` points [m] of Dim coordinates.
template <int Dim>
std::vector<Point<Dim>> readPoints(const At& a, std::size_t least) {
    if (!a.v.is_array() || a.v.size() < least)
        a.fail("a list of " + std::to_string(least) + " points or more ([[x, y], ...])");
    std::vector<Point<Dim>> points;
    for (std::size_t i = 0; i < a.v.size(); ++i) points.push_back(detail::readVec<Dim>(a[i], "m"));
    return points;
}

SolidPtr<2> readPolygon(const At& a, const std::string&) {
    a.object(keys({"points"}), {"points"});
    return geometry::polygon(readPoints<2>(a["points"], 3));
}

SolidPtr<2> readPolyline(const At& a, const std::string&) {
    a.object(keys({"points", "thickness"}), {"points", "thickness"});
    const double thickness = a["thickness"].number(0, 1e300, true, "m");
    return std::make_shared<geometry::Polyline<2>>(readPoints<2>(a["points"], 2), thickness / 2);
}

SolidPtr<3> readCylinder(const At& a, const std::string&) {
    a.object(keys({"base", "top", "radius"}), {"base", "top", "radius"});
    const Point<3> base = detail::readVec<3>(a["base"], "m"),
                   top = detail::readVec<3>(a["top"], "m");
    if (base == top) a["top"].fail("a top apart from the base");
    return geometry::cylinder(base, top, a["radius"].number(0, 1e300, true, "m"));
}

SolidPtr<3> readCone(const At& a, const std::string&) {
    a.object(keys({"base", "top", "base_radius", "top_radius"}),
             {"base", "top", "base_radius", "top_radius"});
    const Point<3> base = detail::readVec<3>(a["base"], "m"),
                   top = detail::readVec<3>(a["top"], "m");
    if (base == top) a["top"].fail("a top apart from the base");
    const double rb = a["base_radius"].number(0, 1e300, false, "m");
    const double rt = a["top_radius"].number(0, 1e300, false, "m");
    if (rb == 0 && rt == 0) a["top_radius"].fail("a radius > 0 at one end at least");
    return std::make_shared<geometry::Cone>(base, top, rb, rt);
}

/// The mesh file of a["file"], relative to the scene's directory, checked to bound a volume.
std::shared_ptr<const geometry::MeshSolid> readClosedMesh(const At& a,
                                                          const std::string& sceneDir) {
    const std::string file = a["file"].string();
    const std::filesystem::path path = std::filesystem::path(sceneDir) / file;
    return std::make_shared<const geometry::MeshSolid>(geometry::readMesh(path.string()), file);
}

SolidPtr<3> readMeshFile(const At& a, const std::string& sceneDir) {
    a.object(keys({"file"}), {"file"});
    return readClosedMesh(a, sceneDir);
}

/// The 2D section of a mesh by the plane x[axis] = at (in the file's units, before "scale").
SolidPtr<2> readSection(const At& a, const std::string& sceneDir) {
    a.object(keys({"file", "axis", "at"}), {"file", "axis", "at"});
    const std::string axis = a["axis"].choice({"x", "y", "z"});
    const double at = a["at"].number();
    const auto loops =
        geometry::sectionLoops(readClosedMesh(a, sceneDir)->mesh(), int(axis[0] - 'x'), at);
    if (loops.empty()) a["at"].fail("a plane " + axis + " = at that cuts the mesh");
    return std::make_shared<geometry::PolygonSet>(loops);
}

template <int Dim, geometry::Combine how>
SolidPtr<Dim> readCombination(const At& a, const std::string& sceneDir) {
    a.object(keys({"shapes"}), {"shapes"});
    const At list = a["shapes"];
    if (!list.v.is_array() || list.v.size() < 2) list.fail("a list of two shapes or more");
    std::vector<SolidPtr<Dim>> parts;
    for (std::size_t i = 0; i < list.v.size(); ++i)
        parts.push_back(readSolid<Dim>(list[i], sceneDir));
    return std::make_shared<geometry::Combination<Dim>>(how, std::move(parts));
}

using geometry::Combine;
template <Combine how>
constexpr ShapeReaders combination{readCombination<2, how>, readCombination<3, how>};

/// Every shape a scene can name.
constexpr std::array shapes{
    sph::Choice<ShapeReaders>{"box", {readBox<2>, readBox<3>}, "axis-aligned: min, max"},
    sph::Choice<ShapeReaders>{"circle", {readBall<2>, nullptr}, "2D: center, radius"},
    sph::Choice<ShapeReaders>{"sphere", {nullptr, readBall<3>}, "3D: center, radius"},
    sph::Choice<ShapeReaders>{
        "polygon", {readPolygon, nullptr}, "2D: points of a closed outline, either orientation"},
    sph::Choice<ShapeReaders>{
        "polyline", {readPolyline, nullptr}, "2D wall: points of an open line, thickness"},
    sph::Choice<ShapeReaders>{"cylinder", {nullptr, readCylinder}, "3D: base, top, radius"},
    sph::Choice<ShapeReaders>{
        "cone", {nullptr, readCone}, "3D: base, top, base_radius, top_radius"},
    sph::Choice<ShapeReaders>{
        "mesh", {nullptr, readMeshFile}, "3D: a closed triangle mesh file (STL, OBJ, PLY)"},
    sph::Choice<ShapeReaders>{"section",
                              {readSection, nullptr},
                              "2D: the section of a closed mesh file by the plane axis = at"},
    sph::Choice<ShapeReaders>{"plane",
                              {readPlane<2>, readPlane<3>},
                              "the half-space behind a plane: point, outward normal"},
    sph::Choice<ShapeReaders>{"union", combination<Combine::UNION>, "shapes: every point in any"},
    sph::Choice<ShapeReaders>{"intersection", combination<Combine::INTERSECTION>,
                              "shapes: the points in all"},
    sph::Choice<ShapeReaders>{"difference", combination<Combine::DIFFERENCE>,
                              "shapes: the first minus the others"},
};

template <int Dim>
Reader<Dim> readerOf(const ShapeReaders& r) {
    if constexpr (Dim == 2)
        return r.in2D;
    else
        return r.in3D;
}

/// The names of the shapes of a Dim-dimensional scene.
template <int Dim>
std::vector<std::string> namesIn() {
    std::vector<std::string> names;
    for (const auto& s : shapes)
        if (readerOf<Dim>(s.value)) names.emplace_back(s.name);
    return names;
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
    if (known && !readerOf<Dim>(shapes[*known].value))
        shape.fail("a shape of a " + std::to_string(Dim) + "D scene: " + sph::choiceList(here),
                   "\"" + std::string(shapes[*known].name) + "\" is a " + std::to_string(5 - Dim) +
                       "D shape");
    const Reader<Dim> read =
        readerOf<Dim>(shapes[*sph::choiceIndex(shapes, shape.choice(here))].value);
    try {
        return transform<Dim>(at, read(at, sceneDir));
    } catch (const std::invalid_argument& e) {
        throw AppError(ExitCode::SCENE, at.file + ": " + at.path + ": " + e.what());
    }
}

template <int Dim>
std::vector<std::string> shapeHelp() {
    std::vector<std::string> help;
    for (const auto& s : shapes)
        if (readerOf<Dim>(s.value))
            help.push_back(std::string(s.name) + " (" + std::string(s.help) + ")");
    return help;
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

}  // namespace num::app
