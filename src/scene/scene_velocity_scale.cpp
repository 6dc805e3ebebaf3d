// The velocity scale U of the "auto" sound speed (c0 = 10 U), derived from the scene.
#include "scene/flow_sides.hpp"
#include "scene/scene_setup_detail.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "app/formatted.hpp"

namespace num::app {

using detail::at;

namespace {

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

}  // namespace

namespace detail {

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

template double settledVelocityScale<2>(const Scene<2>&, const std::string&);
template double settledVelocityScale<3>(const Scene<3>&, const std::string&);

}  // namespace detail

}  // namespace num::app
