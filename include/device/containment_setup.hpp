// The containment's solids (containment.hpp) from a fluid geometry, on the host: the bodies and
// the walls inside the domain, general solids flattened (geometry/flat_solid.hpp). Triangle
// meshes are not flattened: the device refuses them (firstSolidNotOnDevice).
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

#include "device/containment.hpp"
#include "geometry/flat_solid.hpp"
#include "sph/bodies/moving_bodies.hpp"
#include "sph/setup/fluid_geometry.hpp"

namespace num::device {

/// "bodies[i]" or "walls[i]" of the first body or interior wall whose shape the device cannot
/// evaluate (a triangle mesh), or "".
template <int Dim>
std::string firstSolidNotOnDevice(const sph::FluidGeometry<Dim>& g) {
    const auto flat = [](const sph::PlacedShape<Dim>& p) {
        return !p.isGeneral() || geometry::flatten(*p.solid).has_value();
    };
    for (std::size_t i = 0; i < g.bodies.size(); ++i)
        if (!flat(g.bodies[i])) return "bodies[" + std::to_string(i) + "]";
    for (std::size_t i = 0; i < g.interiorWalls.size(); ++i)
        if (!flat(g.interiorWalls[i])) return "walls[" + std::to_string(i) + "]";
    return "";
}

/// The bodies, then the walls inside the domain, in the CPU containment's order; a body that
/// moving->moves() kept out in its frame. Throws std::invalid_argument for a solid flatten()
/// does not take (check firstSolidNotOnDevice).
template <int Dim>
ContainmentSolids<Dim> containmentSolids(const sph::FluidGeometry<Dim>& g,
                                         const sph::MovingBodies<Dim>* moving = nullptr) {
    ContainmentSolids<Dim> out;
    const auto add = [&](const sph::PlacedShape<Dim>& p) {
        ContainmentSolid<Dim> s;
        s.shape = p.shape, s.bounds = p.solidBounds;
        if (p.isGeneral()) {
            const std::optional<geometry::FlatSolid<Dim>> flat = geometry::flatten(*p.solid);
            if (!flat) throw std::invalid_argument("a mesh shape cannot run on the device");
            s.firstNode = int(out.nodes.size()), s.nodeCount = int(flat->nodes.size());
            s.firstValue = int(out.values.size()), s.valueCount = int(flat->data.size());
            out.nodes.insert(out.nodes.end(), flat->nodes.begin(), flat->nodes.end());
            out.values.insert(out.values.end(), flat->data.begin(), flat->data.end());
        }
        out.solids.push_back(s);
    };
    for (std::size_t b = 0; b < g.bodies.size(); ++b) {
        add(g.bodies[b]);
        if (moving && moving->moves(int(b))) out.solids.back().moving = int(b);
    }
    for (const sph::InteriorWall<Dim>& wall : g.interiorWalls) add(wall);
    return out;
}

}  // namespace num::device
