// The checks that a triangle mesh bounds a volume, and its volume.
#include <cmath>
#include <cstdio>
#include <unordered_map>

#include "geometry/triangle_mesh.hpp"

namespace num::geometry {

namespace {

std::string text(const Point<3>& p) {
    char s[96];
    std::snprintf(s, sizeof s, "(%g, %g, %g)", p[0], p[1], p[2]);
    return s;
}

double diagonal(const TriangleMesh& mesh) {
    Point<3> lo = mesh.vertices[0], hi = mesh.vertices[0];
    for (const Point<3>& v : mesh.vertices)
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
    return norm(hi - lo);
}

void checkAreas(const TriangleMesh& mesh, const std::string& name) {
    const double tiny = 1e-14 * std::pow(diagonal(mesh), 2);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& [a, b, c] = mesh.triangles[t];
        const Point<3>&pa = mesh.vertices[a], &pb = mesh.vertices[b], &pc = mesh.vertices[c];
        if (norm(cross(pb - pa, pc - pa)) <= tiny)
            throw GeometryError(name + ": triangle " + std::to_string(t) + " at " + text(pa) +
                                " has zero area: remove degenerate triangles (repair the mesh)");
    }
}

/// How the triangles use an edge: how many, and the sum of +1 (low to high index) or -1.
struct EdgeUse {
    int count = 0, direction = 0;
    int from = 0, to = 0;
};

std::unordered_map<std::uint64_t, EdgeUse> edgeUses(const TriangleMesh& mesh) {
    std::unordered_map<std::uint64_t, EdgeUse> uses;
    for (const auto& t : mesh.triangles)
        for (int c = 0; c < 3; ++c) {
            const std::uint32_t u = t[c], v = t[(c + 1) % 3];
            EdgeUse& e = uses[std::uint64_t(std::min(u, v)) << 32 | std::max(u, v)];
            ++e.count, e.direction += u < v ? 1 : -1, e.from = int(u), e.to = int(v);
        }
    return uses;
}

enum class EdgeFault { NONE, OPEN, SHARED, FLIPPED };

EdgeFault faultOf(const EdgeUse& e) {
    return e.count == 1       ? EdgeFault::OPEN
           : e.count > 2      ? EdgeFault::SHARED
           : e.direction != 0 ? EdgeFault::FLIPPED
                              : EdgeFault::NONE;
}

/// How many edges have the fault, and the first of them in the order of the triangles.
std::pair<std::size_t, const EdgeUse*> find(const TriangleMesh& mesh,
                                            const std::unordered_map<std::uint64_t, EdgeUse>& uses,
                                            EdgeFault fault) {
    std::size_t count = 0;
    for (const auto& [key, e] : uses) count += faultOf(e) == fault;
    for (const auto& t : mesh.triangles)
        for (int c = 0; c < 3 && count; ++c) {
            const std::uint32_t u = t[c], v = t[(c + 1) % 3];
            const EdgeUse& e = uses.at(std::uint64_t(std::min(u, v)) << 32 | std::max(u, v));
            if (faultOf(e) == fault) return {count, &e};
        }
    return {0, nullptr};
}

/// One sentence for the first kind of bad edge found: how many and where one is.
void checkEdges(const TriangleMesh& mesh, const std::string& name) {
    const auto uses = edgeUses(mesh);
    auto where = [&](const EdgeUse* e) {
        return "one from " + text(mesh.vertices[e->from]) + " to " + text(mesh.vertices[e->to]);
    };
    if (const auto [n, e] = find(mesh, uses, EdgeFault::OPEN); n)
        throw GeometryError(name + " is not closed: " + std::to_string(n) + " open edges (" +
                            where(e) + "): a volume needs a closed surface; fill the holes");
    if (const auto [n, e] = find(mesh, uses, EdgeFault::SHARED); n)
        throw GeometryError(name + " is not manifold: " + std::to_string(n) +
                            " edges shared by more than two triangles (" + where(e) +
                            "): give each body as a separate closed mesh");
    if (const auto [n, e] = find(mesh, uses, EdgeFault::FLIPPED); n)
        throw GeometryError(name + " is not consistently oriented: " + std::to_string(n) +
                            " edges where two triangles face opposite ways (" + where(e) +
                            "): unify the normals (repair the mesh)");
}

}  // namespace

double enclosedVolume(const TriangleMesh& mesh) {
    double six = 0;
    for (const auto& [a, b, c] : mesh.triangles)
        six += dot(mesh.vertices[a], cross(mesh.vertices[b], mesh.vertices[c]));
    return six / 6;
}

void checkClosedVolume(TriangleMesh& mesh, const std::string& name) {
    if (mesh.triangles.empty()) throw GeometryError(name + " holds no triangles");
    checkAreas(mesh, name);
    checkEdges(mesh, name);
    if (enclosedVolume(mesh) < 0)
        for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
}

}  // namespace num::geometry
