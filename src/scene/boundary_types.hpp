// The one table of boundary types of the scene format (boundaries.<side>.type): each type's
// name, its keys beside "type", and the reader of those keys into its module
// (sph/boundary/side_boundary.hpp says what a module does). The scene reader's allowed `type`
// values, their error text and the keys a side may have come from it (internal to
// numerics_app).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "app/scene.hpp"
#include "scene/json_check.hpp"

namespace num::app {

template <int Dim>
struct BoundaryType {
    std::string name;               ///< the value of "type"
    std::vector<std::string> keys;  ///< the keys beside "type" a side of this type may have
    /// Reads a side of this type (whose keys are checked against `keys`) into its module.
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

/// What a side's boundary is, for messages: {"type": "wall"}, "periodic" or "open".
template <int Dim>
std::string boundaryTypeChoices();

}  // namespace num::app
