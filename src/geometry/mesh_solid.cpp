// The signed distance of a closed triangle mesh: nearest point through the tree, sign from the
// angle-weighted pseudonormals (Baerentzen & Aanaes 2005): the face normal on a face, the sum of
// the two face normals on an edge, the sum of the face normals weighted by their angles at a
// vertex.
#include "geometry/mesh_solid.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "triangle_tree.hpp"

namespace num::geometry {

namespace {

Point<3> unit(const Point<3>& v) { return v / norm(v); }

/// The angle at a between the edges towards b and c.
double angleAt(const Point<3>& a, const Point<3>& b, const Point<3>& c) {
    return std::acos(std::clamp(dot(unit(b - a), unit(c - a)), -1.0, 1.0));
}

}  // namespace

struct MeshSolid::Parts {
    TriangleMesh mesh;
    detail::TriangleTree tree;
    std::vector<Point<3>> faceNormal, vertexNormal;
    std::vector<std::array<Point<3>, 3>> edgeNormal;  ///< edges ab, bc, ca of each triangle

    explicit Parts(TriangleMesh m) : mesh(std::move(m)), tree(mesh) { pseudonormals(); }

    void pseudonormals() {
        const auto& V = mesh.vertices;
        vertexNormal.assign(V.size(), Point<3>{});
        std::unordered_map<std::uint64_t, Point<3>> edgeSum;
        auto key = [](std::uint64_t u, std::uint64_t v) {
            return std::min(u, v) << 32 | std::max(u, v);
        };
        for (const auto& t : mesh.triangles) {
            const Point<3> n = unit(cross(V[t[1]] - V[t[0]], V[t[2]] - V[t[0]]));
            faceNormal.push_back(n);
            for (int c = 0; c < 3; ++c) {
                const int a = t[c], b = t[(c + 1) % 3], o = t[(c + 2) % 3];
                vertexNormal[a] += n * angleAt(V[a], V[b], V[o]);
                edgeSum[key(a, b)] += n;
            }
        }
        for (const auto& t : mesh.triangles)
            edgeNormal.push_back(
                {edgeSum[key(t[0], t[1])], edgeSum[key(t[1], t[2])], edgeSum[key(t[2], t[0])]});
    }

    /// The pseudonormal of the feature where the nearest point lies (not normalised: only its
    /// direction's side matters).
    Point<3> pseudonormal(const detail::NearestTriangle& n) const {
        const auto& t = mesh.triangles[n.triangle];
        switch (n.at.feature) {
            case detail::Feature::FACE:
                return faceNormal[n.triangle];
            case detail::Feature::EDGE_AB:
                return edgeNormal[n.triangle][0];
            case detail::Feature::EDGE_BC:
                return edgeNormal[n.triangle][1];
            case detail::Feature::EDGE_CA:
                return edgeNormal[n.triangle][2];
            case detail::Feature::VERTEX_A:
                return vertexNormal[t[0]];
            case detail::Feature::VERTEX_B:
                return vertexNormal[t[1]];
            case detail::Feature::VERTEX_C:
                return vertexNormal[t[2]];
        }
        return faceNormal[n.triangle];
    }
};

MeshSolid::MeshSolid(TriangleMesh mesh, const std::string& name) {
    checkClosedVolume(mesh, name);
    parts_ = std::make_unique<const Parts>(std::move(mesh));
    detail::checkSelfCrossings(parts_->mesh, parts_->tree, name);
}

MeshSolid::~MeshSolid() = default;

double MeshSolid::signedDistance(const Point<3>& x) const {
    const detail::NearestTriangle n = parts_->tree.nearest(x);
    const double d = std::sqrt(n.distanceSqr);
    return dot(x - n.at.point, parts_->pseudonormal(n)) < 0 ? -d : d;
}

Point<3> MeshSolid::outwardNormal(const Point<3>& x, double) const {
    const detail::NearestTriangle n = parts_->tree.nearest(x);
    const Point<3> pseudo = parts_->pseudonormal(n), away = x - n.at.point;
    const double d = std::sqrt(n.distanceSqr);
    if (!(d > 1e-12 * norm(bounds().max - bounds().min))) return unit(pseudo);
    return dot(away, pseudo) < 0 ? -away / d : away / d;
}

Bounds<3> MeshSolid::bounds() const { return parts_->tree.bounds(); }

const TriangleMesh& MeshSolid::mesh() const { return parts_->mesh; }

}  // namespace num::geometry
