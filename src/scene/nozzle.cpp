#include "app/nozzle.hpp"

#include <algorithm>
#include <cmath>

namespace num::app {

template <int Dim>
std::vector<SceneVec<Dim>> nozzleOffsets(const Emitter<Dim>& e, double dx) {
    std::vector<SceneVec<Dim>> out;
    const int m = std::max(1, int(std::lround(2 * e.radius / dx)));
    auto offset = [&](int j) { return (j + 0.5 - 0.5 * m) * dx; };
    if constexpr (Dim == 2) {
        const SceneVec<2> across{{-e.direction[1], e.direction[0]}};
        for (int j = 0; j < m; ++j) out.push_back(across * offset(j));
    } else {
        // An orthonormal pair across the direction d.
        SceneVec<3> a{{1, 0, 0}};
        if (std::abs(e.direction[0]) > 0.9) a = {{0, 1, 0}};
        SceneVec<3> e1 = a - e.direction * dot(a, e.direction);
        e1 /= norm(e1);
        const SceneVec<3> e2{{e.direction[1] * e1[2] - e.direction[2] * e1[1],
                              e.direction[2] * e1[0] - e.direction[0] * e1[2],
                              e.direction[0] * e1[1] - e.direction[1] * e1[0]}};
        for (int i = 0; i < m; ++i)
            for (int j = 0; j < m; ++j)
                if (offset(i) * offset(i) + offset(j) * offset(j) <= e.radius * e.radius + 1e-12)
                    out.push_back(e1 * offset(i) + e2 * offset(j));
        if (out.empty()) out.push_back({});
    }
    return out;
}

template <int Dim>
Nozzle<Dim> openNozzle(const Scene<Dim>& scene, std::size_t i) {
    const Emitter<Dim>& e = scene.emitters[i];
    std::vector<std::pair<std::string, sph::PlacedShape<Dim>>> solids;
    for (std::size_t j = 0; j < scene.bodies.size(); ++j)
        solids.emplace_back("bodies[" + std::to_string(j) + "]", scene.bodies[j].placed());
    for (std::size_t j = 0; j < scene.walls.size(); ++j)
        solids.emplace_back("walls[" + std::to_string(j) + "]", scene.walls[j].placed());
    Nozzle<Dim> nozzle;
    for (const SceneVec<Dim>& offset : nozzleOffsets(e, scene.spacing)) {
        const SceneVec<Dim> x = e.position + offset;
        auto taken = std::find_if(solids.begin(), solids.end(), [&](const auto& s) {
            return s.second.signedDistance(x) < 0.5 * scene.spacing;
        });
        if (taken == solids.end()) {
            nozzle.open.push_back(offset);
        } else {
            if (nozzle.cut++ == 0) nozzle.cutBy = taken->first;
        }
    }
    return nozzle;
}

template std::vector<SceneVec<2>> nozzleOffsets<2>(const Emitter<2>&, double);
template std::vector<SceneVec<3>> nozzleOffsets<3>(const Emitter<3>&, double);
template Nozzle<2> openNozzle<2>(const Scene<2>&, std::size_t);
template Nozzle<3> openNozzle<3>(const Scene<3>&, std::size_t);

}  // namespace num::app
