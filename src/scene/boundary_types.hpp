// The one table of boundary types of the scene format (boundaries.<side>.type): each type's
// name, the key table of its keys beside "type" (scene/scene_keys.hpp; docs/scenes.md's table
// of the type is made from it), and the maker of its module from them
// (sph/boundary/side_boundary.hpp says what a module does). The scene reader's allowed `type`
// values, their error text and the keys a side may have come from it (internal to
// numerics_app).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "app/scene.hpp"
#include "scene/json_check.hpp"
#include "scene/scene_keys.hpp"
#include "sph/boundary/flow_boundaries.hpp"
#include "sph/boundary/wall_boundary.hpp"

namespace num::app {

/// A side (or an interior wall) as its keys are read: a wall's values, an inlet's or outlet's,
/// and the side's object (for the checks of several keys at once).
template <int Dim>
struct SideInput {
    bool slip = false;
    sph::Vector<Dim> velocity{};  ///< a wall's
    sph::WallThermal thermal;
    sph::FlowSide<Dim> flow;     ///< an inlet's or outlet's
    std::optional<double> held;  ///< an inlet's constant temperature
    const detail::At* at = nullptr;
};

/// A wall's "thermal" as its keys are read: exactly one of them is given.
struct ThermalInput {
    double temperature = 0, heatFlux = 0;
};

/// The keys of a wall's "thermal" (a side's or an interior wall's).
const KeyTable<ThermalInput>& wallThermalKeys();

template <int Dim>
struct BoundaryType {
    std::string name;               ///< the value of "type"
    KeyTable<SideInput<Dim>> keys;  ///< the keys beside "type" a side of this type may have
    /// Reads a side of this type (whose other keys are refused) into its module.
    SideBoundary<Dim> (*read)(const detail::At& side);
};

/// The boundary types, in the order messages list them.
template <int Dim>
const std::vector<BoundaryType<Dim>>& boundaryTypes();

/// Reads one side's object ({"type": ..., and that type's keys}) into its module.
template <int Dim>
SideBoundary<Dim> readSideBoundary(const detail::At& side);

/// A wall's keys beside "type" (slip, velocity, thermal) into its module: a side's, or an
/// interior wall's (scene key "walls").
template <int Dim>
std::shared_ptr<const sph::WallBoundary<Dim>> readWallKeys(const detail::At& wall);

/// The keys of an interior wall (scene key "walls"): `shape` (read with its shape's keys), then a
/// wall side's.
template <int Dim>
const KeyTable<SideInput<Dim>>& interiorWallKeys();

/// What a side's boundary is, for messages: {"type": "wall"}, "periodic" or "open".
template <int Dim>
std::string boundaryTypeChoices();

}  // namespace num::app
