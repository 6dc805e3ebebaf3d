#include "scene/flow_sides.hpp"

#include <algorithm>
#include <cmath>

#include "app/errors.hpp"
#include "app/formatted.hpp"
#include "sph/boundary/inlet_outlet_boundary.hpp"

namespace num::app {

namespace {

template <int Dim>
const sph::InletOutletBoundary<Dim>* flowSideAt(const Scene<Dim>& scene, int axis, int high) {
    return dynamic_cast<const sph::InletOutletBoundary<Dim>*>(scene.sides[axis][high].get());
}

/// A point as text: (x, y) or (x, y, z).
template <int Dim>
std::string pointText(const sph::Vector<Dim>& x) {
    std::string text = "(" + formatted("%g", x[0]);
    for (int k = 1; k < Dim; ++k) text += ", " + formatted("%g", x[k]);
    return text + ")";
}

/// Calls f(x, t) for the lattice points of side `high` of `axis` (on the side's plane) across
/// its opening, at 21 times from 0 to the end time.
template <int Dim, class F>
void forEachSideSample(const Scene<Dim>& scene, int axis, int high, F&& f) {
    const sph::FlowSide<Dim>& spec = flowSideAt(scene, axis, high)->spec();
    std::array<long, Dim> n{};
    for (int k = 0; k < Dim; ++k)
        n[k] = k == axis ? 1
                         : std::max(1L, std::lround((scene.domainMax[k] - scene.domainMin[k]) /
                                                    scene.spacing));
    constexpr int times = 21;
    for (int step = 0; step < times; ++step) {
        const double t = scene.endTime * step / (times - 1);
        std::array<long, Dim> i{};
        for (;;) {
            sph::Vector<Dim> x;
            for (int k = 0; k < Dim; ++k)
                x[k] = k == axis ? (high ? scene.domainMax[k] : scene.domainMin[k])
                                 : scene.domainMin[k] + (double(i[k]) + 0.5) * scene.spacing;
            bool across = true;
            for (int k = 0; k < Dim; ++k)
                across &= k == axis || (x[k] >= spec.openFrom[k] && x[k] <= spec.openTo[k]);
            if (across) f(x, t);
            int k = 0;
            while (k < Dim && ++i[k] == n[k]) i[k++] = 0;
            if (k == Dim) break;
        }
    }
}

}  // namespace

template <int Dim>
std::shared_ptr<sph::FlowBoundaries<Dim>> makeFlowBoundaries(const Scene<Dim>& scene,
                                                             const sph::FluidGeometry<Dim>& geo,
                                                             int wallLayers,
                                                             double backgroundPressure) {
    auto flow = std::make_shared<sph::FlowBoundaries<Dim>>();
    for (int k = 0; k < Dim; ++k)
        for (int hi = 0; hi < 2; ++hi)
            if (const auto* side = flowSideAt(scene, k, hi)) {
                auto spec = side->flowSide(geo.domain, k, hi, wallLayers * scene.spacing);
                if (spec.kind == sph::ParticleKind::OUTLET && !spec.pressure)
                    spec.pressure = [backgroundPressure](const sph::Vector<Dim>&, double) {
                        return backgroundPressure;
                    };
                flow->sides.push_back(std::move(spec));
            }
    return flow->sides.empty() ? nullptr : flow;
}

template <int Dim>
double largestInflowSpeed(const Scene<Dim>& scene) {
    double U = 0;
    for (int k = 0; k < Dim; ++k)
        for (int hi = 0; hi < 2; ++hi) {
            const auto* side = flowSideAt(scene, k, hi);
            if (!side || side->kind() != sph::ParticleKind::INLET) continue;
            const sph::FlowSide<Dim> spec = side->flowSide({}, k, hi, 0);
            forEachSideSample(scene, k, hi, [&](const sph::Vector<Dim>& x, double t) {
                U = std::max(U, norm(spec.velocity(x, t)));
            });
        }
    return U;
}

/// An opening's corners lie on the side, span at least two spacings along it and stay
/// within it.
template <int Dim>
void checkOpening(const Scene<Dim>& scene, int axis, int high) {
    const sph::FlowSide<Dim>& spec = flowSideAt(scene, axis, high)->spec();
    if (spec.openFrom[0] < -1e299) return;  // the whole side
    const std::string key = std::string("boundaries.") + sideName(axis, high);
    const double plane = high ? scene.domainMax[axis] : scene.domainMin[axis];
    for (const auto& [name, corner] : {std::pair{"from", spec.openFrom}, {"to", spec.openTo}})
        if (std::abs(corner[axis] - plane) > 1e-9 * (1 + std::abs(plane)))
            throw sceneError(scene.file, key + "." + name,
                             std::string("a point on the side (coordinate ") + "xyz"[axis] + " = " +
                                 formatted("%g", plane) + ")",
                             pointText(corner));
    for (int k = 0; k < Dim; ++k) {
        if (k == axis) continue;
        const bool inside = spec.openFrom[k] >= scene.domainMin[k] - 1e-12 &&
                            spec.openTo[k] <= scene.domainMax[k] + 1e-12;
        if (!inside || spec.openTo[k] - spec.openFrom[k] < 2 * scene.spacing - 1e-12)
            throw sceneError(scene.file, key + ".to",
                             std::string("an opening at least two spacings (") +
                                 formatted("%g", 2 * scene.spacing) + " m) wide along " + "xyz"[k] +
                                 " and within the side (the buffer needs particles across it)",
                             "from " + pointText(spec.openFrom) + " to " + pointText(spec.openTo),
                             "widen it, or refine particles.spacing");
    }
}

template <int Dim>
void checkFlowSides(const Scene<Dim>& scene) {
    for (int k = 0; k < Dim; ++k)
        for (int hi = 0; hi < 2; ++hi) {
            const auto* side = flowSideAt(scene, k, hi);
            if (!side) continue;
            checkOpening(scene, k, hi);
            if (side->kind() != sph::ParticleKind::INLET) continue;
            const sph::FlowSide<Dim> spec = side->flowSide({}, k, hi, 0);
            forEachSideSample(scene, k, hi, [&](const sph::Vector<Dim>& x, double t) {
                const double out = dot(spec.velocity(x, t), spec.outward());
                if (!(out <= 1e-12 * (1 + norm(spec.velocity(x, t)))))
                    throw sceneError(
                        scene.file, std::string("boundaries.") + sideName(k, hi) + ".velocity",
                        "a velocity into the domain (an inlet's water enters)",
                        formatted("%g m/s out of it", out) + " at " + pointText(x) +
                            ", t = " + formatted("%g", t) + " s",
                        "give the velocity the sign that points into the domain, or make the "
                        "side an outlet");
            });
        }
}

template std::shared_ptr<sph::FlowBoundaries<2>> makeFlowBoundaries<2>(const Scene<2>&,
                                                                       const sph::FluidGeometry<2>&,
                                                                       int, double);
template std::shared_ptr<sph::FlowBoundaries<3>> makeFlowBoundaries<3>(const Scene<3>&,
                                                                       const sph::FluidGeometry<3>&,
                                                                       int, double);
template double largestInflowSpeed<2>(const Scene<2>&);
template double largestInflowSpeed<3>(const Scene<3>&);
template void checkFlowSides<2>(const Scene<2>&);
template void checkFlowSides<3>(const Scene<3>&);

}  // namespace num::app
