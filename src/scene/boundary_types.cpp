// The table of boundary types and their readers (format: docs/scenes.md, "boundaries").
#include "scene/boundary_types.hpp"

#include <algorithm>

#include "sph/boundary/inlet_outlet_boundary.hpp"
#include "sph/boundary/open_boundary.hpp"
#include "sph/boundary/periodic_boundary.hpp"
#include "sph/boundary/wall_boundary.hpp"

namespace num::app {

using detail::At;

namespace {

template <int Dim>
using SideKeys = KeyTable<SideInput<Dim>>;

const KeyTable<ThermalInput> kThermalKeys{
    {.name = "temperature",
     .type = KeyType::NUMBER,
     .field = &ThermalInput::temperature,
     .fallback = 0.0,
     .unit = "degC",
     .lo = -273.15,
     .hi = 1e4,
     .meaning = "held fixed",
     .shownDefault = "this or `heat_flux`"},
    {.name = "heat_flux",
     .type = KeyType::NUMBER,
     .field = &ThermalInput::heatFlux,
     .fallback = 0.0,
     .unit = "W/m^2",
     .lo = -1e9,
     .hi = 1e9,
     .meaning = "into the fluid, delivered by the wall layer next to it",
     .shownDefault = "this or `temperature`"},
};

/// A wall's "thermal": exactly one of its keys; adiabatic without it.
template <int Dim>
void readWallThermal(const At& t, SideInput<Dim>& in) {
    t.object(keyNames(kThermalKeys));
    if (t.has("temperature") == t.has("heat_flux"))
        t.fail("an object with exactly one of \"temperature\" [degC] or \"heat_flux\" [W/m^2]");
    ThermalInput values;
    readKeyValues(t, kThermalKeys, values);
    const bool fixed = t.has("temperature");
    in.thermal.condition =
        fixed ? sph::ThermalCondition::FIXED_TEMPERATURE : sph::ThermalCondition::HEAT_FLUX;
    in.thermal.value = fixed ? values.temperature : values.heatFlux;
}

template <int Dim>
void readWallVelocity(const At& a, SideInput<Dim>& in) {
    in.velocity = detail::readVec<Dim>(a, "m/s");
}

/// The keys of a wall: a side's, or an interior wall's beside its shape.
template <int Dim>
const SideKeys<Dim>& wallKeys() {
    static const SideKeys<Dim> keys{
        {.name = "slip",
         .type = KeyType::FLAG,
         .field = &SideInput<Dim>::slip,
         .fallback = false,
         .meaning = "free-slip instead of no-slip"},
        {.name = "velocity",
         .type = KeyType::CUSTOM,
         .unit = "m/s",
         .meaning = "tangential velocity of a moving wall (Couette, cavity lid)",
         .read = readWallVelocity<Dim>,
         .shownDefault = "zero"},
        {.name = "thermal",
         .type = KeyType::CUSTOM,
         .meaning = "exactly one of `temperature` and `heat_flux` (a wall's `thermal`, under "
                    "[`wall` sides](#wall-sides))",
         .read = readWallThermal<Dim>,
         .shownDefault = "absent: adiabatic"},
    };
    return keys;
}

template <int Dim>
SideBoundary<Dim> readWall(const At& b) {
    return readWallKeys<Dim>(b);
}

/// The variables of an inlet's or outlet's values: the position on the side and the time.
template <int Dim>
const char* sideVariables() {
    return Dim == 2 ? "xyt" : "xyzt";
}
const char* const kSideMeaning = "a function of the position (x, y, z in 3D) and the time t";

/// An expression as a function of the position and the time.
template <int Dim>
sph::PointFunction<Dim> pointFunction(const Expression& e) {
    return [e](const sph::Vector<Dim>& x, sph::Float t) {
        return e(x[0], x[1], Dim > 2 ? x[Dim - 1] : 0.0, t);
    };
}

/// "from" and "to": the corners of the part of the side an inlet or outlet opens (points on
/// the side, checked with the domain: checkFlowSides); without them, the whole side.
template <int Dim>
void checkOpening(const SideInput<Dim>& in) {
    if (in.at->has("from") != in.at->has("to"))
        in.at->fail("both \"from\" and \"to\" (the corners of the opening) or neither");
}

template <int Dim>
void readFrom(const At& a, SideInput<Dim>& in) {
    checkOpening(in);
    in.flow.openFrom = detail::readVec<Dim>(a, "m");
}

template <int Dim>
void readTo(const At& a, SideInput<Dim>& in) {
    checkOpening(in);
    in.flow.openTo = detail::readVec<Dim>(a, "m");
}

/// An inlet's "velocity": numbers or expressions of x, y, z and t [m/s].
template <int Dim>
void readInletVelocity(const At& a, SideInput<Dim>& in) {
    a.array(Dim, "numbers or expressions [m/s] (one per axis of the " + std::to_string(Dim) +
                     "D scene)");
    std::array<sph::PointFunction<Dim>, Dim> component;
    for (int k = 0; k < Dim; ++k)
        component[k] =
            pointFunction<Dim>(a[std::size_t(k)].expression(sideVariables<Dim>(), kSideMeaning));
    in.flow.velocity = [component](const sph::Vector<Dim>& x, sph::Float t) {
        sph::Vector<Dim> v;
        for (int k = 0; k < Dim; ++k) v[k] = component[k](x, t);
        return v;
    };
}

/// An inlet's "temperature": a number or expression [degC] (held, if constant).
template <int Dim>
void readInletTemperature(const At& a, SideInput<Dim>& in) {
    const Expression T = a.expression(sideVariables<Dim>(), kSideMeaning);
    in.flow.temperature = pointFunction<Dim>(T);
    if (T.isConstant()) in.held = T(0, 0, 0, 0);
}

/// An outlet's "pressure": a number or expression of x, y, z and t [Pa].
template <int Dim>
void readOutletPressure(const At& a, SideInput<Dim>& in) {
    in.flow.pressure = pointFunction<Dim>(a.expression(sideVariables<Dim>(), kSideMeaning));
}

/// The keys of an inlet (`inlet`) or an outlet: theirs, then the opening's.
template <int Dim>
SideKeys<Dim> flowKeys(bool inlet) {
    SideKeys<Dim> keys;
    if (inlet)
        keys.push_back({.name = "velocity",
                        .type = KeyType::CUSTOM,
                        .unit = "m/s",
                        .meaning = "the inflow velocity, numbers or [expressions](#expressions) "
                                   "of x, y, z and `t`, pointing into the domain on the whole "
                                   "opening at all times (checked at its lattice points at 21 "
                                   "times)",
                        .read = readInletVelocity<Dim>,
                        .shownDefault = "required"});
    else
        keys.push_back({.name = "pressure",
                        .type = KeyType::CUSTOM,
                        .unit = "Pa",
                        .meaning = "the pressure held there, a number or expression of x, y, z "
                                   "and t (hydrostatic: `\"9810*(0.5-y)\"`)",
                        .read = readOutletPressure<Dim>,
                        .shownDefault = "`physics.background_pressure` (0)"});
    keys.push_back({.name = "from",
                    .type = KeyType::CUSTOM,
                    .unit = "m",
                    .meaning = "with `to`, the corners of the part of the side that opens (at "
                               "least two spacings wide); the rest is a wall",
                    .read = readFrom<Dim>,
                    .shownDefault = "the whole side"});
    keys.push_back({.name = "to",
                    .type = KeyType::CUSTOM,
                    .unit = "m",
                    .meaning = "the opening's other corner",
                    .read = readTo<Dim>,
                    .shownDefault = "the whole side"});
    if (inlet)
        keys.push_back({.name = "temperature",
                        .type = KeyType::CUSTOM,
                        .unit = "degC",
                        .meaning = "the inflow temperature, a number or expression of x, y, z "
                                   "and t",
                        .read = readInletTemperature<Dim>,
                        .shownDefault = "the fluid's reference temperature"});
    return keys;
}

/// The type of `name`, of the table.
template <int Dim>
const BoundaryType<Dim>& boundaryType(const std::string& name) {
    const auto& types = boundaryTypes<Dim>();
    return *std::find_if(types.begin(), types.end(), [&](const auto& t) { return t.name == name; });
}

/// An inlet ("velocity" required) or an outlet, read by its type's keys.
template <int Dim, sph::ParticleKind Kind>
SideBoundary<Dim> readFlowSide(const At& b) {
    const bool inlet = Kind == sph::ParticleKind::INLET;
    if (inlet && !b.has("velocity"))
        b.fail("an inlet with \"velocity\": numbers or expressions [m/s] (one per axis)");
    SideInput<Dim> in;
    in.at = &b;
    in.flow.kind = Kind;
    readKeyValues(b, boundaryType<Dim>(inlet ? "inlet" : "outlet").keys, in);
    return std::make_shared<sph::InletOutletBoundary<Dim>>(in.flow, in.held);
}

/// The reader of a type without keys of its own.
template <int Dim, class Module>
SideBoundary<Dim> keyless(const At&) {
    return std::make_shared<Module>();
}

template <int Dim>
bool hasKey(const SideKeys<Dim>& keys, const std::string& key) {
    return std::any_of(keys.begin(), keys.end(), [&](const auto& k) { return k.name == key; });
}

/// Refuses a key of another type on a side of type `name`, naming the types it applies to.
template <int Dim>
void refuseOtherTypesKeys(const At& b, const std::string& name,
                          const std::vector<std::string>& keys) {
    const BoundaryType<Dim>& type = boundaryType<Dim>(name);
    for (const std::string& key : keys) {
        if (key == "type" || !b.has(key) || hasKey<Dim>(type.keys, key)) continue;
        std::string owners;
        for (const BoundaryType<Dim>& t : boundaryTypes<Dim>())
            if (hasKey<Dim>(t.keys, key)) owners += (owners.empty() ? "" : ", ") + t.name;
        const char* article =
            std::string("aeiou").find(name[0]) != std::string::npos ? "an " : "a ";
        b[key].fail("no '" + key + "' on " + article + name + " side (it applies to " + owners +
                    " sides only)");
    }
}

}  // namespace

const KeyTable<ThermalInput>& wallThermalKeys() { return kThermalKeys; }

template <int Dim>
std::shared_ptr<const sph::WallBoundary<Dim>> readWallKeys(const At& b) {
    SideInput<Dim> in;
    readKeyValues(b, wallKeys<Dim>(), in);
    return std::make_shared<sph::WallBoundary<Dim>>(
        in.velocity, in.slip ? sph::WallSlip::FREE_SLIP : sph::WallSlip::NO_SLIP, in.thermal);
}

template <int Dim>
const SideKeys<Dim>& interiorWallKeys() {
    static const SideKeys<Dim> keys = [] {
        SideKeys<Dim> all{{.name = "shape",
                           .type = KeyType::CUSTOM,
                           .meaning = "any [shape](#shapes) with its keys: the solid of the wall",
                           .required = true,
                           .read = readBefore<SideInput<Dim>>}};
        all.insert(all.end(), wallKeys<Dim>().begin(), wallKeys<Dim>().end());
        return all;
    }();
    return keys;
}

template <int Dim>
const std::vector<BoundaryType<Dim>>& boundaryTypes() {
    static const std::vector<BoundaryType<Dim>> types = {
        {"wall", wallKeys<Dim>(), &readWall<Dim>},
        {"periodic", {}, &keyless<Dim, sph::PeriodicBoundary<Dim>>},
        {"open", {}, &keyless<Dim, sph::OpenBoundary<Dim>>},
        {"inlet", flowKeys<Dim>(true), &readFlowSide<Dim, sph::ParticleKind::INLET>},
        {"outlet", flowKeys<Dim>(false), &readFlowSide<Dim, sph::ParticleKind::OUTLET>},
    };
    return types;
}

template <int Dim>
std::string boundaryTypeChoices() {
    const auto& types = boundaryTypes<Dim>();
    std::string list = "{\"type\": \"" + types.front().name + "\"}";
    for (std::size_t k = 1; k < types.size(); ++k)
        list += (k + 1 == types.size() ? " or \"" : ", \"") + types[k].name + "\"";
    return list;
}

template <int Dim>
SideBoundary<Dim> readSideBoundary(const At& b) {
    std::vector<std::string> names, keys{"type"};
    for (const BoundaryType<Dim>& t : boundaryTypes<Dim>()) {
        names.push_back(t.name);
        for (const auto& k : t.keys)
            if (std::find(keys.begin(), keys.end(), k.name) == keys.end()) keys.push_back(k.name);
    }
    b.object(keys, {"type"});
    const std::string name = b["type"].choice(names);
    refuseOtherTypesKeys<Dim>(b, name, keys);
    return boundaryType<Dim>(name).read(b);
}

template std::shared_ptr<const sph::WallBoundary<2>> readWallKeys<2>(const At&);
template std::shared_ptr<const sph::WallBoundary<3>> readWallKeys<3>(const At&);
template const KeyTable<SideInput<2>>& interiorWallKeys<2>();
template const KeyTable<SideInput<3>>& interiorWallKeys<3>();
template const std::vector<BoundaryType<2>>& boundaryTypes<2>();
template const std::vector<BoundaryType<3>>& boundaryTypes<3>();
template SideBoundary<2> readSideBoundary<2>(const At&);
template SideBoundary<3> readSideBoundary<3>(const At&);
template std::string boundaryTypeChoices<2>();
template std::string boundaryTypeChoices<3>();

}  // namespace num::app
