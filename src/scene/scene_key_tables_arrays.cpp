// The key tables of the elements of the scene's arrays `fluids`, `bodies`, `emitters` and `probes`
// (scene/scene_keys.hpp): one entry per key, with the readers of the keys that are more than a
// value (vectors, checked names, indices). What involves several keys at once is checked by the
// reader after readKeys (scene_reader.cpp).
#include <algorithm>
#include <cctype>

#include "scene/body_motion_reader.hpp"
#include "scene/scene_keys.hpp"
#include "sph/defaults.hpp"

namespace num::app {

using detail::At;
using detail::readField;
using detail::readVec;
namespace d = sph::defaults;

std::string materialName(const At& a, const std::map<std::string, MaterialSpec>& materials) {
    const std::string name = a.string();
    if (materials.count(name)) return name;
    std::vector<std::string> names;
    std::string list;
    for (const auto& [n, m] : materials) names.push_back(n), list += (list.empty() ? "" : ", ") + n;
    const std::string guess = detail::closest(name, names);
    a.fail("the name of a material defined under \"materials\" (" + list + ")",
           guess.empty() ? "" : "did you mean \"" + guess + "\"?");
}

namespace {

/// The variables of an initial field: the position's coordinates (x, y in 2D; x, y, z in 3D)
/// and t, which is 0 when the field is set.
template <int Dim>
const char* initialVariables() {
    return Dim == 2 ? "xyt" : "xyzt";
}
template <int Dim>
std::string initialMeaning() {
    return Dim == 2 ? "a 2D scene has the coordinates x and y only" : "";
}

template <int Dim>
void readFluidMaterial(const At& a, FluidInput<Dim>& b) {
    b.material = materialName(a, *b.materials);
}

template <int Dim>
void readFluidTemperature(const At& a, FluidInput<Dim>& b) {
    b.temperature = a.expression(initialVariables<Dim>(), initialMeaning<Dim>());
}

template <int Dim>
void readFluidPressure(const At& a, FluidInput<Dim>& b) {
    b.pressure = a.expression(initialVariables<Dim>(), initialMeaning<Dim>());
}

/// Read after the pressure, as the scenes before the table were.
template <int Dim>
void readFluidVelocity(const At& a, FluidInput<Dim>& b) {
    if (b.at->has("pressure")) readFluidPressure((*b.at)["pressure"], b);
    b.velocity = readField<Dim>(a, initialVariables<Dim>(), initialMeaning<Dim>());
}

template <int Dim>
const KeyTable<FluidInput<Dim>> kFluidKeys{
    {.name = "material",
     .type = KeyType::CUSTOM,
     .meaning = "a name from `materials`",
     .required = true,
     .read = readFluidMaterial<Dim>},
    {.name = "shape",
     .type = KeyType::CUSTOM,
     .meaning = "`box` (`min`, `max`), `circle` (2D) or `sphere` (3D) (`center`, `radius`), or "
                "any [shape](#shapes) with its keys",
     .required = true,
     .read = readBefore<FluidInput<Dim>>},
    {.name = "temperature",
     .type = KeyType::CUSTOM,
     .unit = "degC",
     .meaning = "number or expression in x, y, z",
     .read = readFluidTemperature<Dim>,
     .shownDefault = "20"},
    {.name = "velocity",
     .type = KeyType::CUSTOM,
     .unit = "m/s",
     .meaning = "vector of numbers or expressions",
     .read = readFluidVelocity<Dim>,
     .shownDefault = "zero"},
    {.name = "pressure",
     .type = KeyType::CUSTOM,
     .unit = "Pa",
     .meaning = "number or expression; the density follows from the equation of state",
     .read = readFluidPressure<Dim>,
     .shownDefault = "0"},
};

template <int Dim>
void readBodyMaterial(const At& a, BodyInput<Dim>& b) {
    b.material = materialName(a, *b.materials);
}

template <int Dim>
void readBodyMotionKey(const At& a, BodyInput<Dim>& b) {
    b.motion = readBodyMotion<Dim>(a);
}

template <int Dim>
const KeyTable<BodyInput<Dim>> kBodyKeys{
    {.name = "shape",
     .type = KeyType::CUSTOM,
     .meaning = "`circle`/`sphere` (`center`, `radius`), `box` (`min`, `max`), or any "
                "[shape](#shapes) with its keys",
     .required = true,
     .read = readBefore<BodyInput<Dim>>},
    {.name = "temperature",
     .type = KeyType::NUMBER,
     .field = &BodyInput<Dim>::temperature,
     .fallback = d::temperature,
     .unit = "degC",
     .lo = -273.15,
     .hi = 1e4,
     .meaning = "initial temperature; held fixed unless `material` is given"},
    {.name = "material",
     .type = KeyType::CUSTOM,
     .meaning = "a conducting body of that material (its temperature evolves)",
     .read = readBodyMaterial<Dim>,
     .shownDefault = "absent"},
    {.name = "name",
     .type = KeyType::TEXT,
     .field = &BodyInput<Dim>::name,
     .fallback = std::string(),
     .meaning = "its name in `bodies.csv`, messages and Python",
     .shownDefault = "`bodies[i]`"},
    {.name = "motion",
     .type = KeyType::CUSTOM,
     .meaning = "`\"fixed\"`, or an object with `type` `fixed`, `free` or `prescribed`",
     .read = readBodyMotionKey<Dim>,
     .shownDefault = "`\"fixed\"`"},
};

template <int Dim>
void readEmitterName(const At& a, EmitterInput<Dim>& e) {
    e.name = a.string();
}

template <int Dim>
void readEmitterPosition(const At& a, EmitterInput<Dim>& e) {
    e.position = readVec<Dim>(a, "m");
}

/// Any non-zero vector, kept normalised.
template <int Dim>
void readEmitterDirection(const At& a, EmitterInput<Dim>& e) {
    e.direction = readVec<Dim>(a, "-");
    if (!(norm(e.direction) > 0)) a.fail("a non-zero direction vector");
    e.direction = e.direction / norm(e.direction);
}

template <int Dim>
void readEmitterMaterial(const At& a, EmitterInput<Dim>& e) {
    e.material = materialName(a, *e.materials);
}

template <int Dim>
const KeyTable<EmitterInput<Dim>> kEmitterKeys{
    {.name = "name",
     .type = KeyType::CUSTOM,
     .meaning = "label; N is the emitter's index in `emitters` (from 0)",
     .read = readEmitterName<Dim>,
     .shownDefault = "`emitterN`"},
    {.name = "position",
     .type = KeyType::CUSTOM,
     .unit = "m",
     .meaning = "nozzle centre, inside the domain",
     .required = true,
     .read = readEmitterPosition<Dim>},
    {.name = "direction",
     .type = KeyType::CUSTOM,
     .meaning = "non-zero vector (normalised)",
     .required = true,
     .read = readEmitterDirection<Dim>},
    {.name = "speed",
     .type = KeyType::NUMBER,
     .field = &EmitterInput<Dim>::speed,
     .fallback = d::emitterSpeed,
     .unit = "m/s",
     .lo = 0,
     .hi = 1e4,
     .loOpen = true,
     .required = true},
    {.name = "radius",
     .type = KeyType::NUMBER,
     .field = &EmitterInput<Dim>::radius,
     .fallback = d::emitterRadius,
     .unit = "m",
     .lo = 0,
     .loOpen = true,
     .meaning = "nozzle radius, ≥ half the spacing and ≤ half the domain's largest extent",
     .required = true},
    {.name = "material",
     .type = KeyType::CUSTOM,
     .meaning = "a name from `materials`",
     .required = true,
     .read = readEmitterMaterial<Dim>},
    {.name = "temperature",
     .type = KeyType::NUMBER,
     .field = &EmitterInput<Dim>::temperature,
     .fallback = d::temperature,
     .unit = "degC",
     .lo = -273.15,
     .hi = 1e4,
     .meaning = "of the emitted water"},
    {.name = "start",
     .type = KeyType::NUMBER,
     .field = &EmitterInput<Dim>::start,
     .fallback = 0.0,
     .unit = "s",
     .lo = 0,
     .meaning = "when emission starts"},
    {.name = "end",
     .type = KeyType::NUMBER,
     .field = &EmitterInput<Dim>::end,
     .fallback = 1e300,
     .unit = "s",
     .lo = 0,
     .meaning = "when it stops, `end > start`",
     .shownDefault = "forever"},
};

/// Column names of probes.csv: 1 to 64 letters, digits, '_' and '-' only (no separator, quote,
/// line break or control character can reach the file), each name once.
template <int Dim>
void readProbeName(const At& a, ProbeInput<Dim>& p) {
    p.name = a.string();
    const bool plain = !p.name.empty() && p.name.size() <= 64 &&
                       std::all_of(p.name.begin(), p.name.end(), [](char c) {
                           return std::isalnum((unsigned char)c) || c == '_' || c == '-';
                       });
    if (!plain) a.fail("a name of 1 to 64 letters, digits, '_' or '-'");
    if (!p.names->insert(p.name).second) a.fail("a name no other probe has");
}

template <int Dim>
void readProbePoint(const At& a, ProbeInput<Dim>& p) {
    p.checkOneKind();
    p.point = readVec<Dim>(a, "m");
}

template <int Dim>
void readProbeBody(const At& a, ProbeInput<Dim>& p) {
    p.checkOneKind();
    p.body = int(a.integer(0, 1 << 30));
}

template <int Dim>
void readProbeWall(const At& a, ProbeInput<Dim>& p) {
    p.checkOneKind();
    p.wall = int(a.integer(0, 1 << 30));
}

/// A side's name ("x_min", ...) as 2 axis + high.
template <int Dim>
void readProbeSide(const At& a, ProbeInput<Dim>& p) {
    p.checkOneKind();
    std::vector<std::string> names;
    for (int k = 0; k < 2 * Dim; ++k) names.push_back(sideName(k / 2, k % 2));
    const std::string name = a.choice(names);
    p.side = int(std::find(names.begin(), names.end(), name) - names.begin());
}

/// The fields the probe's kind may record (read after its point, body, wall or side).
template <int Dim>
void readProbeFields(const At& fl, ProbeInput<Dim>& p) {
    p.checkOneKind();
    const std::vector<std::string> choices =
        p.body >= 0 || p.wall >= 0 ? std::vector<std::string>{"force"}
        : p.side >= 0              ? std::vector<std::string>{"flow_rate"}
                      : std::vector<std::string>{"velocity", "density", "pressure", "temperature"};
    if (!fl.v.is_array() || fl.v.empty()) fl.fail("a non-empty array of field names");
    for (std::size_t k = 0; k < fl.v.size(); ++k) p.fields.push_back(fl[k].choice(choices));
}

constexpr const char* kOneKind = "one of `point`, `body`, `wall`, `side`";

template <int Dim>
const KeyTable<ProbeInput<Dim>> kProbeKeys{
    {.name = "name",
     .type = KeyType::CUSTOM,
     .meaning = "unique; 1 to 64 letters, digits, `_` or `-` (a column name of `probes.csv`)",
     .required = true,
     .read = readProbeName<Dim>},
    {.name = "point",
     .type = KeyType::CUSTOM,
     .unit = "m",
     .meaning = "a point inside the domain: field values there",
     .read = readProbePoint<Dim>,
     .shownDefault = kOneKind},
    {.name = "body",
     .type = KeyType::CUSTOM,
     .meaning = "index of a body in `bodies` (from 0): the fluid's force on it",
     .read = readProbeBody<Dim>,
     .shownDefault = kOneKind},
    {.name = "wall",
     .type = KeyType::CUSTOM,
     .meaning = "index of a wall in `walls` (from 0): the fluid's force on it",
     .read = readProbeWall<Dim>,
     .shownDefault = kOneKind},
    {.name = "side",
     .type = KeyType::CUSTOM,
     .meaning = "a side of the box (`\"x_min\"`, ...): the flow rate through it",
     .read = readProbeSide<Dim>,
     .shownDefault = kOneKind},
    {.name = "fields",
     .type = KeyType::CUSTOM,
     .meaning = "at a point any of `velocity`, `density`, `pressure`, `temperature`; on a body "
                "or wall `force`; on a side `flow_rate`",
     .read = readProbeFields<Dim>,
     .shownDefault = "`[\"velocity\", \"pressure\", \"temperature\"]`; body or wall "
                     "`[\"force\"]`; side `[\"flow_rate\"]`"},
};

}  // namespace

template <int Dim>
const KeyTable<FluidInput<Dim>>& fluidKeys() {
    return kFluidKeys<Dim>;
}

template <int Dim>
const KeyTable<BodyInput<Dim>>& bodyKeys() {
    return kBodyKeys<Dim>;
}

template <int Dim>
const KeyTable<EmitterInput<Dim>>& emitterKeys() {
    return kEmitterKeys<Dim>;
}

template <int Dim>
const KeyTable<ProbeInput<Dim>>& probeKeys() {
    return kProbeKeys<Dim>;
}

template const KeyTable<FluidInput<2>>& fluidKeys<2>();
template const KeyTable<FluidInput<3>>& fluidKeys<3>();
template const KeyTable<BodyInput<2>>& bodyKeys<2>();
template const KeyTable<BodyInput<3>>& bodyKeys<3>();
template const KeyTable<EmitterInput<2>>& emitterKeys<2>();
template const KeyTable<EmitterInput<3>>& emitterKeys<3>();
template const KeyTable<ProbeInput<2>>& probeKeys<2>();
template const KeyTable<ProbeInput<3>>& probeKeys<3>();

}  // namespace num::app
