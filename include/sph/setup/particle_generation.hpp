// Particles on a Cartesian lattice of spacing dx: the fluid, the wall layers outside the
// container box and the particles of solid bodies all sit on one lattice of cell centres
// (x = lo + (i + 1/2) dx), so spacing is uniform across fluid-wall interfaces.
#pragma once

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sph/setup/fluid_geometry.hpp"
#include "sph/setup/set_up_interrupt.hpp"

namespace num::sph {

/// Calls f(x) for every cell centre of the lattice covering [lo, hi) with spacing dx (polling
/// pollSetUpInterrupt once per row along the first axis).
template <int Dim, class F>
void forEachLatticePoint(const Vector<Dim>& lo, const Vector<Dim>& hi, Float dx, F&& f) {
    std::array<long, Dim> n{};
    for (int k = 0; k < Dim; ++k) {
        n[k] = std::lround((hi[k] - lo[k]) / dx);
        if (n[k] <= 0) return;
    }
    std::array<long, Dim> i{};
    for (;;) {
        Vector<Dim> x;
        for (int k = 0; k < Dim; ++k) x[k] = lo[k] + (Float(i[k]) + 0.5) * dx;
        f(x);
        int k = 0;
        while (k < Dim && ++i[k] == n[k]) i[k++] = 0;
        if (k == Dim) return;
        if (k > 0) pollSetUpInterrupt();
    }
}

/// One generated particle before it goes into a Storage.
template <int Dim>
struct GeneratedParticle {
    Vector<Dim> x{}, v{};
    ParticleKind kind = ParticleKind::FLUID;
    Float temperature = defaults::temperature;
    int material = 0;
    Vector<Dim> wallVelocity{};
    WallSlip slip = WallSlip::NO_SLIP;
};

/// Wall layers needed to cover a kernel support radius with spacing dx.
inline int wallLayersFor(Float supportRadius, Float dx) {
    return std::max(1, int(std::ceil(supportRadius / dx - 1e-9)));
}

namespace detail {

/// The lattice's box: the domain, grown by `layers` spacings on each side with a wall. Throws
/// std::invalid_argument (naming the axis) when a periodic length is not a multiple of dx.
template <int Dim>
void latticeBox(const FluidGeometry<Dim>& g, int layers, Vector<Dim>& lo, Vector<Dim>& hi) {
    const Float dx = g.spacing;
    const Domain<Dim>& d = g.domain;
    lo = d.min, hi = d.max;
    for (int k = 0; k < Dim; ++k) {
        const Float cells = d.length(k) / dx;
        if (d.periodic[k] && std::abs(cells - std::round(cells)) > 1e-6 * cells)
            throw std::invalid_argument("periodic axis " + std::to_string(k) + ": length " +
                                        std::to_string(d.length(k)) +
                                        " is not a multiple of the spacing " + std::to_string(dx));
        if (g.hasWall(k, 0)) lo[k] -= layers * dx;
        if (g.hasWall(k, 1)) hi[k] += layers * dx;
    }
}

/// Whether p.x lies outside the box; p is then a wall particle, described by the side it lies
/// deepest beyond, or beyond an inlet's or outlet's side only, a particle of its buffer
/// (FluidGeometry::kindBeyond).
template <int Dim>
bool describeBeyondBox(const FluidGeometry<Dim>& g, GeneratedParticle<Dim>& p) {
    const Domain<Dim>& d = g.domain;
    Float depth = 0, wallDepth = 0;
    int axis = -1, side = 0, wallAxis = -1, wallSide = 0;
    for (int k = 0; k < Dim; ++k) {
        if (d.periodic[k]) continue;
        for (int hi = 0; hi < 2; ++hi) {
            const Float beyond = hi ? p.x[k] - d.max[k] : d.min[k] - p.x[k];
            if (beyond > depth) depth = beyond, axis = k, side = hi;
            if (beyond > wallDepth && g.isSolidWall(k, hi))
                wallDepth = beyond, wallAxis = k, wallSide = hi;
        }
    }
    if (wallAxis >= 0) axis = wallAxis, side = wallSide;
    if (axis < 0) return false;
    const WallSide<Dim>& w = g.walls[axis][side];
    p.kind = wallAxis >= 0 ? ParticleKind::WALL : g.kindBeyond(axis, side, p.x);
    p.temperature = w.temperature, p.material = w.material;
    p.wallVelocity = w.velocity, p.slip = w.slip;
    return true;
}

/// The particle at lattice point x, if any: beyond the box a wall's or a buffer's, else a
/// body's (whole, or a shell of its thickness), an interior wall's (-layers dx < signed
/// distance < 0), or the fluid's inside its regions.
template <int Dim>
std::optional<GeneratedParticle<Dim>> particleAt(const FluidGeometry<Dim>& g, const Vector<Dim>& x,
                                                 int layers) {
    GeneratedParticle<Dim> p;
    p.x = x;
    if (describeBeyondBox(g, p)) return p;
    for (const SolidBody<Dim>& b : g.bodies) {
        const Float s = b.signedDistance(x);
        if (s >= 0) continue;
        if (b.thickness > 0 && s < -b.thickness) return std::nullopt;
        p.kind = ParticleKind::BODY;
        p.temperature = b.temperature, p.material = b.material, p.slip = b.slip;
        return p;
    }
    for (const InteriorWall<Dim>& w : g.interiorWalls) {
        const Float s = w.signedDistance(x);
        if (s >= 0) continue;
        if (s <= -layers * g.spacing) return std::nullopt;  // deeper than the wall layers
        p.kind = ParticleKind::WALL;
        p.temperature = w.temperature, p.material = w.material;
        p.wallVelocity = w.velocity, p.slip = w.slip;
        return p;
    }
    for (const FluidRegion<Dim>& r : g.fluid) {
        if (!r.contains(x)) continue;
        p.temperature = r.temperature, p.material = r.material;
        if (r.velocity) p.v = r.velocity(x);
        return p;
    }
    return std::nullopt;
}

}  // namespace detail

/// Generates the fluid, wall and body particles of a geometry: the box walls' `layers`, bodies
/// (whole, or a shell of their thickness), interior walls (the lattice points with
/// -layers dx < signed distance < 0), and fluid inside its regions and outside every body and
/// wall. Throws std::invalid_argument
/// (naming the axis) when a periodic length is not a multiple of the spacing.
template <int Dim>
std::vector<GeneratedParticle<Dim>> generateParticles(const FluidGeometry<Dim>& g, int layers) {
    if (!(g.spacing > 0)) throw std::invalid_argument("particle spacing must be positive");
    Vector<Dim> lo, hi;
    detail::latticeBox(g, layers, lo, hi);
    std::vector<GeneratedParticle<Dim>> out;
    forEachLatticePoint<Dim>(lo, hi, g.spacing, [&](const Vector<Dim>& x) {
        if (auto p = detail::particleAt(g, x, layers)) out.push_back(*p);
    });
    return out;
}

}  // namespace num::sph
