// The section of a closed mesh by the plane x[axis] = at: every triangle whose vertices lie on
// both sides contributes a segment between the points where two of its edges cross the plane;
// each crossing edge belongs to two triangles, so the segments chain into closed loops. A vertex
// exactly on the plane counts as above it, which keeps every crossing well defined.
#include <algorithm>
#include <cstdint>
#include <unordered_map>

#include "geometry/triangle_mesh.hpp"

namespace num::geometry {

namespace {

using EdgeKey = std::uint64_t;

EdgeKey keyOf(std::uint64_t u, std::uint64_t v) { return std::min(u, v) << 32 | std::max(u, v); }

struct Crossings {
    std::unordered_map<EdgeKey, std::array<EdgeKey, 2>> next;  ///< the two edges it links to
    std::unordered_map<EdgeKey, Point<2>> point;
};

Crossings crossings(const TriangleMesh& mesh, int axis, double at) {
    Crossings c;
    auto above = [&](int v) { return mesh.vertices[v][axis] >= at; };
    auto cut = [&](int u, int v) {
        const Point<3>&a = mesh.vertices[u], &b = mesh.vertices[v];
        const Point<3> p = a[axis] == at   ? a
                           : b[axis] == at ? b
                                           : a + (b - a) * ((at - a[axis]) / (b[axis] - a[axis]));
        return Point<2>{{p[(axis + 1) % 3], p[(axis + 2) % 3]}};
    };
    for (const auto& t : mesh.triangles) {
        EdgeKey ends[2];
        int n = 0;
        for (int k = 0; k < 3; ++k) {
            const int u = t[k], v = t[(k + 1) % 3];
            if (above(u) == above(v)) continue;
            ends[n] = keyOf(u, v);
            c.point.try_emplace(ends[n], cut(u, v));
            ++n;
        }
        if (n != 2) continue;
        auto link = [&](EdgeKey from, EdgeKey to) {
            auto [it, added] = c.next.try_emplace(from, std::array<EdgeKey, 2>{to, to});
            if (!added) it->second[1] = to;
        };
        link(ends[0], ends[1]), link(ends[1], ends[0]);
    }
    return c;
}

}  // namespace

std::vector<std::vector<Point<2>>> sectionLoops(const TriangleMesh& mesh, int axis, double at) {
    Crossings c = crossings(mesh, axis, at);
    std::vector<std::vector<Point<2>>> loops;
    std::unordered_map<EdgeKey, bool> used;
    for (const auto& [start, links] : c.next) {
        if (used[start]) continue;
        std::vector<Point<2>> loop;
        EdgeKey previous = start, current = start;
        while (!used[current]) {
            used[current] = true;
            const Point<2>& p = c.point[current];
            if (loop.empty() || !(p == loop.back())) loop.push_back(p);
            const auto& n = c.next[current];
            const EdgeKey following = n[0] == previous ? n[1] : n[0];
            previous = current, current = following;
        }
        while (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
        if (loop.size() >= 3) loops.push_back(std::move(loop));
    }
    return loops;
}

}  // namespace num::geometry
