#include "scene/flow_sides.hpp"

#include <algorithm>
#include <cmath>

#include "io/errors.hpp"
#include "io/formatted.hpp"
#include "sph/boundary/inlet_outlet_boundary.hpp"

namespace num::io {

namespace {

template <int Dim>
const sph::InletOutletBoundary<Dim>* flowSideAt(const Scene<Dim>& scene, int axis, int high) {
    return dynamic_cast<const sph::InletOutletBoundary<Dim>*>(scene.sides[axis][high].get());
}

/// Calls f(x, t) for the lattice points of side `high` of `axis` (on the side's plane) at 21
/// times from 0 to the end time.
template <int Dim, class F>
void forEachSideSample(const Scene<Dim>& scene, int axis, int high, F&& f) {
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
            f(x, t);
            int k = 0;
            while (k < Dim && ++i[k] == n[k]) i[k++] = 0;
            if (k == Dim) break;
        }
    }
}

template <int Dim>
std::string pointText(const sph::Vector<Dim>& x) {
    std::string text = "(" + formatted("%g", x[0]);
    for (int k = 1; k < Dim; ++k) text += ", " + formatted("%g", x[k]);
    return text + ")";
}

}  // namespace

template <int Dim>
std::shared_ptr<sph::FlowBoundaries<Dim>> makeFlowBoundaries(const Scene<Dim>& scene,
                                                             const sph::FluidGeometry<Dim>& geo,
                                                             int wallLayers) {
    auto flow = std::make_shared<sph::FlowBoundaries<Dim>>();
    for (int k = 0; k < Dim; ++k)
        for (int hi = 0; hi < 2; ++hi)
            if (const auto* side = flowSideAt(scene, k, hi))
                flow->sides.push_back(
                    side->flowSide(geo.domain, k, hi, wallLayers * scene.spacing));
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

template <int Dim>
void checkInflows(const Scene<Dim>& scene) {
    for (int k = 0; k < Dim; ++k)
        for (int hi = 0; hi < 2; ++hi) {
            const auto* side = flowSideAt(scene, k, hi);
            if (!side || side->kind() != sph::ParticleKind::INLET) continue;
            const sph::FlowSide<Dim> spec = side->flowSide({}, k, hi, 0);
            forEachSideSample(scene, k, hi, [&](const sph::Vector<Dim>& x, double t) {
                const double out = dot(spec.velocity(x, t), spec.outward());
                if (!(out <= 1e-12 * (1 + norm(spec.velocity(x, t)))))
                    throw sceneError(
                        scene.file, std::string("boundaries.") + sideName(k, hi) + ".velocity",
                        "a velocity into the domain (an inlet's water enters)",
                        formatted("%g m/s out of it", out) + " at t = " + formatted("%g", t) +
                            " s, " + pointText(x),
                        "give the velocity the sign that points into the domain, or make the "
                        "side an outlet");
            });
        }
}

template std::shared_ptr<sph::FlowBoundaries<2>> makeFlowBoundaries<2>(const Scene<2>&,
                                                                       const sph::FluidGeometry<2>&,
                                                                       int);
template std::shared_ptr<sph::FlowBoundaries<3>> makeFlowBoundaries<3>(const Scene<3>&,
                                                                       const sph::FluidGeometry<3>&,
                                                                       int);
template double largestInflowSpeed<2>(const Scene<2>&);
template double largestInflowSpeed<3>(const Scene<3>&);
template void checkInflows<2>(const Scene<2>&);
template void checkInflows<3>(const Scene<3>&);

}  // namespace num::io
