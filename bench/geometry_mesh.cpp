// The cost of a mesh's signed distance: building it (checks, pseudonormals, tree) and querying
// it, for an icosphere of 20480 triangles; beside it the generalized winding number computed
// directly (one solid angle per triangle, Van Oosterom & Strackee 1983), the other sign test
// the mesh could have used.
//
//   bench_geometry_mesh [--subdivisions S]     (default 5: 20 * 4^5 = 20480 triangles)
//
// Prints the build time, the time per query for points spread over the bounding box and for
// points near the surface, and the time per query of the direct winding number.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>

#include "geometry/mesh_solid.hpp"

namespace {

using num::geometry::Point;
using num::geometry::TriangleMesh;

double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

/// The icosahedron of unit radius, each triangle split into 4 `subdivisions` times.
TriangleMesh icosphere(int subdivisions) {
    const double t = (1 + std::sqrt(5.0)) / 2;
    TriangleMesh m;
    for (auto [a, b, c] : {std::array{-1., t, 0.},
                           {1., t, 0.},
                           {-1., -t, 0.},
                           {1., -t, 0.},
                           {0., -1., t},
                           {0., 1., t},
                           {0., -1., -t},
                           {0., 1., -t},
                           {t, 0., -1.},
                           {t, 0., 1.},
                           {-t, 0., -1.},
                           {-t, 0., 1.}})
        m.vertices.push_back(Point<3>{{a, b, c}} / std::sqrt(1 + t * t));
    m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                   {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                   {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                   {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<int, int>, int> middle;
        auto mid = [&](int a, int b) {
            const auto [it, added] = middle.try_emplace({std::min(a, b), std::max(a, b)}, 0);
            if (added) {
                const Point<3> p = m.vertices[a] + m.vertices[b];
                it->second = int(m.vertices.size());
                m.vertices.push_back(p / norm(p));
            }
            return it->second;
        };
        std::vector<std::array<int, 3>> finer;
        for (const auto [a, b, c] : m.triangles) {
            const int ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
            finer.insert(finer.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
        }
        m.triangles = std::move(finer);
    }
    return m;
}

/// The winding number of the mesh around x: the sum of the triangles' solid angles / 4 pi.
double windingNumber(const TriangleMesh& m, const Point<3>& x) {
    double sum = 0;
    for (const auto& t : m.triangles) {
        const Point<3> a = m.vertices[t[0]] - x, b = m.vertices[t[1]] - x, c = m.vertices[t[2]] - x;
        const double la = norm(a), lb = norm(b), lc = norm(c);
        sum += 2 * std::atan2(dot(a, num::geometry::cross(b, c)),
                              la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb);
    }
    return sum / (4 * M_PI);
}

}  // namespace

int main(int argc, char** argv) {
    const int subdivisions =
        argc == 3 && std::string(argv[1]) == "--subdivisions" ? std::stoi(argv[2]) : 5;
    const TriangleMesh mesh = icosphere(subdivisions);
    auto start = std::chrono::steady_clock::now();
    const num::geometry::MeshSolid solid(mesh, "icosphere");
    const double build = seconds(start);
    std::mt19937 random(1);
    std::uniform_real_distribution<double> box(-1.2, 1.2), shell(0.9, 1.1);
    const int n = 200000;
    double inside = 0;
    start = std::chrono::steady_clock::now();
    for (int i = 0; i < n; ++i)
        inside += solid.contains(Point<3>{{box(random), box(random), box(random)}});
    const double spread = seconds(start) / n;
    start = std::chrono::steady_clock::now();
    for (int i = 0; i < n; ++i) {
        Point<3> p{{box(random), box(random), box(random)}};
        inside += solid.signedDistance(p / norm(p) * shell(random)) < 0;
    }
    const double near = seconds(start) / n;
    const int w = 200;
    start = std::chrono::steady_clock::now();
    for (int i = 0; i < w; ++i)
        inside += windingNumber(mesh, Point<3>{{box(random), box(random), box(random)}}) > 0.5;
    const double winding = seconds(start) / w;
    std::printf(
        "icosphere of %zu triangles: build %.1f ms; query %.2f us (spread over the box), "
        "%.2f us (near the surface); direct winding number %.0f us per query (%g)\n",
        mesh.triangles.size(), 1e3 * build, 1e6 * spread, 1e6 * near, 1e6 * winding, inside);
}
