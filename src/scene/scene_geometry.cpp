// Geometry checks of a scene: everything inside the domain, no fluid in a body or wall, not
// empty.
#include <algorithm>
#include <cmath>

#include "app/formatted.hpp"
#include "app/nozzle.hpp"
#include "app/scene_loader.hpp"
#include "scene/flow_sides.hpp"
#include "scene/run_limits.hpp"
#include "sph/setup/particle_generation.hpp"

namespace num::app {

namespace {

template <int Dim>
std::string text(const SceneVec<Dim>& v) {
    std::string s = "[";
    for (int k = 0; k < Dim; ++k) s += (k ? ", " : "") + formatted("%g", v[k]);
    return s + "]";
}

/// Bounding box of a shape.
template <int Dim>
void bounds(const SceneShape<Dim>& shape, SceneVec<Dim>& lo, SceneVec<Dim>& hi) {
    const geometry::Bounds<Dim> b = shape.placed().bounds();
    lo = b.min, hi = b.max;
}

/// Distance from p to a box (0 inside).
template <int Dim>
double distanceToBox(const SceneVec<Dim>& p, const SceneVec<Dim>& lo, const SceneVec<Dim>& hi) {
    double d2 = 0;
    for (int k = 0; k < Dim; ++k) {
        const double e = std::max({lo[k] - p[k], 0.0, p[k] - hi[k]});
        d2 += e * e;
    }
    return std::sqrt(d2);
}

/// Whether a box or ball fluid block and a box or ball body overlap by more than `tol`.
template <int Dim>
bool overlap(const SceneShape<Dim>& f, const SceneShape<Dim>& b, double tol) {
    const bool fBox = f.shape == ShapeKind::BOX, bBox = b.shape == ShapeKind::BOX;
    if (fBox && bBox) {
        for (int k = 0; k < Dim; ++k)
            if (std::min(f.max[k], b.max[k]) - std::max(f.min[k], b.min[k]) <= tol) return false;
        return true;
    }
    if (fBox) return distanceToBox<Dim>(b.center, f.min, f.max) < b.radius - tol;
    if (bBox) return distanceToBox<Dim>(f.center, b.min, b.max) < f.radius - tol;
    return norm(f.center - b.center) < f.radius + b.radius - tol;
}

/// The cells lo..hi of the particle lattice (the domain's cells) that cover a bounding box,
/// within the domain.
template <int Dim>
void latticeCellsAround(const Scene<Dim>& s, const geometry::Bounds<Dim>& b, SceneVec<Dim>& lo,
                        SceneVec<Dim>& hi) {
    for (int k = 0; k < Dim; ++k) {
        const double cells = std::round((s.domainMax[k] - s.domainMin[k]) / s.spacing);
        const double first = std::clamp(std::floor((b.min[k] - s.domainMin[k]) / s.spacing), 0.0,
                                        cells),
                     last =
                         std::clamp(std::ceil((b.max[k] - s.domainMin[k]) / s.spacing), 0.0, cells);
        lo[k] = s.domainMin[k] + first * s.spacing, hi[k] = s.domainMin[k] + last * s.spacing;
    }
}

/// Calls visit(x) at the points of the particle lattice (the domain's cell centres) inside a
/// shape, within the domain.
template <int Dim, class Visit>
void forEachLatticePointInside(const Scene<Dim>& s, const sph::PlacedShape<Dim>& shape,
                               Visit&& visit) {
    SceneVec<Dim> lo, hi;
    latticeCellsAround(s, shape.bounds(), lo, hi);
    sph::forEachLatticePoint<Dim>(lo, hi, s.spacing, [&](const SceneVec<Dim>& x) {
        if (shape.contains(x)) visit(x);
    });
}

/// Whether a fluid block lies deeper than `tol` inside a solid (a body or a wall) at a point of
/// its particle lattice.
template <int Dim>
bool overlapOnLattice(const Scene<Dim>& s, const SceneShape<Dim>& f, const SceneShape<Dim>& solid,
                      double tol) {
    const sph::PlacedShape<Dim> into = solid.placed();
    bool found = false;
    forEachLatticePointInside(s, f.placed(), [&](const SceneVec<Dim>& x) {
        found = found || into.signedDistance(x) < -tol;
    });
    return found;
}

/// Whether a shape's bounding box meets the domain (an unbounded shape's may be infinite).
template <int Dim>
bool meetsDomain(const Scene<Dim>& s, const SceneShape<Dim>& shape) {
    const geometry::Bounds<Dim> b = shape.placed().bounds();
    for (int k = 0; k < Dim; ++k)
        if (b.max[k] < s.domainMin[k] || b.min[k] > s.domainMax[k]) return false;
    return true;
}

/// Whether the box lo..hi lies inside the scene's domain, up to a rounding tolerance.
template <int Dim>
bool insideDomain(const Scene<Dim>& s, const SceneVec<Dim>& lo, const SceneVec<Dim>& hi) {
    const double tol = 1e-9 * norm(s.domainMax - s.domainMin);
    for (int k = 0; k < Dim; ++k)
        if (lo[k] < s.domainMin[k] - tol || hi[k] > s.domainMax[k] + tol) return false;
    return true;
}

/// The domain as the messages name it.
template <int Dim>
std::string domainText(const Scene<Dim>& s) {
    return "the domain " + text<Dim>(s.domainMin) + " to " + text<Dim>(s.domainMax);
}

/// The spacing is at most half the domain's extent on every axis.
template <int Dim>
void checkSpacing(const Scene<Dim>& s) {
    for (int k = 0; k < Dim; ++k)
        if (s.domainMax[k] - s.domainMin[k] < 2 * s.spacing)
            throw sceneError(s.file, "particles.spacing",
                             "a spacing at most half the domain's extent on every axis",
                             formatted("%g", s.spacing));
}

/// A box or ball fluid block lies inside the domain and is at least one spacing wide. Returns
/// its bounding box's volume in spacing cells (an estimate of its particle count).
template <int Dim>
double checkBoxOrBallBlock(const Scene<Dim>& s, const FluidBlock<Dim>& f, const std::string& path) {
    const std::string& file = s.file;
    SceneVec<Dim> lo, hi;
    bounds<Dim>(f, lo, hi);
    if (!insideDomain(s, lo, hi))
        throw sceneError(file, path, "a fluid block inside " + domainText(s),
                         "a block spanning " + text<Dim>(lo) + " to " + text<Dim>(hi));
    double cells = 1;
    for (int k = 0; k < Dim; ++k) cells *= (hi[k] - lo[k]) / s.spacing;
    if (f.shape != ShapeKind::BOX && 2 * f.radius < s.spacing)
        throw sceneError(
            file, path + ".radius",
            "a radius of at least half the spacing (" + formatted("%g", s.spacing / 2) + " m)",
            formatted("%g", f.radius), "the block would hold no particle");
    for (int k = 0; k < Dim; ++k)
        if (hi[k] - lo[k] < s.spacing)
            throw sceneError(
                file, path,
                "a block at least one spacing (" + formatted("%g", s.spacing) +
                    " m) wide on every axis",
                "a width of " + formatted("%g", hi[k] - lo[k]) + " m on axis " + std::to_string(k),
                "the block would hold no particle");
    return cells;
}

/// The fluid particles of a block of any shape: its lattice points outside every body and wall.
template <int Dim>
double countFluidPoints(const Scene<Dim>& s, const FluidBlock<Dim>& f) {
    std::vector<sph::PlacedShape<Dim>> solids;
    for (const auto& b : s.bodies) solids.push_back(b.placed());
    for (const auto& w : s.walls) solids.push_back(w.placed());
    double count = 0;
    forEachLatticePointInside(s, f.placed(), [&](const SceneVec<Dim>& x) {
        count += std::none_of(solids.begin(), solids.end(),
                              [&](const auto& solid) { return solid.contains(x); });
    });
    return count;
}

/// A fluid block of any other shape meets the domain and holds particles. Returns their number.
template <int Dim>
double checkGeneralBlock(const Scene<Dim>& s, const FluidBlock<Dim>& f, const std::string& path) {
    SceneVec<Dim> lo, hi;
    bounds<Dim>(f, lo, hi);
    if (!meetsDomain(s, f))
        throw sceneError(s.file, path, "a fluid volume inside " + domainText(s),
                         "a shape spanning " + text<Dim>(lo) + " to " + text<Dim>(hi));
    const double count = countFluidPoints(s, f);
    if (count == 0)
        throw sceneError(s.file, path,
                         "a fluid volume holding particles on the lattice of spacing " +
                             formatted("%g", s.spacing) +
                             " m (inside the domain, outside every body and wall)",
                         "none", "enlarge the shape or refine particles.spacing");
    return count;
}

/// Fluid block i lies inside the domain, holds particles and overlaps no wall by more than half
/// a spacing (it fills its volume outside every body: a floating box placed in a tank). Returns
/// an estimate of its particle count.
template <int Dim>
double checkFluidBlock(const Scene<Dim>& s, std::size_t i) {
    const FluidBlock<Dim>& f = s.fluids[i];
    const std::string path = "fluids[" + std::to_string(i) + "]";
    const bool general = f.shape == ShapeKind::SOLID;
    const double tol = 0.5 * s.spacing;
    const double cells = general ? 0 : checkBoxOrBallBlock(s, f, path);
    for (std::size_t j = 0; j < s.walls.size(); ++j)
        if (overlapOnLattice(s, f, s.walls[j], tol))
            throw sceneError(s.file, path, "a fluid block that does not overlap a wall",
                             "an overlap with walls[" + std::to_string(j) + "]",
                             "shrink or split the block around the wall");
    // A block that overlaps a body: its particles counted on the lattice (none is refused).
    bool cut = general;
    for (const Body<Dim>& b : s.bodies)
        cut = cut || b.shape == ShapeKind::SOLID || overlap<Dim>(f, b, tol);
    return cut ? checkGeneralBlock(s, f, path) : cells;
}

/// Checks every fluid block; returns the estimated number of fluid particles.
template <int Dim>
double checkFluidBlocks(const Scene<Dim>& s) {
    double estimate = 0;
    for (std::size_t i = 0; i < s.fluids.size(); ++i) estimate += checkFluidBlock(s, i);
    return estimate;
}

/// A moving body starts clear of every other body and wall (by more than half a spacing), and
/// a free body's given inertia is positive.
template <int Dim>
void checkMovingBodyClear(const Scene<Dim>& s, std::size_t i) {
    const std::string path = "bodies[" + std::to_string(i) + "]";
    const double tol = 0.5 * s.spacing;
    auto refuse = [&](const std::string& other) {
        throw sceneError(s.file, path, "a moving body clear of every other body and wall",
                         "it starts inside " + other, "move it or make it smaller");
    };
    for (std::size_t j = 0; j < s.bodies.size(); ++j)
        if (j != i && overlapOnLattice(s, s.bodies[i], s.bodies[j], tol))
            refuse("bodies[" + std::to_string(j) + "]");
    for (std::size_t j = 0; j < s.walls.size(); ++j)
        if (overlapOnLattice(s, s.bodies[i], s.walls[j], tol))
            refuse("walls[" + std::to_string(j) + "]");
    const BodyMotionSpec<Dim>& m = s.bodies[i].motion;
    if (m.inertia.size() == 9) {
        sph::Inertia<3> I;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) I.rows[r][c] = m.inertia[3 * r + c];
        if (!I.positive())
            throw sceneError(s.file, path + ".motion.inertia",
                             "a symmetric, positive definite tensor [kg m^2]", "one that is not");
    }
}

/// Whether a shape holds a point of the particle lattice inside the domain: where a body or
/// wall has its boundary particles (none: it would run as if it were not there).
template <int Dim>
bool holdsLatticePoint(const Scene<Dim>& s, const SceneShape<Dim>& shape) {
    const sph::PlacedShape<Dim> placed = shape.placed();
    bool found = false;
    SceneVec<Dim> lo, hi;
    latticeCellsAround(s, placed.bounds(), lo, hi);
    // More points than the set-up may visit: the run's limits refuse the scene (run_limits.hpp).
    double points = 1;
    for (int k = 0; k < Dim; ++k) points *= std::round((hi[k] - lo[k]) / s.spacing);
    if (points > kMaxLatticePoints) return true;
    // Once a point is found the rest of the lattice is walked without asking the shape.
    sph::forEachLatticePoint<Dim>(lo, hi, s.spacing, [&](const SceneVec<Dim>& x) {
        found = found || placed.signedDistance(x) < 0;
    });
    return found;
}

/// Bodies lie inside the domain (a box or ball) or meet it (any other shape); walls meet it;
/// each holds boundary particles.
template <int Dim>
void checkBodiesAndWalls(const Scene<Dim>& s) {
    auto check = [&](const SceneShape<Dim>& shape, const std::string& path, const char* what) {
        SceneVec<Dim> lo, hi;
        bounds<Dim>(shape, lo, hi);
        const bool boxOrBall = shape.shape != ShapeKind::SOLID && std::string(what) == "body";
        if (!(boxOrBall ? insideDomain(s, lo, hi) : meetsDomain(s, shape)))
            throw sceneError(s.file, path, std::string("a ") + what + " inside " + domainText(s),
                             std::string("a ") + (boxOrBall ? what : "shape") + " spanning " +
                                 text<Dim>(lo) + " to " + text<Dim>(hi));
        if (!holdsLatticePoint(s, shape))
            throw sceneError(
                s.file, path,
                std::string("a ") + what +
                    " holding boundary particles: a point of the lattice of spacing " +
                    formatted("%g", s.spacing) + " m inside the domain and the shape",
                "none (a shape spanning " + text<Dim>(lo) + " to " + text<Dim>(hi) + ")",
                "make it at least one spacing thick, or refine particles.spacing");
    };
    for (std::size_t j = 0; j < s.bodies.size(); ++j)
        check(s.bodies[j], "bodies[" + std::to_string(j) + "]", "body");
    for (std::size_t j = 0; j < s.walls.size(); ++j)
        check(s.walls[j], "walls[" + std::to_string(j) + "]", "wall");
    for (std::size_t j = 0; j < s.bodies.size(); ++j)
        if (s.bodies[j].motion.type != sph::MotionType::FIXED) checkMovingBodyClear(s, j);
}

/// Emitter i's nozzle is at least one spacing wide and no wider than the domain.
template <int Dim>
void checkEmitterRadius(const Scene<Dim>& s, std::size_t i) {
    const Emitter<Dim>& e = s.emitters[i];
    double extent = 0;
    for (int k = 0; k < Dim; ++k) extent = std::max(extent, s.domainMax[k] - s.domainMin[k]);
    if (2 * e.radius < s.spacing || 2 * e.radius > extent)
        throw sceneError(s.file, "emitters[" + std::to_string(i) + "].radius",
                         "a radius of at least half the spacing (" +
                             formatted("%g", s.spacing / 2) +
                             " m) and at most half the domain's largest extent (" +
                             formatted("%g", extent / 2) + " m)",
                         formatted("%g", e.radius) + " m");
}

/// Every emitter lies inside the domain, with a nozzle at least one spacing wide and no wider
/// than the domain (which bounds the set-up's work), not wholly inside bodies and walls.
template <int Dim>
void checkEmitters(const Scene<Dim>& s) {
    for (std::size_t i = 0; i < s.emitters.size(); ++i) {
        const Emitter<Dim>& e = s.emitters[i];
        if (!insideDomain(s, e.position, e.position))
            throw sceneError(s.file, "emitters[" + std::to_string(i) + "].position",
                             "a point inside " + domainText(s), text<Dim>(e.position));
        checkEmitterRadius(s, i);
        if (const Nozzle<Dim> nozzle = openNozzle(s, i); nozzle.open.empty())
            throw sceneError(
                s.file, "emitters[" + std::to_string(i) + "].position",
                "a nozzle with points at least half a spacing outside every body "
                "and wall",
                text<Dim>(e.position) + ": every nozzle point is in or next to " + nozzle.cutBy,
                "move the nozzle into the open");
    }
}

/// A probe's body or wall index names one of the scene's (`what`: "bodies" or "walls").
template <int Dim>
void checkProbeIndex(const Scene<Dim>& s, std::size_t i, const char* key, int index,
                     std::size_t count, const char* what) {
    if (index >= int(count))
        throw sceneError(
            s.file, "probes[" + std::to_string(i) + "]." + key,
            "the index of one of the scene's " + std::to_string(count) + " " + what + " (from 0)",
            std::to_string(index));
}

/// The key at path names another of the scene's bodies than body b (-1: none, the world).
template <int Dim>
void checkOtherBody(const Scene<Dim>& s, std::size_t b, int other, const std::string& path) {
    if (other < int(s.bodies.size()) && other != int(b)) return;
    throw sceneError(s.file, path,
                     "the index of another of the scene's " + std::to_string(s.bodies.size()) +
                         " bodies (from 0)",
                     std::to_string(other));
}

/// A spring's anchor_body and a hinge's hinge_body name another of the scene's bodies.
template <int Dim>
void checkBodyLinks(const Scene<Dim>& s) {
    for (std::size_t b = 0; b < s.bodies.size(); ++b) {
        const BodyMotionSpec<Dim>& m = s.bodies[b].motion;
        const std::string motion = "bodies[" + std::to_string(b) + "].motion.";
        for (std::size_t k = 0; k < m.springs.size(); ++k)
            checkOtherBody(s, b, m.springs[k].anchorBody,
                           motion + "springs[" + std::to_string(k) + "].anchor_body");
        checkOtherBody(s, b, m.hingeBody, motion + "hinge_body");
    }
}

template <int Dim>
void checkProbes(const Scene<Dim>& s) {
    for (std::size_t i = 0; i < s.probes.size(); ++i) {
        const Probe<Dim>& p = s.probes[i];
        checkProbeIndex(s, i, "body", p.body, s.bodies.size(), "bodies");
        checkProbeIndex(s, i, "wall", p.wall, s.walls.size(), "walls");
        if (p.body < 0 && p.wall < 0 && !insideDomain(s, p.point, p.point))
            throw sceneError(s.file, "probes[" + std::to_string(i) + "].point",
                             "a point inside " + domainText(s), text<Dim>(p.point));
    }
}

/// The scene makes fluid particles, at most 20 million of them at the start.
template <int Dim>
void checkFluidAmount(const Scene<Dim>& s, double estimate) {
    if (s.fluids.empty() && s.emitters.empty())
        throw sceneError(s.file, "fluids",
                         "at least one fluid block or emitter (the scene has no fluid particles)",
                         "none",
                         "add a block such as {\"material\": \"water\", \"shape\": \"box\", "
                         "\"min\": [...], \"max\": [...]}");
    if (estimate > 2e7)
        throw sceneError(
            s.file, "particles.spacing", "a spacing giving at most 20 million fluid particles",
            formatted("%g", s.spacing) + " (about " + formatted("%.3g", estimate) + " particles)",
            "increase the spacing");
}

/// Every periodic axis is at least twice the largest kernel support (2h) long and a whole
/// number of spacings.
template <int Dim>
void checkPeriodicAxes(const Scene<Dim>& s) {
    const double support = 2.0 * s.hOverSpacing * s.spacing;
    for (int k = 0; k < Dim; ++k)
        if (s.sides[k][0]->wraps() && s.domainMax[k] - s.domainMin[k] < 2 * support)
            throw sceneError(s.file, std::string("boundaries.") + sideName(k, 0),
                             "a periodic axis at least twice the kernel support (" +
                                 std::to_string(2 * support) + " m) long",
                             std::to_string(s.domainMax[k] - s.domainMin[k]) + " m");
    for (int k = 0; k < Dim; ++k) {
        const double cells = (s.domainMax[k] - s.domainMin[k]) / s.spacing;
        if (s.sides[k][0]->wraps() && std::abs(cells - std::round(cells)) > 1e-6 * cells)
            throw sceneError(s.file, "particles.spacing",
                             "a spacing that divides the periodic length " +
                                 std::to_string(s.domainMax[k] - s.domainMin[k]) + " m of axis " +
                                 std::to_string(k),
                             std::to_string(s.spacing),
                             "use " + std::to_string((s.domainMax[k] - s.domainMin[k]) /
                                                     std::max(1.0, std::round(cells))));
    }
}

}  // namespace

template <int Dim>
void checkSceneGeometry(const Scene<Dim>& s) {
    checkSpacing(s);
    checkBodiesAndWalls(s);  // first: a fluid block is cut by them (a body far out, named)
    const double estimate = checkFluidBlocks(s);
    checkEmitters(s);
    checkProbes(s);
    checkBodyLinks(s);
    checkFluidAmount(s, estimate);
    checkPeriodicAxes(s);
    checkFlowSides(s);
}

template void checkSceneGeometry<2>(const Scene<2>&);
template void checkSceneGeometry<3>(const Scene<3>&);

}  // namespace num::app
