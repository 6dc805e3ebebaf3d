// A solid of include/geometry/ flattened into plain data (flat_solid_view.hpp) that the CUDA back
// end copies to the device and evaluates there: the same signed distance and outward normal as
// the Solid, bit for bit. Every solid but triangle meshes: balls, boxes, half-spaces, polygons,
// polylines, cones and cylinders, and their transformations and combinations.
#pragma once

#include <climits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/combination.hpp"
#include "geometry/flat_solid_view.hpp"
#include "geometry/polygon.hpp"
#include "geometry/primitives.hpp"
#include "geometry/revolved.hpp"
#include "geometry/transformed.hpp"

namespace num::geometry {

/// The host's copy: the nodes and numbers of a view (flat_solid_view.hpp), owned.
template <int Dim>
struct FlatSolid {
    std::vector<FlatNode> nodes;
    std::vector<double> data;

    /// A view over these vectors (valid while they are neither changed nor moved).
    FlatSolidView<Dim> view() const {
        return {nodes.data(), int(nodes.size()), data.data(), int(data.size())};
    }
};

namespace detail {

template <int Dim>
void flatPush(std::vector<double>& data, const Point<Dim>& p) {
    for (int k = 0; k < Dim; ++k) data.push_back(p[k]);
}

/// Appends a leaf node for the solid; false for a kind that has none (meshes, unknown kinds).
template <int Dim>
bool flattenLeaf(const Solid<Dim>& solid, FlatSolid<Dim>& flat) {
    FlatNode node{FlatKind::BALL, 0, 1, int(flat.data.size())};
    std::vector<double>& d = flat.data;
    if (const auto* ball = dynamic_cast<const Ball<Dim>*>(&solid)) {
        flatPush(d, ball->center()), d.push_back(ball->radius());
    } else if (const auto* box = dynamic_cast<const Box<Dim>*>(&solid)) {
        node.kind = FlatKind::BOX, flatPush(d, box->min()), flatPush(d, box->max());
    } else if (const auto* half = dynamic_cast<const HalfSpace<Dim>*>(&solid)) {
        node.kind = FlatKind::HALF_SPACE, flatPush(d, half->point()), flatPush(d, half->normal());
    } else if (const auto* line = dynamic_cast<const Polyline<Dim>*>(&solid)) {
        node.kind = FlatKind::POLYLINE, node.count = int(line->points().size());
        for (const Point<Dim>& p : line->points()) flatPush(d, p);
        d.push_back(line->halfThickness());
    } else if (const auto* set = dynamic_cast<const PolygonSet*>(&solid)) {
        const auto edges = set->edges();
        node.kind = FlatKind::POLYGON, node.count = int(edges.size());
        for (const auto& e : edges) flatPush(d, e[0]), flatPush(d, e[1]);
    } else if (const auto* cone = dynamic_cast<const Cone*>(&solid)) {
        node.kind = FlatKind::CONE, flatPush(d, cone->base()), flatPush(d, cone->axis());
        d.insert(d.end(), {cone->length(), cone->baseRadius(), cone->topRadius()});
    } else {
        return false;
    }
    flat.nodes.push_back(node);
    return true;
}

/// Appends the nodes of the solid's tree in pre-order; false where a part has no flat form.
/// `depth`: the transformations and combinations above it.
template <int Dim>
bool flattenInto(const Solid<Dim>& solid, FlatSolid<Dim>& flat, int depth) {
    const auto* moved = dynamic_cast<const Transformed<Dim>*>(&solid);
    const auto* combined = dynamic_cast<const Combination<Dim>*>(&solid);
    if (!moved && !combined) return flattenLeaf(solid, flat);
    if (depth == FLAT_MAX_DEPTH)
        throw std::invalid_argument("a shape nests transformations and combinations more than " +
                                    std::to_string(FLAT_MAX_DEPTH) +
                                    " deep: too deep for the device's containment");
    const std::size_t index = flat.nodes.size();
    flat.nodes.push_back({FlatKind::TRANSFORMED, 1, 1, int(flat.data.size())});
    if (moved) {
        flat.data.push_back(moved->scale());
        for (const Point<Dim>& row : moved->rotation().rows()) flatPush(flat.data, row);
        flatPush(flat.data, moved->translation());
        if (!flattenInto(moved->inner(), flat, depth + 1)) return false;
    } else {
        const Combine how = combined->how();
        flat.nodes[index].kind = how == Combine::UNION          ? FlatKind::UNION
                                 : how == Combine::INTERSECTION ? FlatKind::INTERSECTION
                                                                : FlatKind::DIFFERENCE;
        flat.nodes[index].count = int(combined->parts().size());
        for (const SolidPtr<Dim>& part : combined->parts())
            if (!flattenInto(*part, flat, depth + 1)) return false;
    }
    flat.nodes[index].size = int(flat.nodes.size() - index);
    return true;
}

}  // namespace detail

/// The flat form of `solid`; empty when some part has none (a MeshSolid, a solid class this
/// file does not know). Throws std::invalid_argument when transformations and combinations
/// nest more than FLAT_MAX_DEPTH deep, or the data pass int's range.
template <int Dim>
std::optional<FlatSolid<Dim>> flatten(const Solid<Dim>& solid) {
    FlatSolid<Dim> flat;
    if (!detail::flattenInto(solid, flat, 0)) return std::nullopt;
    if (flat.nodes.size() > INT_MAX || flat.data.size() > INT_MAX)
        throw std::invalid_argument("a shape too large for the device's containment");
    return flat;
}

}  // namespace num::geometry
