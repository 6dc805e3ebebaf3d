// The signed distance of a closed triangle mesh: nearest point through the tree, sign from the
// angle-weighted pseudonormals (Baerentzen & Aanaes 2005): the face normal on a face, the sum of
// the two face normals on an edge, the sum of the face normals weighted by their angles at a
// vertex. Its mass properties from the triangles by the divergence theorem.
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

/// P += w u u^T
void addOuter(Rows<3>& P, const Point<3>& u, double w) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) P[i][j] += w * (u[i] * u[j]);
}

/// Volume, centroid and inertia of the closed, outward mesh by the divergence theorem: a sum
/// over the triangles of the signed tetrahedra (o, a, b, c), o the first vertex (for accuracy)
/// and a, b, c relative to it, d = a . (b x c): volume d / 6, first moment d s / 24 and
/// integral x x^T dV = d / 120 (a a^T + b b^T + c c^T + s s^T) with s = a + b + c (Tonon 2004,
/// J. Math. Stat. 1(1), in matrix form). About the centroid C: P = integral x x^T - V C C^T,
/// I = tr(P) 1 - P. Each u[i] u[j] equals u[j] u[i], so I is exactly symmetric.
MassProperties<3> meshMassProperties(const TriangleMesh& mesh) {
    const Point<3> origin = mesh.vertices[0];
    double volume = 0;
    Point<3> firstMoment{};
    Rows<3> P{};
    for (const auto& t : mesh.triangles) {
        const Point<3> a = mesh.vertices[t[0]] - origin, b = mesh.vertices[t[1]] - origin,
                       c = mesh.vertices[t[2]] - origin, s = a + b + c;
        const double d = dot(a, cross(b, c));
        volume += d / 6;
        firstMoment += s * (d / 24);
        for (const Point<3>& u : {a, b, c, s}) addOuter(P, u, d / 120);
    }
    const Point<3> centroid = firstMoment / volume;
    addOuter(P, centroid, -volume);
    MassProperties<3> m;
    m.volume = volume, m.centroid = origin + centroid;
    const double trace = P[0][0] + P[1][1] + P[2][2];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m.inertia[i][j] = (i == j) * trace - P[i][j];
    return m;
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

std::optional<MassProperties<3>> MeshSolid::massProperties() const {
    return meshMassProperties(parts_->mesh);
}

const TriangleMesh& MeshSolid::mesh() const { return parts_->mesh; }

}  // namespace num::geometry
