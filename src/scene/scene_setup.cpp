// Scene -> engine: settings, fluid model with heat terms, geometry, initial particles, emitters.
#include "io/scene_setup.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>

#include "io/formatted.hpp"

namespace num::io {

using sph::Float;
using sph::QuantityId;
using sph::Size;

namespace {

template <int Dim>
sph::Shape<Dim> shapeOf(ShapeKind shape, const SceneVec<Dim>& mn, const SceneVec<Dim>& mx,
                        const SceneVec<Dim>& c, double r) {
    return shape == ShapeKind::BOX ? sph::Shape<Dim>::box(mn, mx) : sph::Shape<Dim>::ball(c, r);
}

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
/// them: a coarser sub-lattice for huge blocks).
template <int Dim, class Visit>
void forEachBlockSample(const FluidBlock<Dim>& f, double dx, Visit&& visit) {
    const sph::Shape<Dim> shape = shapeOf<Dim>(f.shape, f.min, f.max, f.center, f.radius);
    SceneVec<Dim> lo = f.min, hi = f.max;
    if (f.shape != ShapeKind::BOX)
        for (int k = 0; k < Dim; ++k)
            lo[k] = f.center[k] - f.radius, hi[k] = f.center[k] + f.radius;
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
        if (k == Dim) return;
    }
}

/// The largest initial speed of a fluid block, sampled on its particle lattice.
template <int Dim>
double largestBlockSpeed(const FluidBlock<Dim>& f, double dx) {
    double u = 0;
    forEachBlockSample(f, dx, [&](const sph::Vector<Dim>& x) {
        u = std::max(u, norm(at<Dim>(f.velocity, x, 0.0)));
    });
    return u;
}

/// The flow's velocity scale U for "auto" sound speeds (c0 = 10 U), derived from the scene:
/// the largest of the initial fluid speeds (every lattice point of every block), the speeds
/// of moving walls and of emitters, and, under gravity, the free-fall speed sqrt(2 g H) over
/// the domain's height along g where the water has a free surface, or, where the fluid fills a
/// closed box, sqrt(g H) (its hydrostatic compression) and the buoyancy speed sqrt(g beta dT H)
/// (dT the spread of the fluid temperatures at every lattice point of every block, and of the
/// walls and bodies). physics.max_speed overrides it. 0 where none of these gives a speed.
template <int Dim>
double velocityScale(const Scene<Dim>& scene, const sph::Vector<Dim>& g) {
    if (scene.maxSpeed > 0) return scene.maxSpeed;
    double U = 0;
    for (const auto& f : scene.fluids) U = std::max(U, largestBlockSpeed(f, scene.spacing));
    bool open = false;
    for (int k = 0; k < Dim; ++k)
        for (const auto& side : scene.sides[k]) {
            U = std::max(U, side->surfaceSpeed());
            open |= side->letsFluidOut();
        }
    for (const auto& e : scene.emitters) U = std::max(U, e.speed);
    const double gravity = norm(g);
    if (gravity > 0) {
        double height = 0, domainVolume = 1, fluidVolume = 0;
        for (int k = 0; k < Dim; ++k) {
            height += std::abs(g[k]) / gravity * (scene.domainMax[k] - scene.domainMin[k]);
            domainVolume *= scene.domainMax[k] - scene.domainMin[k];
        }
        for (const auto& f : scene.fluids) {
            double v = 1;
            for (int k = 0; k < Dim; ++k) v *= f.max[k] - f.min[k];
            if (f.shape != ShapeKind::BOX)
                v = Dim == 2 ? M_PI * f.radius * f.radius : 4 / 3.0 * M_PI * std::pow(f.radius, 3);
            fluidVolume += v;
        }
        const bool freeSurface =
            open || !scene.emitters.empty() || fluidVolume < 0.99 * domainVolume;
        if (freeSurface) {
            U = std::max(U, std::sqrt(2 * gravity * height));
        } else {
            // No fall, but the hydrostatic compression rho0 g H must stay near 1 % of
            // rho0 c0^2: c0 >= 10 sqrt(g H) (Monaghan 1994, sec. 3).
            U = std::max(U, std::sqrt(gravity * height));
            double tMin = 1e300, tMax = -1e300, beta = 0;
            auto see = [&](double T) { tMin = std::min(tMin, T), tMax = std::max(tMax, T); };
            for (const auto& f : scene.fluids)
                forEachBlockSample(f, scene.spacing, [&](const sph::Vector<Dim>& x) {
                    see(at<Dim>(f.temperature, x, 0.0));
                });
            for (const auto& b : scene.bodies) see(b.temperature);
            for (int k = 0; k < Dim; ++k)
                for (const auto& side : scene.sides[k])
                    if (const auto held = side->heldTemperature()) see(*held);
            for (const auto& [name, m] : scene.materials) beta = std::max(beta, m.thermalExpansion);
            if (scene.physics.heat && scene.physics.buoyancy && tMax > tMin)
                U = std::max(U, std::sqrt(gravity * beta * (tMax - tMin) * height));
        }
    }
    return U;
}

/// Whether the fluid fills a box closed by walls on every side, with no bodies or emitters: no
/// free surface; under gravity the density is then the kernel sum (docs/physics.md, "Closed
/// boxes"). Every lattice site (the sites fluid particles are made on) must lie in a fluid
/// block.
template <int Dim>
bool filledClosedBox(const Scene<Dim>& scene, const sph::FluidGeometry<Dim>& geo) {
    if (!scene.bodies.empty() || !scene.emitters.empty() || geo.fluid.empty()) return false;
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
        for (const sph::FluidRegion<Dim>& r : geo.fluid) inside |= r.shape.contains(x);
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
void checkSoundSpeed(const Scene<Dim>& scene, const std::string& fluidName, double U) {
    const MaterialSpec& fluid = scene.materials.at(fluidName);
    const std::string key = "materials." + fluidName + ".sound_speed";
    const double c0 = fluid.soundSpeed ? *fluid.soundSpeed : sph::defaults::soundSpeedFactor * U;
    const std::string from = scene.maxSpeed > 0 ? "physics.max_speed"
                                                : "the scene's speeds (initial velocities, moving "
                                                  "walls, emitters, the height of a fall)";
    if (!fluid.soundSpeed && std::isfinite(c0) && c0 > kMaxSoundSpeed)
        throw sceneError(
            scene.file, key, "a sound speed of at most " + formatted("%g", kMaxSoundSpeed) + " m/s",
            formatted("\"auto\" = %g x U = %.3g m/s, from the velocity scale U = "
                      "%.3g m/s of ",
                      sph::defaults::soundSpeedFactor, c0, U) +
                from,
            "the weakly-compressible model is for flows far below the speed of "
            "sound: lower those speeds, at most " +
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
    double U = velocityScale(scene, g0);
    if (!(U > 0) && !fluid.soundSpeed)
        throw sceneError(scene.file, "physics.max_speed",
                         "the largest speed you expect, for the automatic sound speed",
                         "nothing that moves the fluid (no initial velocity, moving wall, "
                         "emitter or gravity)",
                         "or give the material a sound_speed");
    if (!(U > 0)) U = *fluid.soundSpeed / sph::defaults::soundSpeedFactor;
    checkSoundSpeed(scene, fluidName, U);
    return U;
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

/// A fluid block as the engine's region: its shape, its temperature at its centre (the
/// per-particle expression comes later) and its velocity field.
template <int Dim>
sph::FluidRegion<Dim> fluidRegion(const FluidBlock<Dim>& f, int material) {
    sph::FluidRegion<Dim> r;
    r.shape = shapeOf<Dim>(f.shape, f.min, f.max, f.center, f.radius);
    r.temperature =
        at<Dim>(f.temperature,
                r.shape.type == sph::Shape<Dim>::Type::BOX ? (f.min + f.max) * 0.5 : f.center, 0.0);
    r.material = material;
    const VectorField<Dim> v = f.velocity;
    r.velocity = [v](const sph::Vector<Dim>& x) { return at<Dim>(v, x, 0.0); };
    return r;
}

/// The geometry: domain and walls, fluid regions, solid bodies (of the fluid's material where
/// they name none).
template <int Dim>
void buildGeometry(const Scene<Dim>& scene, const MaterialSpec& fluid, SceneSetup<Dim>& setup) {
    sph::FluidGeometry<Dim>& geo = setup.geometry;
    buildDomain(scene, fluid.referenceTemperature, setup.fluidMaterial, geo);
    for (const FluidBlock<Dim>& f : scene.fluids)
        geo.fluid.push_back(fluidRegion(f, setup.materialIndex[f.material]));
    for (const Body<Dim>& b : scene.bodies) {
        sph::SolidBody<Dim> body;
        body.shape = shapeOf<Dim>(b.shape, b.min, b.max, b.center, b.radius);
        body.temperature = b.temperature;
        body.material = b.material.empty() ? setup.fluidMaterial : setup.materialIndex[b.material];
        geo.bodies.push_back(body);
    }
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
    r.shape = sph::Shape<Dim>::box(tiny.domain.min, tiny.domain.max);
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
    const double dx = scene.spacing;
    for (Size i = 0; i < st.size(); ++i) {
        if (kind[i] != int(sph::ParticleKind::FLUID)) continue;
        for (std::size_t b = 0; b < scene.fluids.size(); ++b) {
            if (!setup.geometry.fluid[b].shape.contains(x[i])) continue;
            const FluidBlock<Dim>& f = scene.fluids[b];
            if (!f.temperature.isConstant()) T[i] = at<Dim>(f.temperature, x[i], 0.0);
            if (!f.pressure.isConstant() || f.pressure(0, 0, 0, 0) != 0) {
                p[i] = at<Dim>(f.pressure, x[i], 0.0);
                rho[i] = eos.density(p[i]);
            }
            break;
        }
    }
    if (!scene.physics.heat || !st.has(sph::heat_ids::THERMAL_CONDITION)) return st;
    // Thermal conditions: bodies by their material, walls by the side they lie beyond.
    using TC = sph::ThermalCondition;
    const auto cond = st.template getValue<int>(sph::heat_ids::THERMAL_CONDITION);
    std::array<std::array<std::vector<Size>, 2>, Dim> beyond;
    std::array<std::array<std::vector<Float>, 2>, Dim> depths;
    for (Size i = 0; i < st.size(); ++i) {
        if (kind[i] == int(sph::ParticleKind::BODY)) {
            int body = -1;
            for (std::size_t b = 0; b < scene.bodies.size() && body < 0; ++b)
                if (setup.geometry.bodies[b].shape.contains(x[i])) body = int(b);
            cond[i] =
                int(body >= 0 && !scene.bodies[body].material.empty() ? TC::CONDUCTING
                                                                      : TC::FIXED_TEMPERATURE);
            continue;
        }
        if (kind[i] != int(sph::ParticleKind::WALL)) continue;
        double depth = 0;
        int axis = -1, hi = 0;
        for (int k = 0; k < Dim; ++k) {
            if (setup.geometry.domain.periodic[k]) continue;
            const double below = scene.domainMin[k] - x[i][k], above = x[i][k] - scene.domainMax[k];
            if (below > depth) depth = below, axis = k, hi = 0;
            if (above > depth) depth = above, axis = k, hi = 1;
        }
        if (axis < 0) continue;
        beyond[axis][hi].push_back(i), depths[axis][hi].push_back(depth);
    }
    for (int k = 0; k < Dim; ++k)
        for (int hi = 0; hi < 2; ++hi) {
            double area = 1;
            for (int j = 0; j < Dim; ++j)
                if (j != k) area *= scene.domainMax[j] - scene.domainMin[j];
            scene.sides[k][hi]->setThermal(st, beyond[k][hi], depths[k][hi], area, dx);
        }
    return st;
}

template SceneSetup<2> makeSceneSetup<2>(const Scene<2>&, int, const sph::EquationHolder<2>&);
template SceneSetup<3> makeSceneSetup<3>(const Scene<3>&, int, const sph::EquationHolder<3>&);
template sph::Storage<2> makeInitialStorage<2>(const Scene<2>&, SceneSetup<2>&);
template sph::Storage<3> makeInitialStorage<3>(const Scene<3>&, SceneSetup<3>&);

}  // namespace num::io
