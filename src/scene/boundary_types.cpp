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

/// A wall's "thermal": exactly one of temperature [degC] or heat_flux [W/m^2]; adiabatic
/// without it.
sph::WallThermal readWallThermal(const At& b) {
    sph::WallThermal thermal;
    if (!b.has("thermal")) return thermal;
    const At t = b["thermal"];
    t.object({"temperature", "heat_flux"});
    if (t.has("temperature") == t.has("heat_flux"))
        t.fail("an object with exactly one of \"temperature\" [degC] or \"heat_flux\" [W/m^2]");
    thermal.condition = t.has("temperature") ? sph::ThermalCondition::FIXED_TEMPERATURE
                                             : sph::ThermalCondition::HEAT_FLUX;
    thermal.value = t.has("temperature") ? t["temperature"].number(-273.15, 1e4, false, "degC")
                                         : t["heat_flux"].number(-1e9, 1e9, false, "W/m^2");
    return thermal;
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
void readOpening(const At& b, sph::FlowSide<Dim>& spec) {
    if (b.has("from") != b.has("to"))
        b.fail("both \"from\" and \"to\" (the corners of the opening) or neither");
    if (!b.has("from")) return;
    spec.openFrom = detail::readVec<Dim>(b["from"], "m");
    spec.openTo = detail::readVec<Dim>(b["to"], "m");
}

/// An inlet: "velocity" (numbers or expressions of x, y, z and t [m/s]), optionally
/// "temperature" (a number or expression [degC]; without it, the fluid's).
template <int Dim>
SideBoundary<Dim> readInlet(const At& b) {
    if (!b.has("velocity"))
        b.fail("an inlet with \"velocity\": numbers or expressions [m/s] (one per axis)");
    const At a = b["velocity"];
    a.array(Dim, "numbers or expressions [m/s] (one per axis of the " + std::to_string(Dim) +
                     "D scene)");
    std::array<sph::PointFunction<Dim>, Dim> component;
    for (int k = 0; k < Dim; ++k)
        component[k] =
            pointFunction<Dim>(a[std::size_t(k)].expression(sideVariables<Dim>(), kSideMeaning));
    sph::FlowSide<Dim> spec;
    spec.kind = sph::ParticleKind::INLET;
    spec.velocity = [component](const sph::Vector<Dim>& x, sph::Float t) {
        sph::Vector<Dim> v;
        for (int k = 0; k < Dim; ++k) v[k] = component[k](x, t);
        return v;
    };
    readOpening(b, spec);
    std::optional<double> held;
    if (b.has("temperature")) {
        const Expression T = b["temperature"].expression(sideVariables<Dim>(), kSideMeaning);
        spec.temperature = pointFunction<Dim>(T);
        if (T.isConstant()) held = T(0, 0, 0, 0);
    }
    return std::make_shared<sph::InletOutletBoundary<Dim>>(spec, held);
}

/// An outlet: "pressure" (a number or expression of x, y, z and t [Pa]; without it, the
/// background pressure: makeFlowBoundaries).
template <int Dim>
SideBoundary<Dim> readOutlet(const At& b) {
    sph::FlowSide<Dim> spec;
    spec.kind = sph::ParticleKind::OUTLET;
    if (b.has("pressure"))
        spec.pressure =
            pointFunction<Dim>(b["pressure"].expression(sideVariables<Dim>(), kSideMeaning));
    readOpening(b, spec);
    return std::make_shared<sph::InletOutletBoundary<Dim>>(spec, std::nullopt);
}

/// The reader of a type without keys of its own.
template <int Dim, class Module>
SideBoundary<Dim> keyless(const At&) {
    return std::make_shared<Module>();
}

}  // namespace

template <int Dim>
std::shared_ptr<const sph::WallBoundary<Dim>> readWallKeys(const At& b) {
    const sph::WallSlip slip =
        b.boolean("slip", false) ? sph::WallSlip::FREE_SLIP : sph::WallSlip::NO_SLIP;
    sph::Vector<Dim> velocity{};
    if (b.has("velocity")) velocity = detail::readVec<Dim>(b["velocity"], "m/s");
    return std::make_shared<sph::WallBoundary<Dim>>(velocity, slip, readWallThermal(b));
}

template <int Dim>
const std::vector<BoundaryType<Dim>>& boundaryTypes() {
    static const std::vector<BoundaryType<Dim>> types = {
        {"wall", {"slip", "velocity", "thermal"}, &readWall<Dim>},
        {"periodic", {}, &keyless<Dim, sph::PeriodicBoundary<Dim>>},
        {"open", {}, &keyless<Dim, sph::OpenBoundary<Dim>>},
        {"inlet", {"velocity", "temperature", "from", "to"}, &readInlet<Dim>},
        {"outlet", {"pressure", "from", "to"}, &readOutlet<Dim>},
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
    const auto& types = boundaryTypes<Dim>();
    std::vector<std::string> names, keys{"type"};
    for (const BoundaryType<Dim>& t : types) {
        names.push_back(t.name);
        for (const std::string& key : t.keys)
            if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
    }
    b.object(keys, {"type"});
    const std::string name = b["type"].choice(names);
    const BoundaryType<Dim>& type =
        *std::find_if(types.begin(), types.end(), [&](const auto& t) { return t.name == name; });
    for (const std::string& key : keys) {
        if (key == "type" || !b.has(key) ||
            std::find(type.keys.begin(), type.keys.end(), key) != type.keys.end())
            continue;
        std::string owners;
        for (const BoundaryType<Dim>& t : types)
            if (std::find(t.keys.begin(), t.keys.end(), key) != t.keys.end())
                owners += (owners.empty() ? "" : ", ") + t.name;
        const char* article =
            std::string("aeiou").find(name[0]) != std::string::npos ? "an " : "a ";
        b[key].fail("no '" + key + "' on " + article + name + " side (it applies to " + owners +
                    " sides only)");
    }
    return type.read(b);
}

template std::shared_ptr<const sph::WallBoundary<2>> readWallKeys<2>(const At&);
template std::shared_ptr<const sph::WallBoundary<3>> readWallKeys<3>(const At&);
template const std::vector<BoundaryType<2>>& boundaryTypes<2>();
template const std::vector<BoundaryType<3>>& boundaryTypes<3>();
template SideBoundary<2> readSideBoundary<2>(const At&);
template SideBoundary<3> readSideBoundary<3>(const At&);
template std::string boundaryTypeChoices<2>();
template std::string boundaryTypeChoices<3>();

}  // namespace num::app
