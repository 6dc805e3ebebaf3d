// The types of shapes (scene/shape_reader.hpp): each shape's key table, beside "shape" and the
// transformations, with the readers of the keys that are more than a value and the maker of the
// solid. The reader reads and checks the keys from these tables, and docs/geometry.md's table
// of each shape's keys is made from them (tests/apps/test_scene_key_docs.cpp fails when the two
// differ). A key checked against another (a box's max against its min) is read after it.
#include <filesystem>
#include <map>
#include <memory>

#include "geometry/combination.hpp"
#include "geometry/mesh_solid.hpp"
#include "geometry/polygon.hpp"
#include "geometry/primitives.hpp"
#include "geometry/revolved.hpp"
#include "scene/shape_reader.hpp"

namespace num::app {

namespace {

using detail::At;
using geometry::Point;
using geometry::SolidPtr;

template <int Dim>
using ShapeKeys = KeyTable<ShapeInput<Dim>>;

template <int Dim, Point<Dim> ShapeInput<Dim>::*member>
void readPoint(const At& a, ShapeInput<Dim>& s) {
    s.*member = detail::readVec<Dim>(a, "m");
}

/// Read after min.
template <int Dim>
void readBoxMax(const At& a, ShapeInput<Dim>& s) {
    s.max = detail::readVec<Dim>(a, "m");
    for (int k = 0; k < Dim; ++k)
        if (!(s.max[k] > s.min[k])) a.fail("max > min on every axis");
}

template <int Dim>
void readNormal(const At& a, ShapeInput<Dim>& s) {
    s.normal = detail::readVec<Dim>(a, "");
    if (!(norm(s.normal) > 0)) a.fail("a nonzero outward normal");
}

/// At least `least` points [m] of Dim coordinates.
template <int Dim, std::size_t least>
void readPoints(const At& a, ShapeInput<Dim>& s) {
    if (!a.v.is_array() || a.v.size() < least)
        a.fail("a list of " + std::to_string(least) + " points or more ([[x, y], ...])");
    for (std::size_t i = 0; i < a.v.size(); ++i)
        s.points.push_back(detail::readVec<Dim>(a[i], "m"));
}

/// A cylinder's or cone's top, read after its base.
template <int Dim>
void readTop(const At& a, ShapeInput<Dim>& s) {
    s.top = detail::readVec<Dim>(a, "m");
    if (s.base == s.top) a.fail("a top apart from the base");
}

template <int Dim>
void readSectionAt(const At& a, ShapeInput<Dim>& s) {
    s.at = a.number();
}

template <int Dim>
void readShapes(const At& list, ShapeInput<Dim>& s) {
    if (!list.v.is_array() || list.v.size() < 2) list.fail("a list of two shapes or more");
    for (std::size_t i = 0; i < list.v.size(); ++i)
        s.shapes.push_back(readSolid<Dim>(list[i], *s.sceneDir));
}

/// A required vector [m] read by readPoint.
template <int Dim, Point<Dim> ShapeInput<Dim>::*member>
SceneKey<ShapeInput<Dim>> pointKey(const char* name, const char* meaning) {
    return {.name = name,
            .type = KeyType::CUSTOM,
            .unit = "m",
            .meaning = meaning,
            .required = true,
            .read = readPoint<Dim, member>};
}

/// A required length [m] > 0 (>= 0 with `zeroAllowed`).
template <int Dim>
SceneKey<ShapeInput<Dim>> lengthKey(const char* name, double ShapeInput<Dim>::*field,
                                    const char* meaning, bool zeroAllowed = false) {
    return {.name = name,
            .type = KeyType::NUMBER,
            .field = field,
            .fallback = 0.0,
            .unit = "m",
            .lo = 0,
            .loOpen = !zeroAllowed,
            .meaning = meaning,
            .required = true};
}

template <int Dim>
const ShapeKeys<Dim> kBoxKeys{pointKey<Dim, &ShapeInput<Dim>::min>(
                                  "min", "the lowest corner (axis-aligned; turned by `rotate`)"),
                              {.name = "max",
                               .type = KeyType::CUSTOM,
                               .unit = "m",
                               .meaning = "the highest corner: `max > min` on every axis",
                               .required = true,
                               .read = readBoxMax<Dim>}};

template <int Dim>
SolidPtr<Dim> makeBox(const ShapeInput<Dim>& s) {
    return std::make_shared<geometry::Box<Dim>>(s.min, s.max);
}

/// A circle's or a sphere's. The radius was read before the centre (the arguments of one call,
/// in the order the compiler evaluated them), before the table.
template <int Dim>
const ShapeKeys<Dim> kBallKeys{pointKey<Dim, &ShapeInput<Dim>::center>("center", "the centre"),
                               lengthKey<Dim>("radius", &ShapeInput<Dim>::radius, "")};

template <int Dim>
SolidPtr<Dim> makeBall(const ShapeInput<Dim>& s) {
    return std::make_shared<geometry::Ball<Dim>>(s.center, s.radius);
}

/// The normal was read before the point, before the table.
template <int Dim>
const ShapeKeys<Dim> kPlaneKeys{
    pointKey<Dim, &ShapeInput<Dim>::point>("point", "a point of the plane"),
    {.name = "normal",
     .type = KeyType::CUSTOM,
     .meaning = "the plane's outward normal, not zero: the half-space behind the plane (against "
                "the normal) is inside",
     .required = true,
     .read = readNormal<Dim>}};

template <int Dim>
SolidPtr<Dim> makePlane(const ShapeInput<Dim>& s) {
    return std::make_shared<geometry::HalfSpace<Dim>>(s.point, s.normal);
}

/// A union's, an intersection's or a difference's.
template <int Dim>
const ShapeKeys<Dim> kCombinationKeys{
    {.name = "shapes",
     .type = KeyType::CUSTOM,
     .meaning = "two shapes or more, each with its keys (combinations nest)",
     .required = true,
     .read = readShapes<Dim>}};

template <int Dim, geometry::Combine how>
SolidPtr<Dim> makeCombination(const ShapeInput<Dim>& s) {
    return std::make_shared<geometry::Combination<Dim>>(how, s.shapes);
}

const ShapeKeys<2> kPolygonKeys{
    {.name = "points",
     .type = KeyType::CUSTOM,
     .unit = "m",
     .meaning = "3 points or more, `[[x, y], ...]`, round a closed outline in either direction "
                "(the last joins the first); it must not cross itself",
     .required = true,
     .read = readPoints<2, 3>}};

SolidPtr<2> makePolygon(const ShapeInput<2>& s) { return geometry::polygon(s.points); }

/// The thickness was read before the points, before the table.
const ShapeKeys<2> kPolylineKeys{
    {.name = "points",
     .type = KeyType::CUSTOM,
     .unit = "m",
     .meaning = "2 points or more, `[[x, y], ...]`, of an open line",
     .required = true,
     .read = readPoints<2, 2>},
    lengthKey<2>("thickness", &ShapeInput<2>::thickness,
                 "the band's width: the points within `thickness` / 2 of the line (its ends "
                 "rounded)")};

SolidPtr<2> makePolyline(const ShapeInput<2>& s) {
    return std::make_shared<geometry::Polyline<2>>(s.points, s.thickness / 2);
}

const SceneKey<ShapeInput<3>> kBaseKey =
    pointKey<3, &ShapeInput<3>::base>("base", "the centre of the disc at one end");

/// A cylinder's or cone's top, read after its base.
const SceneKey<ShapeInput<3>> kTopKey{
    .name = "top",
    .type = KeyType::CUSTOM,
    .unit = "m",
    .meaning =
        "the centre of the disc at the other end, apart from `base` (anywhere: not above it, "
        "slanted)",
    .required = true,
    .read = readTop<3>};

const ShapeKeys<3> kCylinderKeys{kBaseKey, kTopKey,
                                 lengthKey<3>("radius", &ShapeInput<3>::radius, "")};

SolidPtr<3> makeCylinder(const ShapeInput<3>& s) {
    return geometry::cylinder(s.base, s.top, s.radius);
}

const ShapeKeys<3> kConeKeys{
    kBaseKey, kTopKey,
    lengthKey<3>("base_radius", &ShapeInput<3>::baseRadius, "the radius at `base`", true),
    lengthKey<3>("top_radius", &ShapeInput<3>::topRadius,
                 "the radius at `top` (0: a tip); not both 0", true)};

/// Refuses a cone without a radius, after both are read.
SolidPtr<3> makeCone(const ShapeInput<3>& s) {
    if (s.baseRadius == 0 && s.topRadius == 0)
        (*s.object)["top_radius"].fail("a radius > 0 at one end at least");
    return std::make_shared<geometry::Cone>(s.base, s.top, s.baseRadius, s.topRadius);
}

/// A mesh's or a section's (a function: a table of another variable is initialised first).
template <int Dim>
SceneKey<ShapeInput<Dim>> fileKey() {
    return {.name = "file",
            .type = KeyType::TEXT,
            .field = &ShapeInput<Dim>::file,
            .fallback = std::string(),
            .meaning =
                "a closed triangle mesh file (STL, OBJ, PLY), relative to the scene "
                "file's folder",
            .required = true};
}

/// The mesh file, relative to the scene's directory, checked to bound a volume.
template <int Dim>
std::shared_ptr<const geometry::MeshSolid> closedMesh(const ShapeInput<Dim>& s) {
    const std::filesystem::path path = std::filesystem::path(*s.sceneDir) / s.file;
    return std::make_shared<const geometry::MeshSolid>(geometry::readMesh(path.string()), s.file);
}

SolidPtr<3> makeMesh(const ShapeInput<3>& s) { return closedMesh(s); }

/// The axis and the plane were read before the file, before the table.
const ShapeKeys<2> kSectionKeys{
    fileKey<2>(),
    {.name = "axis",
     .type = KeyType::CHOICE,
     .field = &ShapeInput<2>::axis,
     .fallback = std::string(),
     .choices = {"x", "y", "z"},
     .meaning = "the axis the cutting plane is normal to; the section's coordinates are the two "
                "others in cyclic order",
     .required = true},
    {.name = "at",
     .type = KeyType::CUSTOM,
     .meaning = "a number: the plane `axis = at` (in the file's units, before `scale`), which "
                "must cut the mesh",
     .required = true,
     .read = readSectionAt<2>}};

/// The 2D section of a mesh by the plane x[axis] = at (in the file's units, before "scale").
SolidPtr<2> makeSection(const ShapeInput<2>& s) {
    const auto loops = geometry::sectionLoops(closedMesh(s)->mesh(), int(s.axis[0] - 'x'), s.at);
    if (loops.empty()) (*s.object)["at"].fail("a plane " + s.axis + " = at that cuts the mesh");
    return std::make_shared<geometry::PolygonSet>(loops);
}

template <int Dim>
std::map<std::string, ShapeType<Dim>, std::less<>> typesIn() {
    using geometry::Combine;
    std::map<std::string, ShapeType<Dim>, std::less<>> types{
        {"box", {kBoxKeys<Dim>, {}, makeBox<Dim>}},
        {"plane", {kPlaneKeys<Dim>, {"normal"}, makePlane<Dim>}},
        {"union", {kCombinationKeys<Dim>, {}, makeCombination<Dim, Combine::UNION>}},
        {"intersection", {kCombinationKeys<Dim>, {}, makeCombination<Dim, Combine::INTERSECTION>}},
        {"difference", {kCombinationKeys<Dim>, {}, makeCombination<Dim, Combine::DIFFERENCE>}}};
    if constexpr (Dim == 2)
        types.insert({{"circle", {kBallKeys<2>, {"radius"}, makeBall<2>}},
                      {"polygon", {kPolygonKeys, {}, makePolygon}},
                      {"polyline", {kPolylineKeys, {"thickness"}, makePolyline}},
                      {"section", {kSectionKeys, {"axis", "at"}, makeSection}}});
    else
        types.insert({{"sphere", {kBallKeys<3>, {"radius"}, makeBall<3>}},
                      {"cylinder", {kCylinderKeys, {}, makeCylinder}},
                      {"cone", {kConeKeys, {}, makeCone}},
                      {"mesh", {{fileKey<3>()}, {}, makeMesh}}});
    return types;
}

}  // namespace

template <int Dim>
const ShapeType<Dim>* shapeType(std::string_view name) {
    static const std::map<std::string, ShapeType<Dim>, std::less<>> types = typesIn<Dim>();
    const auto found = types.find(name);
    return found == types.end() ? nullptr : &found->second;
}

template const ShapeType<2>* shapeType<2>(std::string_view);
template const ShapeType<3>* shapeType<3>(std::string_view);

}  // namespace num::app
