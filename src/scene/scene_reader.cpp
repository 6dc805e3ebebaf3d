// readScene: every key of the scene format (docs/scenes.md) with its type, unit and range.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include "app/formatted.hpp"
#include "app/nozzle.hpp"
#include "app/scene_loader.hpp"
#include "geometry/scale_check.hpp"
#include "scene/boundary_types.hpp"
#include "scene/json_check.hpp"
#include "scene/scene_keys.hpp"
#include "scene/shape_reader.hpp"

namespace num::app {

using detail::At;

namespace {

using detail::readField;
using detail::readVec;

MaterialSpec readMaterial(const At& a, const std::string& name) {
    MaterialSpec m;
    m.name = name;
    readKeys(a, materialKeys(), m);
    return m;
}

/// The side names of a Dim-dimensional box, "x_min, x_max, ...".
template <int Dim>
std::string sideList() {
    std::string list;
    for (int k = 0; k < Dim; ++k)
        for (int hi = 0; hi < 2; ++hi)
            list += (list.empty() ? "" : ", ") + std::string(sideName(k, hi));
    return list;
}

/// The side names before x_min ... z_max (left/right = x, bottom/top = y, back/front = z).
int legacySide(const std::string& key, int& high) {
    static const char* old[3][2] = {{"left", "right"}, {"bottom", "top"}, {"back", "front"}};
    for (int k = 0; k < 3; ++k)
        for (high = 0; high < 2; ++high)
            if (key == old[k][high]) return k;
    return -1;
}

template <int Dim>
void readSides(const At& a, Scene<Dim>& s) {
    if (!a.v.is_object()) a.fail("an object with the sides of the domain box");
    std::vector<std::string> allowed;
    for (int k = 0; k < Dim; ++k)
        allowed.push_back(sideName(k, 0)), allowed.push_back(sideName(k, 1));
    const std::string expected =
        "a side of the " + std::to_string(Dim) + "D domain box (" + sideList<Dim>() + ")";
    for (const auto& [key, value] : a.v.items()) {
        if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
        int high = 0;
        const int axis = legacySide(key, high);
        if (axis >= 0 && axis < Dim)
            throw sceneError(a.file, a.join(key), expected, "the old side name '" + key + "'",
                             "side names are " + sideList<Dim>() + "; did you mean " +
                                 sideName(axis, high) +
                                 "? The old left/right, bottom/top, back/front were the x, y, z "
                                 "sides");
        const std::string guess = detail::closest(key, allowed);
        throw sceneError(a.file, a.join(key), expected, "'" + key + "'",
                         guess.empty() ? "" : "did you mean '" + guess + "'?");
    }
    for (int k = 0; k < Dim; ++k)
        for (int hi = 0; hi < 2; ++hi) {
            const char* name = sideName(k, hi);
            if (!a.has(name))
                a.failAt(name, "this side's boundary (" + boundaryTypeChoices<Dim>() +
                                   "; every side must be given)");
            s.sides[k][hi] = readSideBoundary<Dim>(a[name]);
        }
    for (int k = 0; k < Dim; ++k) {
        const bool lo = s.sides[k][0]->wraps(), hi = s.sides[k][1]->wraps();
        if (lo == hi) continue;
        const std::string wrapping = s.sides[k][lo ? 0 : 1]->type();
        throw sceneError(a.file, a.join(sideName(k, lo ? 1 : 0)) + ".type",
                         "\"" + wrapping + "\" as on the opposite side '" +
                             sideName(k, lo ? 0 : 1) + "' (" + wrapping +
                             " applies to both sides of an axis)",
                         "\"" + std::string(s.sides[k][lo ? 1 : 0]->type()) + "\"");
    }
}

/// Whether a shape object is a plain box or ball, read here as the scenes before other shapes
/// were (the fast path, which the CUDA back end runs too): "box", "circle" or "sphere" without
/// a transformation. Every other shape is readSolid's (scene/shape_reader.hpp).
bool isBoxOrBall(const At& a) {
    if (!a.has("shape") || !a["shape"].v.is_string()) return true;  // the messages of a box
    const std::string name = a["shape"].v.get<std::string>();
    if (name != "box" && name != "circle" && name != "sphere") return false;
    return !a.has("rotate") && !a.has("translate") && !a.has("scale");
}

template <int Dim>
void readBoxOrBall(const At& a, SceneShape<Dim>& s) {
    const char* round = Dim == 2 ? "circle" : "sphere";
    const std::string name = a.required("shape").choice({"box", "circle", "sphere"});
    if (name != "box" && name != round)
        a["shape"].fail(std::string("\"box\" or \"") + round + "\" in a " + std::to_string(Dim) +
                        "D scene");
    s.shape = name == "box" ? ShapeKind::BOX : Dim == 2 ? ShapeKind::CIRCLE : ShapeKind::SPHERE;
    if (s.shape == ShapeKind::BOX) {
        s.min = readVec<Dim>(a.required("min"), "m");
        s.max = readVec<Dim>(a.required("max"), "m");
        for (int k = 0; k < Dim; ++k)
            if (!(s.max[k] > s.min[k])) a["max"].fail("max > min on every axis");
        for (const char* key : {"center", "radius"})
            if (a.has(key)) a[key].fail("no '" + std::string(key) + "' for a box (use min, max)");
    } else {
        s.center = readVec<Dim>(a.required("center"), "m");
        s.radius = a.required("radius").number(0, 1e300, true, "m");
        for (const char* key : {"min", "max"})
            if (a.has(key))
                a[key].fail("no '" + std::string(key) + "' for a " + round +
                            " (use center, radius)");
    }
}

/// Any shape (docs/geometry.md) by readSolid, given the object without the keys of its owner
/// (`own`: a block's material, a wall's thermal...). What the geometry library refuses (a mesh
/// that is not closed, a file that is not a mesh) becomes a scene error naming the key path.
template <int Dim>
void readGeneralShape(const At& a, const std::vector<std::string>& own, SceneShape<Dim>& s) {
    detail::json shapeOnly = a.v;
    for (const std::string& key : own) shapeOnly.erase(key);
    const At at{shapeOnly, a.file, a.path};
    const std::string sceneDir = std::filesystem::path(a.file).parent_path().string();
    s.shape = ShapeKind::SOLID;
    try {
        s.solid = readSolid<Dim>(at, sceneDir);
    } catch (const AppError&) {
        throw;
    } catch (const std::exception& e) {
        throw sceneError(a.file, a.path, "a usable shape", "", e.what());
    }
}

/// A shape object with its owner's keys: `keys` are those a box or ball may have (its own and
/// its owner's), `required` those it must have. A box or ball is read as it always was; other
/// shapes have readSolid's keys beside their owner's.
template <int Dim>
void readShape(const At& a, const std::vector<std::string>& keys,
               const std::vector<std::string>& required, SceneShape<Dim>& s) {
    if (isBoxOrBall(a)) {
        a.object(keys, required);
        readBoxOrBall(a, s);
        return;
    }
    if (!a.v.is_object()) a.fail("an object");
    const std::vector<std::string> shapeKeys = {"shape", "min", "max", "center", "radius"};
    std::vector<std::string> own;
    for (const std::string& key : keys)
        if (std::find(shapeKeys.begin(), shapeKeys.end(), key) == shapeKeys.end())
            own.push_back(key);
    for (const std::string& key : required) a.required(key);
    readGeneralShape(a, own, s);
}

/// The shape of a fluid block, body or wall, whose keys are `table`'s (a box's or ball's after
/// `shape`; scene_keys.hpp). The table's other keys are read after it.
template <int Dim, class Spec>
void readPlacedShape(const At& a, const KeyTable<Spec>& table, SceneShape<Dim>& s) {
    std::vector<std::string> keys, required;
    for (const SceneKey<Spec>& k : table) {
        keys.push_back(k.name);
        if (keys.back() == "shape") keys.insert(keys.end(), {"min", "max", "center", "radius"});
        if (k.required) required.push_back(k.name);
    }
    readShape<Dim>(a, keys, required, s);
}

/// Warns of open sides whose normal is perpendicular to gravity: fluid flows out through them
/// sideways, which is rarely meant (an open top faces against gravity).
template <int Dim>
void warnSidewaysOpenSides(Scene<Dim>& s) {
    SceneVec<Dim> g{}, mid = (s.domainMin + s.domainMax) / 2.0;
    double g2 = 0;
    try {
        for (int k = 0; k < Dim; ++k)
            g[k] = s.gravity[k](mid[0], mid[1], Dim == 3 ? mid[Dim - 1] : 0.0, s.endTime);
    } catch (const ExpressionError&) {
        return;  // reported where gravity is evaluated
    }
    for (int k = 0; k < Dim; ++k) g2 += g[k] * g[k];
    if (!(g2 > 0) || !std::isfinite(g2)) return;
    int down = 0;
    for (int k = 1; k < Dim; ++k)
        if (std::abs(g[k]) > std::abs(g[down])) down = k;
    const char* top = sideName(down, g[down] < 0 ? 1 : 0);
    std::string gText;
    for (int k = 0; k < Dim; ++k) gText += (k ? ", " : "") + formatted("%g", g[k]);
    for (int k = 0; k < Dim; ++k)
        for (int hi = 0; hi < 2; ++hi)
            if (s.sides[k][hi]->letsFluidOut() && std::abs(g[k]) <= 1e-12 * std::sqrt(g2))
                s.warnings.push_back(s.file + ": boundaries." + sideName(k, hi) +
                                     ": an open side facing sideways to gravity [" + gText +
                                     "] m/s^2: fluid can flow out through it (the side above "
                                     "the fluid is " +
                                     top + ")");
}

/// Warns of shapes a hundred times larger or smaller than the domain (a mesh in millimetres
/// in a scene in metres).
template <int Dim>
void warnShapeScales(Scene<Dim>& s) {
    const geometry::Bounds<Dim> domain{s.domainMin, s.domainMax};
    auto check = [&](const SceneShape<Dim>& shape, const std::string& path) {
        if (shape.shape != ShapeKind::SOLID) return;
        const std::string warning = geometry::scaleWarning(shape.solid->bounds(), domain);
        if (!warning.empty()) s.warnings.push_back(s.file + ": " + path + ": " + warning);
    };
    for (std::size_t i = 0; i < s.fluids.size(); ++i)
        check(s.fluids[i], "fluids[" + std::to_string(i) + "]");
    for (std::size_t i = 0; i < s.bodies.size(); ++i)
        check(s.bodies[i], "bodies[" + std::to_string(i) + "]");
    for (std::size_t i = 0; i < s.walls.size(); ++i)
        check(s.walls[i], "walls[" + std::to_string(i) + "]");
}

/// Warns of nozzles that a body or wall cuts: they inject across their open part only.
template <int Dim>
void warnCutNozzles(Scene<Dim>& s) {
    for (std::size_t i = 0; i < s.emitters.size(); ++i) {
        const Nozzle<Dim> nozzle = openNozzle(s, i);
        if (nozzle.cut == 0) continue;
        s.warnings.push_back(s.file + ": emitters[" + std::to_string(i) +
                             "]: " + std::to_string(nozzle.cut) + " of " +
                             std::to_string(nozzle.cut + nozzle.open.size()) +
                             " nozzle points are in or within half a spacing of " + nozzle.cutBy +
                             ": they are left out, so the nozzle injects across its open part "
                             "only");
    }
}

/// "dimension" must be this app's: a 3D scene is run with fluid_sim_3d.
template <int Dim>
void checkDimension(const At& root) {
    const int dim = int(root["dimension"].integer(2, 3));
    if (dim != Dim)
        throw sceneError(root.file, "dimension",
                         std::to_string(Dim) + " for " + (Dim == 2 ? "fluid_sim" : "fluid_sim_3d"),
                         std::to_string(dim),
                         "this is a " + std::to_string(dim) + "D scene: run it with " +
                             (dim == 2 ? "fluid_sim" : "fluid_sim_3d"));
}

template <int Dim>
void readDomain(const At& domain, Scene<Dim>& s) {
    DomainInput<Dim> d;
    readKeys(domain, domainKeys<Dim>(), d);
    s.domainMin = d.min;
    s.domainMax = d.max;
}

template <int Dim>
void readParticles(const At& p, Scene<Dim>& s) {
    readKeys<ParticleSpec>(p, particleKeys(), s);
}

template <int Dim>
void readTime(const At& t, Scene<Dim>& s) {
    readKeys<TimeSpec>(t, timeKeys(), s);
}

template <int Dim>
void readGravity(const At& g, Scene<Dim>& s) {
    s.gravity = readField<Dim>(
        g, "t",
        "gravity is uniform in space, a function of the time t only (a force that depends on "
        "the position is a plugin's term)");
}

template <int Dim>
void readNumerics(const At& nu, Scene<Dim>& s) {
    readKeys<NumericsSpec>(nu, numericsKeys(), s);
}

template <int Dim>
void readMaterials(const At& mats, Scene<Dim>& s) {
    if (!mats.v.is_object() || mats.v.empty())
        mats.fail("an object of named materials, e.g. {\"water\": {\"density\": 1000}}");
    for (const auto& [name, value] : mats.v.items())
        s.materials[name] = readMaterial(mats[name], name);
}

template <int Dim>
FluidBlock<Dim> readFluidBlock(const At& b, const std::map<std::string, MaterialSpec>& materials) {
    FluidInput<Dim> blk;
    blk.materials = &materials;
    blk.at = &b;
    readPlacedShape<Dim>(b, fluidKeys<Dim>(), blk);
    readKeyValues(b, fluidKeys<Dim>(), blk);
    return blk;
}

template <int Dim>
void readFluids(const At& f, Scene<Dim>& s) {
    if (!f.v.is_array()) f.fail("an array of fluid blocks");
    for (std::size_t i = 0; i < f.v.size(); ++i)
        s.fluids.push_back(readFluidBlock<Dim>(f[i], s.materials));
}

template <int Dim>
Body<Dim> readBody(const At& b, const std::map<std::string, MaterialSpec>& materials) {
    BodyInput<Dim> body;
    body.materials = &materials;
    readPlacedShape<Dim>(b, bodyKeys<Dim>(), body);
    readKeyValues(b, bodyKeys<Dim>(), body);
    return body;
}

template <int Dim>
void readBodies(const At& f, Scene<Dim>& s) {
    if (!f.v.is_array()) f.fail("an array of solid bodies");
    for (std::size_t i = 0; i < f.v.size(); ++i)
        s.bodies.push_back(readBody<Dim>(f[i], s.materials));
}

/// A wall inside the domain: a shape with a box side's wall keys (slip, velocity, thermal).
template <int Dim>
Wall<Dim> readWall(const At& w) {
    Wall<Dim> wall;
    readPlacedShape<Dim>(w, interiorWallKeys<Dim>(), wall);
    wall.boundary = readWallKeys<Dim>(w);
    return wall;
}

template <int Dim>
void readWalls(const At& f, Scene<Dim>& s) {
    if (!f.v.is_array()) f.fail("an array of walls");
    for (std::size_t i = 0; i < f.v.size(); ++i) s.walls.push_back(readWall<Dim>(f[i]));
}

/// Emitter `i` of the list (named "emitter<i>" unless it has a name).
template <int Dim>
Emitter<Dim> readEmitter(const At& e, std::size_t i,
                         const std::map<std::string, MaterialSpec>& materials) {
    EmitterInput<Dim> em;
    em.materials = &materials;
    em.name = "emitter" + std::to_string(i);
    readKeys(e, emitterKeys<Dim>(), em);
    if (!(em.end > em.start)) e["end"].fail("an end time after the start time");
    return em;
}

template <int Dim>
void readEmitters(const At& f, Scene<Dim>& s) {
    if (!f.v.is_array()) f.fail("an array of emitters");
    for (std::size_t i = 0; i < f.v.size(); ++i)
        s.emitters.push_back(readEmitter<Dim>(f[i], i, s.materials));
}

/// A probe; `names` holds those of the probes before it (a name must be unique).
template <int Dim>
Probe<Dim> readProbe(const At& e, std::set<std::string>& names) {
    ProbeInput<Dim> pr;
    pr.names = &names;
    pr.at = &e;
    readKeys(e, probeKeys<Dim>(), pr);
    pr.checkOneKind();
    // By default a body's, wall's or side's one field, a point's all but density.
    if (!e.has("fields"))
        pr.fields = pr.body >= 0 || pr.wall >= 0 ? std::vector<std::string>{"force"}
                    : pr.side >= 0
                        ? std::vector<std::string>{"flow_rate"}
                        : std::vector<std::string>{"velocity", "pressure", "temperature"};
    return pr;
}

template <int Dim>
void readProbes(const At& f, Scene<Dim>& s) {
    if (!f.v.is_array()) f.fail("an array of probes");
    std::set<std::string> names;
    for (std::size_t i = 0; i < f.v.size(); ++i) s.probes.push_back(readProbe<Dim>(f[i], names));
}

template <int Dim>
void readPhysics(const At& ph, Scene<Dim>& s) {
    readKeys(ph, physicsKeys(), s.physics);
}

}  // namespace

template <int Dim>
Scene<Dim> readScene(const SceneDocument& doc) {
    const At root{doc.json(), doc.file(), ""};
    root.object({"dimension", "name", "description", "domain", "boundaries", "particles", "time",
                 "gravity", "materials", "fluids", "bodies", "walls", "emitters", "output",
                 "probes", "physics", "plugins", "numerics"},
                {"dimension", "domain", "boundaries", "particles", "time", "materials"});
    Scene<Dim> s;
    s.file = doc.file();
    checkDimension<Dim>(root);
    if (root.has("name")) s.name = root["name"].string();
    if (root.has("description")) root["description"].string();
    readDomain(root["domain"], s);
    readSides(root["boundaries"], s);
    readParticles(root["particles"], s);
    readTime(root["time"], s);
    if (root.has("gravity")) readGravity(root["gravity"], s);
    if (root.has("numerics")) readNumerics(root["numerics"], s);
    readMaterials(root["materials"], s);
    if (root.has("fluids")) readFluids(root["fluids"], s);
    if (root.has("bodies")) readBodies(root["bodies"], s);
    if (root.has("walls")) readWalls(root["walls"], s);
    if (root.has("emitters")) readEmitters(root["emitters"], s);
    if (root.has("output")) readKeys(root["output"], outputKeys(), s.output);
    if (root.has("probes")) readProbes(root["probes"], s);
    if (root.has("physics")) readPhysics(root["physics"], s);
    warnShapeScales(s);
    checkSceneGeometry(s);
    warnCutNozzles(s);
    warnSidewaysOpenSides(s);
    return s;
}

template Scene<2> readScene<2>(const SceneDocument&);
template Scene<3> readScene<3>(const SceneDocument&);

}  // namespace num::app
