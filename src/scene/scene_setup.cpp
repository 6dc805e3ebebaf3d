// Scene -> engine: settings, fluid model with heat terms, geometry, emitters (initial particles:
// scene_initial_storage.cpp; the velocity scale: scene_velocity_scale.cpp).
#include "app/scene_setup.hpp"
#include "scene/flow_sides.hpp"
#include "scene/moving_bodies.hpp"
#include "scene/scene_setup_detail.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>

namespace num::app {

using detail::at;
using detail::settledVelocityScale;
using sph::Float;

namespace {

std::shared_ptr<sph::Material> makeMaterial(const MaterialSpec& m, double c0, double alpha) {
    auto mat = std::make_shared<sph::Material>(m.name);
    mat->params()
        .set("density", m.density)
        .set("sound_speed", m.soundSpeed ? *m.soundSpeed : c0)
        .set("viscosity", m.viscosity)
        .set("artificial_viscosity", m.artificialViscosity.value_or(alpha))
        .set("conductivity", m.conductivity)
        .set("heat_capacity", m.heatCapacity)
        .set("thermal_expansion", m.thermalExpansion)
        .set("reference_temperature", m.referenceTemperature);
    return mat;
}
/// Whether the fluid fills a box closed by walls on every side, with no bodies or emitters: no
/// free surface; under gravity the density is then the kernel sum (docs/physics.md, "Closed
/// boxes"). Every lattice site (the sites fluid particles are made on) must lie in a fluid
/// block.
template <int Dim>
bool filledClosedBox(const Scene<Dim>& scene, const sph::FluidGeometry<Dim>& geo) {
    if (!scene.bodies.empty() || !scene.walls.empty() || !scene.emitters.empty() ||
        geo.fluid.empty())
        return false;
    for (int k = 0; k < Dim; ++k)
        for (int hi = 0; hi < 2; ++hi)
            if (!scene.sides[k][hi]->closes()) return false;
    const double dx = geo.spacing;
    std::array<long, Dim> n{};
    long sites = 1;
    for (int k = 0; k < Dim; ++k) {
        n[k] = std::max(1L, std::lround((geo.domain.max[k] - geo.domain.min[k]) / dx));
        sites *= n[k];
    }
    for (long c = 0; c < sites; ++c) {
        sph::Vector<Dim> x;
        long rest = c;
        for (int k = 0; k < Dim; ++k) {
            x[k] = geo.domain.min[k] + (rest % n[k] + 0.5) * dx;
            rest /= n[k];
        }
        bool inside = false;
        for (const sph::FluidRegion<Dim>& r : geo.fluid) inside |= r.contains(x);
        if (!inside) return false;
    }
    return true;
}

/// Runs f; an engine setting it refuses (sph::SettingsError) becomes a scene error naming the
/// scene's file and the key the setting comes from.
template <class F>
void asSceneError(const std::string& file, const std::string& key, F&& f) {
    try {
        f();
    } catch (const sph::SettingsError& e) {
        throw sceneError(file, key, "a value the engine accepts", "", e.what());
    }
}

/// Indexes the materials in name order and returns the fluid's material: the first fluid
/// block's, else the first emitter's. It sets the equation of state.
template <int Dim>
std::string indexMaterials(const Scene<Dim>& scene, SceneSetup<Dim>& setup) {
    int index = 0;
    for (const auto& [name, m] : scene.materials) setup.materialIndex[name] = index++;
    const std::string fluidName =
        !scene.fluids.empty() ? scene.fluids[0].material : scene.emitters[0].material;
    setup.fluidMaterial = setup.materialIndex[fluidName];
    return fluidName;
}

/// Every fluid block and emitter has the density, sound speed and viscosities of the fluid's
/// material: the fluid is one phase (thermal properties may differ).
template <int Dim>
void checkOnePhase(const Scene<Dim>& scene, const std::string& fluidName) {
    const MaterialSpec& fluid = scene.materials.at(fluidName);
    auto sameFluid = [&](const std::string& name, const std::string& path) {
        const MaterialSpec& m = scene.materials.at(name);
        if (m.density != fluid.density || m.soundSpeed != fluid.soundSpeed ||
            m.viscosity != fluid.viscosity || m.artificialViscosity != fluid.artificialViscosity)
            throw sceneError(scene.file, path,
                             "a material with the density, sound_speed, viscosity and "
                             "artificial_viscosity of \"" +
                                 fluidName +
                                 "\" (the fluid is one phase; thermal properties may differ)",
                             "\"" + name + "\"");
    };
    for (std::size_t i = 0; i < scene.fluids.size(); ++i)
        sameFluid(scene.fluids[i].material, "fluids[" + std::to_string(i) + "].material");
    for (std::size_t i = 0; i < scene.emitters.size(); ++i)
        sameFluid(scene.emitters[i].material, "emitters[" + std::to_string(i) + "].material");
}

/// Gravity as a function of time (expressions in t), with the optional ramp
/// g(t) = g 0.5 (1 - cos(pi t / ramp)) for t < ramp.
template <int Dim>
sph::BodyForce<Dim> gravityOverTime(const Scene<Dim>& scene) {
    auto mutex = std::make_shared<std::mutex>();
    const VectorField<Dim> g = scene.gravity;
    const double ramp = scene.physics.gravityRamp;
    return [g, ramp, mutex](Float t) {
        std::lock_guard<std::mutex> lock(*mutex);
        sph::Vector<Dim> v = at<Dim>(g, sph::Vector<Dim>{}, t);
        if (ramp > 0 && t < ramp) v *= 0.5 * (1 - std::cos(M_PI * std::max(t, 0.0) / ramp));
        return v;
    };
}

/// Whether gravity acts at all: some component varies in time or is not zero.
template <int Dim>
bool gravityIsOn(const Scene<Dim>& scene) {
    bool on = false;
    for (int k = 0; k < Dim; ++k)
        on |= !scene.gravity[k].isConstant() || scene.gravity[k](0, 0, 0, 0) != 0;
    return on;
}
/// The fluid model's flow: rest density, equation of state, viscosities, density diffusion,
/// shifting and the free-surface limits.
template <int Dim>
void setFlowModel(const Scene<Dim>& scene, const MaterialSpec& fluid, double U,
                  sph::FluidModel<Dim>& m) {
    m.restDensity = fluid.density;
    m.maxVelocity = U;
    m.soundSpeed = fluid.soundSpeed ? *fluid.soundSpeed : 0.0;
    m.eos = scene.physics.eos == "linear" ? sph::EosType::LINEAR : sph::EosType::TAIT;
    m.backgroundPressure = scene.physics.backgroundPressure;
    m.maxTension = scene.physics.maxTension;
    m.deltaSph = scene.physics.densityDiffusion;
    m.viscosity = fluid.viscosity;
    m.artificialViscosity =
        fluid.artificialViscosity.value_or(sph::defaults::artificialViscosityFor(
            fluid.viscosity, scene.hOverSpacing * scene.spacing, m.c0(), Dim));
    m.shifting = scene.physics.shifting;
    m.shiftingNormalToWalls = scene.physics.shiftingNormalToWalls;
    m.freeSurfaceTensionLimit = scene.physics.freeSurfaceTensionLimit;
    m.freeSurfaceDensityFloor = scene.physics.freeSurfaceDensityFloor;
}

/// The model's material tables in name order; the fluid's sound speed and artificial viscosity
/// stand in where a material gives none.
template <int Dim>
void addMaterials(const Scene<Dim>& scene, sph::FluidModel<Dim>& m) {
    for (const auto& [name, spec] : scene.materials)
        asSceneError(scene.file, "materials." + name, [&] {
            m.materials.push_back(makeMaterial(spec, m.c0(), m.artificialViscosity));
        });
}

/// Heat conduction (physics.heat): adiabatic walls, bodies at a fixed temperature, and buoyancy
/// where it is asked for, gravity acts and some material expands.
template <int Dim>
void setHeatModel(const Scene<Dim>& scene, bool gravityOn, sph::FluidModel<Dim>& m) {
    if (!scene.physics.heat) return;
    m.heat.conduction = true;
    m.heat.walls = sph::ThermalCondition::ADIABATIC;
    m.heat.bodies = sph::ThermalCondition::FIXED_TEMPERATURE;
    bool expands = false;
    for (const auto& [name, spec] : scene.materials) expands |= spec.thermalExpansion != 0;
    m.heat.buoyancy = scene.physics.buoyancy && expands && gravityOn;
}

/// The run settings: kernel, evaluation, smoothing length, threads, time step limits.
template <int Dim>
void setRunSettings(const Scene<Dim>& scene, int threads, sph::RunSettings& s) {
    asSceneError(scene.file, "particles.kernel", [&] { s.set("kernel", scene.kernel); });
    asSceneError(scene.file, "particles.evaluation",
                 [&] { s.set("evaluation", scene.evaluation); });
    asSceneError(scene.file, "particles.h_over_spacing",
                 [&] { s.set("smoothing_length", scene.hOverSpacing * scene.spacing); });
    asSceneError(scene.file, "--threads", [&] { s.set("threads", std::int64_t(threads)); });
    asSceneError(scene.file, "time.cfl", [&] { s.set("cfl", scene.cfl); });
    if (scene.dtMax > 0)
        asSceneError(scene.file, "time.dt_max", [&] { s.set("dt_max", scene.dtMax); });
}

/// The domain and its walls: each side starts absent, at the fluid's reference temperature and
/// of the fluid's material, and its boundary builds what it needs.
template <int Dim>
void buildDomain(const Scene<Dim>& scene, double temperature, int material,
                 sph::FluidGeometry<Dim>& geo) {
    geo.spacing = scene.spacing;
    geo.domain.min = scene.domainMin, geo.domain.max = scene.domainMax;
    for (int k = 0; k < Dim; ++k)
        for (int hi = 0; hi < 2; ++hi) {
            sph::WallSide<Dim>& w = geo.walls[k][hi];
            w.present = false;
            w.temperature = temperature;
            w.material = material;
            scene.sides[k][hi]->build(geo, k, hi);
        }
}

/// Where a shape's initial temperature is taken: a box's or ball's centre, another shape's
/// bounding box's centre within the domain.
template <int Dim>
sph::Vector<Dim> centreOf(const Scene<Dim>& scene, const SceneShape<Dim>& f) {
    if (f.shape == ShapeKind::BOX) return (f.min + f.max) * 0.5;
    if (f.shape != ShapeKind::SOLID) return f.center;
    const geometry::Bounds<Dim> b = f.solid->bounds();
    sph::Vector<Dim> c;
    for (int k = 0; k < Dim; ++k)
        c[k] =
            0.5 * (std::max(b.min[k], scene.domainMin[k]) + std::min(b.max[k], scene.domainMax[k]));
    return c;
}

/// A fluid block as the engine's region: its shape, its temperature at its centre (the
/// per-particle expression comes later) and its velocity field.
template <int Dim>
sph::FluidRegion<Dim> fluidRegion(const Scene<Dim>& scene, const FluidBlock<Dim>& f, int material) {
    sph::FluidRegion<Dim> r;
    static_cast<sph::PlacedShape<Dim>&>(r) = f.placed();
    r.temperature = at<Dim>(f.temperature, centreOf(scene, f), 0.0);
    r.material = material;
    const VectorField<Dim> v = f.velocity;
    r.velocity = [v](const sph::Vector<Dim>& x) { return at<Dim>(v, x, 0.0); };
    return r;
}

/// A wall inside the domain as the engine's: its shape and its module's velocity, slip and
/// held temperature (else the fluid's reference temperature); of the fluid's material.
template <int Dim>
sph::InteriorWall<Dim> interiorWall(const Wall<Dim>& w, double temperature, int material) {
    sph::InteriorWall<Dim> wall;
    static_cast<sph::PlacedShape<Dim>&>(wall) = w.placed();
    wall.velocity = w.boundary->velocity();
    wall.slip = w.boundary->slip();
    wall.temperature = w.boundary->heldTemperature().value_or(temperature);
    wall.material = material;
    return wall;
}

/// The geometry: domain and walls, fluid regions, solid bodies (of the fluid's material where
/// they name none), walls inside the domain.
template <int Dim>
void buildGeometry(const Scene<Dim>& scene, const MaterialSpec& fluid, SceneSetup<Dim>& setup) {
    sph::FluidGeometry<Dim>& geo = setup.geometry;
    buildDomain(scene, fluid.referenceTemperature, setup.fluidMaterial, geo);
    for (const FluidBlock<Dim>& f : scene.fluids)
        geo.fluid.push_back(fluidRegion(scene, f, setup.materialIndex[f.material]));
    for (const Body<Dim>& b : scene.bodies) {
        sph::SolidBody<Dim> body;
        static_cast<sph::PlacedShape<Dim>&>(body) = b.placed();
        body.temperature = b.temperature;
        body.material = b.material.empty() ? setup.fluidMaterial : setup.materialIndex[b.material];
        geo.bodies.push_back(body);
    }
    for (const Wall<Dim>& w : scene.walls)
        geo.interiorWalls.push_back(
            interiorWall(w, fluid.referenceTemperature, setup.fluidMaterial));
}

/// Density by kernel summation where asked, or, for "auto", where gravity acts on a filled
/// closed box; else by the continuity equation.
template <int Dim>
sph::DensityMode densityMode(const Scene<Dim>& scene, const sph::FluidGeometry<Dim>& geo,
                             bool gravityOn) {
    const bool summation =
        scene.physics.density == "summation" ||
        (scene.physics.density == "auto" && gravityOn && filledClosedBox(scene, geo));
    return summation ? sph::DensityMode::SUMMATION : sph::DensityMode::CONTINUITY;
}

/// An emitter's template particle, made by the model itself so it has every quantity.
template <int Dim>
sph::Storage<Dim> emitterTemplate(const Emitter<Dim>& e, int material, double dx,
                                  const sph::FluidModel<Dim>& m, const sph::RunSettings& s) {
    sph::FluidGeometry<Dim> tiny;
    tiny.spacing = dx;
    tiny.domain.max = sph::Vector<Dim>::filled(2 * dx);
    for (auto& axis : tiny.walls)
        for (auto& w : axis) w.present = false;
    sph::FluidRegion<Dim> r;
    r.shape = sph::BoxOrBall<Dim>::box(tiny.domain.min, tiny.domain.max);
    r.temperature = e.temperature;
    r.material = material;
    tiny.fluid.push_back(r);
    sph::Storage<Dim> t = sph::makeFluidStorage(m, tiny, s);
    t.gather({0});
    t.materials().clear();
    return t;
}

}  // namespace

template <int Dim>
SceneSetup<Dim> makeSceneSetup(const Scene<Dim>& scene, int threads,
                               const sph::EquationHolder<Dim>& extraTerms) {
    SceneSetup<Dim> setup;
    const std::string fluidName = indexMaterials(scene, setup);
    const MaterialSpec& fluid = scene.materials.at(fluidName);
    checkOnePhase(scene, fluidName);
    setup.gravity = gravityOverTime(scene);
    setup.velocityScale = settledVelocityScale(scene, fluidName);
    const bool gravityOn = gravityIsOn(scene);

    sph::FluidModel<Dim>& m = setup.model;
    setFlowModel(scene, fluid, setup.velocityScale, m);
    if (gravityOn) m.bodyForce = setup.gravity;
    addMaterials(scene, m);
    setHeatModel(scene, gravityOn, m);
    m.extraTerms += extraTerms;

    setRunSettings(scene, threads, setup.settings);
    buildGeometry(scene, fluid, setup);
    setup.wallLayers =
        sph::wallLayersFor(sph::RunKernel<Dim>(setup.settings).supportRadius(), scene.spacing);
    m.density = densityMode(scene, setup.geometry, gravityOn);
    m.movingBodies = makeMovingBodies(scene);
    m.flowBoundaries =
        makeFlowBoundaries(scene, setup.geometry, setup.wallLayers, m.backgroundPressure);
    for (const Emitter<Dim>& e : scene.emitters)
        setup.emitterTemplates.push_back(
            emitterTemplate(e, setup.materialIndex[e.material], scene.spacing, m, setup.settings));
    return setup;
}

template SceneSetup<2> makeSceneSetup<2>(const Scene<2>&, int, const sph::EquationHolder<2>&);
template SceneSetup<3> makeSceneSetup<3>(const Scene<3>&, int, const sph::EquationHolder<3>&);

}  // namespace num::app
