// Scene -> engine: settings, fluid model with heat terms, geometry, initial particles, emitters.
#include "app/scene_setup.hpp"
#include "scene/flow_sides.hpp"
#include "scene/moving_bodies.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>

#include "app/formatted.hpp"

namespace num::app {

using sph::Float;
using sph::QuantityId;
using sph::Size;

namespace {

template <int Dim>
double at(const Expression& e, const sph::Vector<Dim>& x, double t) {
    return e(x[0], Dim > 1 ? x[1] : 0.0, Dim > 2 ? x[Dim - 1] : 0.0, t);
}

template <int Dim>
sph::Vector<Dim> at(const VectorField<Dim>& f, const sph::Vector<Dim>& x, double t) {
    sph::Vector<Dim> v;
    for (int k = 0; k < Dim; ++k) v[k] = at<Dim>(f[k], x, t);
    return v;
}

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

/// Calls visit(x) at the points of a fluid block's particle lattice (at most about 10^6 of
/// them: a coarser sub-lattice for huge blocks; a shape other than a box or ball within the
/// domain). Returns the stride of the sub-lattice.
template <int Dim, class Visit>
long forEachBlockSample(const Scene<Dim>& scene, const FluidBlock<Dim>& f, Visit&& visit) {
    const double dx = scene.spacing;
    const sph::PlacedShape<Dim> shape = f.placed();
    const geometry::Bounds<Dim> bounds = shape.bounds();
    SceneVec<Dim> lo = bounds.min, hi = bounds.max;
    if (f.shape == ShapeKind::SOLID)
        for (int k = 0; k < Dim; ++k)
            lo[k] = std::max(lo[k], scene.domainMin[k]),
            hi[k] = std::min(hi[k], scene.domainMax[k]);
    std::array<long, Dim> n{};
    double count = 1;
    for (int k = 0; k < Dim; ++k) {
        n[k] = std::max(1L, std::lround((hi[k] - lo[k]) / dx));
        count *= double(n[k]);
    }
    const long stride = std::max(1L, long(std::ceil(std::pow(count / 1e6, 1.0 / Dim))));
    std::array<long, Dim> i{};
    while (true) {
        sph::Vector<Dim> x;
        for (int k = 0; k < Dim; ++k) x[k] = lo[k] + (double(i[k]) + 0.5) * dx;
        if (shape.contains(x)) visit(x);
        int k = 0;
        while (k < Dim && (i[k] += stride) >= n[k]) i[k] = 0, ++k;
        if (k == Dim) return stride;
    }
}

/// A fluid block's volume: exact for a box or ball, from its lattice for other shapes.
template <int Dim>
double blockVolume(const Scene<Dim>& scene, const FluidBlock<Dim>& f) {
    if (f.shape == ShapeKind::BOX) {
        double v = 1;
        for (int k = 0; k < Dim; ++k) v *= f.max[k] - f.min[k];
        return v;
    }
    if (f.shape != ShapeKind::SOLID)
        return Dim == 2 ? M_PI * f.radius * f.radius : 4 / 3.0 * M_PI * std::pow(f.radius, 3);
    double points = 0;
    const long stride = forEachBlockSample(scene, f, [&](const sph::Vector<Dim>&) { ++points; });
    return points * std::pow(double(stride) * scene.spacing, Dim);
}

/// The largest initial speed of a fluid block, sampled on its particle lattice.
template <int Dim>
double largestBlockSpeed(const Scene<Dim>& scene, const FluidBlock<Dim>& f) {
    double u = 0;
    forEachBlockSample(scene, f, [&](const sph::Vector<Dim>& x) {
        u = std::max(u, norm(at<Dim>(f.velocity, x, 0.0)));
    });
    return u;
}

/// A velocity scale and the scene key (or cause) it comes from.
struct SpeedScale {
    double U = 0;
    std::string from;
    /// Keeps u where it is the largest so far.
    void see(double u, const std::string& source) {
        if (u > U) U = u, from = source;
    }
};

/// The buoyancy speed sqrt(g beta dT H) of a closed box (dT the spread of the fluid
/// temperatures at every lattice point of every block, and of the walls and bodies).
template <int Dim>
double buoyancySpeed(const Scene<Dim>& scene, double gravity, double height) {
    double tMin = 1e300, tMax = -1e300, beta = 0;
    auto see = [&](double T) { tMin = std::min(tMin, T), tMax = std::max(tMax, T); };
    for (const auto& f : scene.fluids)
        forEachBlockSample(scene, f,
                           [&](const sph::Vector<Dim>& x) { see(at<Dim>(f.temperature, x, 0.0)); });
    for (const auto& b : scene.bodies) see(b.temperature);
    for (const auto& w : scene.walls)
        if (const auto held = w.boundary->heldTemperature()) see(*held);
    for (int k = 0; k < Dim; ++k)
        for (const auto& side : scene.sides[k])
            if (const auto held = side->heldTemperature()) see(*held);
    for (const auto& [name, m] : scene.materials) beta = std::max(beta, m.thermalExpansion);
    if (!scene.physics.heat || !scene.physics.buoyancy || !(tMax > tMin)) return 0;
    return std::sqrt(gravity * beta * (tMax - tMin) * height);
}

/// The speeds gravity gives: the free-fall speed sqrt(2 g H) over the domain's height along g
/// where the water has a free surface, or, where the fluid fills a closed box, sqrt(g H) (its
/// hydrostatic compression rho0 g H must stay near 1 % of rho0 c0^2: c0 >= 10 sqrt(g H),
/// Monaghan 1994, sec. 3) and the buoyancy speed.
template <int Dim>
void seeGravity(const Scene<Dim>& scene, const sph::Vector<Dim>& g, bool open, SpeedScale& s) {
    const double gravity = norm(g);
    if (!(gravity > 0)) return;
    double height = 0, domainVolume = 1, fluidVolume = 0;
    for (int k = 0; k < Dim; ++k) {
        height += std::abs(g[k]) / gravity * (scene.domainMax[k] - scene.domainMin[k]);
        domainVolume *= scene.domainMax[k] - scene.domainMin[k];
    }
    for (const auto& f : scene.fluids) fluidVolume += blockVolume(scene, f);
    const std::string fall = "gravity over the domain's height, " + formatted("%g m", height);
    if (open || !scene.emitters.empty() || fluidVolume < 0.99 * domainVolume) {
        s.see(std::sqrt(2 * gravity * height), "the free fall under " + fall);
    } else {
        s.see(std::sqrt(gravity * height), "the hydrostatic compression under " + fall);
        s.see(buoyancySpeed(scene, gravity, height), "buoyancy (physics.buoyancy)");
    }
}

/// The flow's velocity scale U for "auto" sound speeds (c0 = 10 U), derived from the scene:
/// the largest of the initial fluid speeds (every lattice point of every block), the speeds
/// of moving walls, emitters and inlets, and the speeds gravity gives (seeGravity), with the
/// key it comes from. physics.max_speed overrides it. 0 where none of these gives a speed.
template <int Dim>
SpeedScale velocityScale(const Scene<Dim>& scene, const sph::Vector<Dim>& g) {
    SpeedScale s;
    if (scene.physics.maxSpeed > 0) return {scene.physics.maxSpeed, "physics.max_speed"};
    for (std::size_t i = 0; i < scene.fluids.size(); ++i)
        s.see(largestBlockSpeed(scene, scene.fluids[i]),
              "fluids[" + std::to_string(i) + "].velocity");
    bool open = false;
    for (int k = 0; k < Dim; ++k)
        for (int hi = 0; hi < 2; ++hi) {
            const auto& side = scene.sides[k][hi];
            s.see(side->surfaceSpeed(), std::string("boundaries.") + sideName(k, hi) + ".velocity");
            open |= side->letsFluidOut();
        }
    for (std::size_t i = 0; i < scene.walls.size(); ++i)
        s.see(scene.walls[i].boundary->surfaceSpeed(), "walls[" + std::to_string(i) + "].velocity");
    for (std::size_t i = 0; i < scene.emitters.size(); ++i)
        s.see(scene.emitters[i].speed, "emitters[" + std::to_string(i) + "].speed");
    s.see(largestInflowSpeed(scene), "an inlet's velocity (boundaries)");
    seeGravity(scene, g, open, s);
    return s;
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

/// The sound speed derived by "auto" (10 U) within the limit of an explicit one. (A scale that
/// is not finite comes from an initial velocity that is not: checkInitialState names it.)
template <int Dim>
void checkSoundSpeed(const Scene<Dim>& scene, const std::string& fluidName, const SpeedScale& U) {
    const MaterialSpec& fluid = scene.materials.at(fluidName);
    const std::string key = "materials." + fluidName + ".sound_speed";
    const double c0 = fluid.soundSpeed ? *fluid.soundSpeed : sph::defaults::soundSpeedFactor * U.U;
    if (!fluid.soundSpeed && std::isfinite(c0) && c0 > kMaxSoundSpeed)
        throw sceneError(
            scene.file, key, "a sound speed of at most " + formatted("%g", kMaxSoundSpeed) + " m/s",
            formatted("\"auto\" = %g x U = %.3g m/s, from the velocity scale U = %.3g m/s of ",
                      sph::defaults::soundSpeedFactor, c0, U.U) +
                U.from,
            "the weakly-compressible model is for flows far below the speed of "
            "sound: lower that speed, at most " +
                formatted("%g", kMaxSoundSpeed / sph::defaults::soundSpeedFactor) + " m/s");
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

/// The velocity scale U of the "auto" sound speed (gravity taken at the end of its ramp), or,
/// where nothing moves the fluid, the one the material's sound speed implies (U = c0 / 10).
template <int Dim>
double settledVelocityScale(const Scene<Dim>& scene, const std::string& fluidName) {
    const MaterialSpec& fluid = scene.materials.at(fluidName);
    const double ramp = scene.physics.gravityRamp;
    const sph::Vector<Dim> g0 = at<Dim>(scene.gravity, sph::Vector<Dim>{}, std::max(ramp, 0.0));
    SpeedScale U = velocityScale(scene, g0);
    if (!(U.U > 0) && !fluid.soundSpeed)
        throw sceneError(scene.file, "physics.max_speed",
                         "the largest speed you expect, for the automatic sound speed",
                         "nothing that moves the fluid (no initial velocity, moving wall, "
                         "emitter or gravity)",
                         "or give the material a sound_speed");
    if (!(U.U > 0)) U.U = *fluid.soundSpeed / sph::defaults::soundSpeedFactor;
    checkSoundSpeed(scene, fluidName, U);
    return U.U;
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

template SceneSetup<2> makeSceneSetup<2>(const Scene<2>&, int, const sph::EquationHolder<2>&);
template SceneSetup<3> makeSceneSetup<3>(const Scene<3>&, int, const sph::EquationHolder<3>&);
template sph::Storage<2> makeInitialStorage<2>(const Scene<2>&, SceneSetup<2>&);
template sph::Storage<3> makeInitialStorage<3>(const Scene<3>&, SceneSetup<3>&);

}  // namespace num::app
