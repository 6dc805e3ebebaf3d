// A closed triangle mesh as a solid. The distance is exact: the nearest triangle is found
// through a bounding-volume tree (axis-aligned boxes), the nearest point on it exactly (Ericson,
// Real-Time Collision Detection, 2005, 5.1.5). The sign is that of (x - nearest) . n with n the
// angle-weighted pseudonormal of the nearest face, edge or vertex (Baerentzen & Aanaes, IEEE
// TVCG 11(3), 2005): exact for a closed, consistently oriented mesh that does not intersect
// itself, at the cost of one nearest-point query.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "geometry/triangle_mesh.hpp"

namespace num::geometry {

class MeshSolid final : public Solid<3> {
  public:
    /// Checks the mesh (checkClosedVolume, then that no two triangles cross; messages naming
    /// `name`) and builds the tree.
    MeshSolid(TriangleMesh mesh, const std::string& name);
    ~MeshSolid() override;

    double signedDistance(const Point<3>& x) const override;
    Bounds<3> bounds() const override;
    /// The direction from the nearest surface point (the pseudonormal on the surface).
    Point<3> outwardNormal(const Point<3>& x, double h = 1e-6) const override;
    /// Exact, from the triangles by the divergence theorem (mesh_solid.cpp).
    std::optional<MassProperties<3>> massProperties() const override;
    const TriangleMesh& mesh() const;

  private:
    struct Parts;
    std::unique_ptr<const Parts> parts_;
};

}  // namespace num::geometry
