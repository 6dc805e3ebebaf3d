// Scene -> engine: the initial particles, their temperatures, pressures and thermal conditions.
#include "app/scene_setup.hpp"
#include "scene/scene_setup_detail.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace num::app {

using detail::at;
using sph::Float;
using sph::QuantityId;
using sph::Size;

namespace {

/// The boundary particle of a box wall beyond the domain at x: the side it lies deepest beyond
/// (axis -1 inside the domain) and how far.
template <int Dim>
double depthBeyondSide(const Scene<Dim>& scene, const sph::FluidGeometry<Dim>& geo,
                       const sph::Vector<Dim>& x, int& axis, int& hi) {
    double depth = 0;
    axis = -1, hi = 0;
    for (int k = 0; k < Dim; ++k) {
        if (geo.domain.periodic[k]) continue;
        const double below = scene.domainMin[k] - x[k], above = x[k] - scene.domainMax[k];
        if (below > depth) depth = below, axis = k, hi = 0;
        if (above > depth) depth = above, axis = k, hi = 1;
    }
    return depth;
}

/// The boundary particles of one wall (a box side or an interior wall) with their depths.
struct WallParticles {
    std::vector<Size> index;
    std::vector<Float> depth;
};

/// Thermal conditions: bodies by their material, box walls by the side they lie beyond,
/// interior walls by the wall they lie in (a heat flux spread over the area of the layer next
/// to the fluid: its particles times dx^(Dim-1)).
template <int Dim>
void setBoundaryThermal(const Scene<Dim>& scene, const SceneSetup<Dim>& setup,
                        sph::Storage<Dim>& st) {
    using TC = sph::ThermalCondition;
    const auto x = st.template getValue<sph::Vector<Dim>>(QuantityId::POSITION);
    const auto kind = st.template getValue<int>(QuantityId::KIND);
    const auto cond = st.template getValue<int>(sph::heat_ids::THERMAL_CONDITION);
    const sph::FluidGeometry<Dim>& geo = setup.geometry;
    const double dx = scene.spacing;
    std::array<std::array<WallParticles, 2>, Dim> beyond;
    std::vector<WallParticles> inWall(scene.walls.size());
    for (Size i = 0; i < st.size(); ++i) {
        if (kind[i] == int(sph::ParticleKind::BODY)) {
            int body = -1;
            for (std::size_t b = 0; b < scene.bodies.size() && body < 0; ++b)
                if (geo.bodies[b].contains(x[i])) body = int(b);
            cond[i] =
                int(body >= 0 && !scene.bodies[body].material.empty() ? TC::CONDUCTING
                                                                      : TC::FIXED_TEMPERATURE);
            continue;
        }
        if (kind[i] != int(sph::ParticleKind::WALL)) continue;
        int axis, hi;
        const double depth = depthBeyondSide(scene, geo, x[i], axis, hi);
        if (axis >= 0) {
            beyond[axis][hi].index.push_back(i), beyond[axis][hi].depth.push_back(depth);
            continue;
        }
        for (std::size_t w = 0; w < geo.interiorWalls.size(); ++w)
            if (const double d = geo.interiorWalls[w].signedDistance(x[i]); d < 0) {
                inWall[w].index.push_back(i), inWall[w].depth.push_back(-d);
                break;
            }
    }
    for (int k = 0; k < Dim; ++k)
        for (int hi = 0; hi < 2; ++hi) {
            double area = 1;
            for (int j = 0; j < Dim; ++j)
                if (j != k) area *= scene.domainMax[j] - scene.domainMin[j];
            scene.sides[k][hi]->setThermal(st, beyond[k][hi].index, beyond[k][hi].depth, area, dx);
        }
    for (std::size_t w = 0; w < inWall.size(); ++w) {
        const double surface = double(std::count_if(inWall[w].depth.begin(), inWall[w].depth.end(),
                                                    [&](Float d) { return d < dx; }));
        scene.walls[w].boundary->setThermal(st, inWall[w].index, inWall[w].depth,
                                            surface * std::pow(dx, Dim - 1), dx);
    }
}

}  // namespace

template <int Dim>
sph::Storage<Dim> makeInitialStorage(const Scene<Dim>& scene, SceneSetup<Dim>& setup) {
    sph::Storage<Dim> st = sph::makeFluidStorage(setup.model, setup.geometry, setup.settings);
    const auto x = st.template getValue<sph::Vector<Dim>>(QuantityId::POSITION);
    const auto kind = st.template getValue<int>(QuantityId::KIND);
    const auto T = st.template getValue<Float>(QuantityId::TEMPERATURE);
    const auto rho = st.template getValue<Float>(QuantityId::DENSITY);
    const auto p = st.template getValue<Float>(QuantityId::PRESSURE);
    const sph::EquationOfState eos = setup.model.equationOfState();
    for (Size i = 0; i < st.size(); ++i) {
        if (kind[i] != int(sph::ParticleKind::FLUID)) continue;
        for (std::size_t b = 0; b < scene.fluids.size(); ++b) {
            if (!setup.geometry.fluid[b].contains(x[i])) continue;
            const FluidBlock<Dim>& f = scene.fluids[b];
            if (!f.temperature.isConstant()) T[i] = at<Dim>(f.temperature, x[i], 0.0);
            if (!f.pressure.isConstant() || f.pressure(0, 0, 0, 0) != 0) {
                p[i] = at<Dim>(f.pressure, x[i], 0.0);
                rho[i] = eos.density(p[i]);
            }
            break;
        }
    }
    if (scene.physics.heat && st.has(sph::heat_ids::THERMAL_CONDITION))
        setBoundaryThermal(scene, setup, st);
    if (setup.model.flowBoundaries) setup.model.flowBoundaries->prepare(st, 0.0);
    return st;
}

template sph::Storage<2> makeInitialStorage<2>(const Scene<2>&, SceneSetup<2>&);
template sph::Storage<3> makeInitialStorage<3>(const Scene<3>&, SceneSetup<3>&);

}  // namespace num::app
