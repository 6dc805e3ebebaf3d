// The shared formulas (include/sph/formulas/) against the engine's pair parts: each built-in
// part's gather (gatherNeighbours) and its symmetric evaluation (eval<true>, each pair once)
// equal, bitwise, a plain loop over the formula functions in the same order; and the two
// evaluations agree to round-off. The CUDA kernels call the same functions, so this checks
// what they compute too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "numerics.hpp"
#include "sph/formulas/fluid_pairs.hpp"
#include "sph/formulas/heat_pairs.hpp"
#include "sph/formulas/pair_geometry.hpp"
#include "sph/terms/artificial_viscosity.hpp"
#include "sph/terms/continuity_density.hpp"
#include "sph/terms/delta_sph.hpp"
#include "sph/terms/free_surface.hpp"
#include "sph/terms/heat_conduction.hpp"
#include "sph/terms/laminar_viscosity.hpp"
#include "sph/terms/pair_inputs.hpp"
#include "sph/terms/particle_shifting.hpp"
#include "sph/terms/pressure_gradient.hpp"
#include "test_physics.hpp"

namespace {

using namespace num::sph;
namespace f = num::sph::formulas;
using V2 = Vector<2>;
using Kernel = num::kernels::CubicSpline<2>;

constexpr Float h = 0.04, c0 = 10, alpha = 0.1, delta = 0.1;

/// 250 random particles: one in five a wall, volumes and pair velocities as PairInputs makes
/// them, previous kernel sums with some particles at a free surface, and what conduction reads
/// (two materials, every thermal condition).
Storage<2> particles() {
    Storage<2> s = enginetest::randomParticles<2>(250, 5);
    std::vector<int> kind(s.size()), material(s.size()), condition(s.size());
    std::vector<Float> previous(s.size()), T(s.size()), Tb(s.size());
    for (Size i = 0; i < s.size(); ++i) {
        kind[i] = i % 5 == 0 ? int(ParticleKind::WALL) : int(ParticleKind::FLUID);
        previous[i] = i % 3 == 0 ? 0.1 : 2.0;
        T[i] = 20 + Float(i % 13), Tb[i] = 80 - Float(i % 5), material[i] = int(i % 2);
        condition[i] = i % 6 == 0    ? int(ThermalCondition::FIXED_TEMPERATURE)
                       : i % 11 == 0 ? int(ThermalCondition::ADIABATIC)
                                     : int(ThermalCondition::CONDUCTING);
    }
    s.insert<int>(QuantityId::KIND, OrderEnum::ZERO, kind);
    s.insert<Float>(FluidId::KERNEL_SUM, OrderEnum::ZERO, previous);
    s.insert<Float>(FluidId::VOLUME, OrderEnum::ZERO, 0.0);
    s.insert<V2>(FluidId::PAIR_VELOCITY, OrderEnum::ZERO, V2{0.25, -0.5});
    s.insert<Float>(QuantityId::TEMPERATURE, OrderEnum::FIRST, T);
    s.insert<Float>(heat_ids::BOUNDARY_TEMPERATURE, OrderEnum::ZERO, Tb);
    s.insert<int>(QuantityId::MATERIAL, OrderEnum::ZERO, material);
    s.insert<int>(heat_ids::THERMAL_CONDITION, OrderEnum::ZERO, condition);
    for (const Float k : {0.6, 45.0}) {
        auto m = std::make_shared<Material>("material");
        m->params().set("conductivity", k).set("heat_capacity", 4186.0 / k);
        m->params().set("density", 1000.0).set("thermal_expansion", 0.0);
        m->params().set("reference_temperature", 20.0);
        s.materials().push_back(m);
    }
    SequentialScheduler scheduler;
    PairInputs<2>().initialize(scheduler, s, 0.0);
    return s;
}

/// The neighbours of every particle within the support (all of them for the gather, those
/// after it for the symmetric evaluation) with the geometry the solver's pair loop computes.
struct Neighbours {
    std::vector<Size> j;
    std::vector<V2> dx, grad;
    std::vector<Float> r, w, laplacian, inverseR2;
    NeighbourGeometry<2> geometry() const {
        const auto view = [](const std::vector<Float>& a) { return std::span(a); };
        return {std::span(dx), view(r), view(w), view(laplacian), view(inverseR2)};
    }
};
Neighbours neighboursOf(const Storage<2>& s, Size i, bool symmetric) {
    const auto x = s.getValue<V2>(QuantityId::POSITION);
    const GradientFactor<Kernel> gradient(h);
    const KernelValue<Kernel> kernelValue(h);
    Neighbours n;
    for (Size j = symmetric ? i + 1 : 0; j < s.size(); ++j) {
        const V2 dx = x[i] - x[j];
        const Float r = std::sqrt(num::normSqr(dx));
        if (j == i || r >= Kernel::supportRadius(h)) continue;
        const V2 grad = dx * gradient.factor(r);
        n.j.push_back(j), n.dx.push_back(dx), n.grad.push_back(grad), n.r.push_back(r);
        n.w.push_back(kernelValue.value(r));
        n.laplacian.push_back(f::pairLaplacian(dx, grad, r, 1e-3 * h * h));
        n.inverseR2.push_back(f::pairInverseR2(r, 1e-2 * h * h));
    }
    return n;
}

/// The plain loop: pair(i, j, grad, geometry, symmetric, out) over the same pairs, in order.
using Sums = std::vector<std::vector<Float>>;  // one array per scalar sum (vector components)
using PairFormula = std::function<void(Size, Size, const V2&, const PairGeometry<2>&, bool, Sums&)>;

/// The part's sums (every component of every id) after one evaluation of all particles.
template <class Part>
Sums evaluate(Part part, const Storage<2>& s, bool symmetric, const std::vector<QuantityId>& ids,
              bool vectors) {
    Accumulated<2> r;
    part.create(r);
    r.reset(s.size());
    part.initialize(s, r);
    for (Size i = 0; i < s.size(); ++i) {
        const Neighbours n = neighboursOf(s, i, symmetric);
        if (symmetric)
            part.template evalNeighbours<true>(i, n.j, n.grad, n.geometry());
        else
            part.template evalNeighbours<false>(i, n.j, n.grad, n.geometry());
    }
    Sums out;
    for (QuantityId id : ids) {
        if (!vectors) {
            const auto v = r.getValue<Float>(id);
            out.emplace_back(v.begin(), v.end());
            continue;
        }
        const auto v = r.getValue<V2>(id);
        for (int c = 0; c < 2; ++c) {
            out.emplace_back();
            for (const V2& x : v) out.back().push_back(x[c]);
        }
    }
    return out;
}

Sums plainLoop(const Storage<2>& s, bool symmetric, std::size_t sums, const PairFormula& pair) {
    Sums out(sums, std::vector<Float>(s.size(), 0.0));
    for (Size i = 0; i < s.size(); ++i) {
        const Neighbours n = neighboursOf(s, i, symmetric);
        for (std::size_t k = 0; k < n.j.size(); ++k)
            pair(i, n.j[k], n.grad[k], n.geometry().pair(k), symmetric, out);
    }
    return out;
}

/// Part against the plain loop, bitwise, in both evaluations; the two evaluations to round-off.
template <class MakePart>
void expectFormulas(const std::string& name, const Storage<2>& s, MakePart make,
                    const std::vector<QuantityId>& ids, bool vectors, const PairFormula& pair) {
    const std::size_t count = ids.size() * (vectors ? 2 : 1);
    Sums result[2];
    for (const bool symmetric : {false, true}) {
        result[symmetric] = evaluate(make(), s, symmetric, ids, vectors);
        const Sums plain = plainLoop(s, symmetric, count, pair);
        std::size_t nonzero = 0;
        for (std::size_t q = 0; q < count; ++q)
            for (Size i = 0; i < s.size(); ++i) {
                ASSERT_EQ(result[symmetric][q][i], plain[q][i])
                    << name << (symmetric ? " symmetric" : " gather") << ", sum " << q
                    << ", particle " << i;
                nonzero += plain[q][i] != 0;
            }
        EXPECT_GT(nonzero, count * s.size() / 2) << name;  // most sums are not trivially zero
    }
    for (std::size_t q = 0; q < count; ++q) {
        Float scale = 0;
        for (Float x : result[0][q]) scale = std::max(scale, std::abs(x));
        for (Size i = 0; i < s.size(); ++i)
            EXPECT_NEAR(result[0][q][i], result[1][q][i], 1e-12 * scale) << name << ", sum " << q;
    }
}

/// Adds vector x to sums (2 c0, 2 c0 + 1) of particle a, with sign.
void addVec(Sums& out, std::size_t c0, Size a, const V2& x, Float sign = 1) {
    if (sign > 0)
        out[c0][a] += x[0], out[c0 + 1][a] += x[1];
    else
        out[c0][a] -= x[0], out[c0 + 1][a] -= x[1];
}

// The fluid parts, a few per helper; each helper reads the fields its formulas use.

/// Continuity and delta-SPH: the density rate.
void expectDensityParts(const Storage<2>& s) {
    const auto rho = s.getValue<Float>(QuantityId::DENSITY);
    const auto kind = s.getValue<int>(QuantityId::KIND);
    const auto V = s.getValue<Float>(FluidId::VOLUME);
    const auto v = s.getDt<V2>(QuantityId::POSITION);
    const auto fluid = [&](Size a) { return isFluid(kind[a]); };
    // Continuity's velocity is every particle's own (a held wall's is zero in a run; a moving
    // body's particle moves with it; these random walls move).
    const auto own = [&](Size a) { return v[a]; };

    expectFormulas(
        "continuity", s, [] { return ContinuityDensityPart<2>(); }, {QuantityId::DENSITY}, false,
        [&](Size i, Size j, const V2& grad, const PairGeometry<2>&, bool sym, Sums& out) {
            const Float div = f::continuityDivergence(own(i), own(j), grad);
            if (fluid(i)) out[0][i] += f::continuityRate(rho[i], V[j], div);
            if (sym && fluid(j)) out[0][j] += f::continuityRate(rho[j], V[i], div);
        });

    auto deltaData = std::make_shared<DeltaSphData<2>>();
    deltaData->gravityTerm = V2{0.0, -0.3};
    const Float coefficient = f::deltaSphCoefficient(delta, c0, h);
    expectFormulas(
        "delta-SPH", s, [&] { return DeltaSphPart<2>(deltaData, delta, c0, h); },
        {QuantityId::DENSITY}, false,
        [&](Size i, Size j, const V2& grad, const PairGeometry<2>& pair, bool sym, Sums& out) {
            if (!fluid(i) || !fluid(j)) return;
            const Float flux = f::deltaSphFlux(coefficient, rho[i], rho[j], deltaData->gravityTerm,
                                               pair.dx, grad, pair.inverseR2);
            out[0][i] += flux * V[j];
            if (sym) out[0][j] -= flux * V[i];
        });
}

/// The pressure gradient and artificial viscosity (accelerations, by the neighbour's mass).
void expectPressureParts(const Storage<2>& s) {
    const auto m = s.getValue<Float>(QuantityId::MASS);
    const auto rho = s.getValue<Float>(QuantityId::DENSITY);
    const auto p = s.getValue<Float>(QuantityId::PRESSURE);
    const auto kind = s.getValue<int>(QuantityId::KIND);
    const auto u = s.getValue<V2>(FluidId::PAIR_VELOCITY);
    const auto fluid = [&](Size a) { return isFluid(kind[a]); };

    auto pressure = std::make_shared<PressureGradientData>();
    for (Size i = 0; i < s.size(); ++i)
        pressure->pOverRho2.push_back(f::pressureOverDensity2(p[i], rho[i]));
    const std::vector<Float>& pr2 = pressure->pOverRho2;
    expectFormulas(
        "pressure gradient", s, [&] { return PressureGradientPart<2>(pressure); },
        {QuantityId::POSITION}, true,
        [&](Size i, Size j, const V2& grad, const PairGeometry<2>&, bool sym, Sums& out) {
            const V2 force = f::pressureGradientForce(grad, pr2[i], pr2[j]);
            if (fluid(i)) addVec(out, 0, i, force * m[j], -1);
            if (sym && fluid(j)) addVec(out, 0, j, force * m[i]);
        });

    expectFormulas(
        "artificial viscosity", s, [] { return ArtificialViscosityPart<2>(alpha, c0, h); },
        {QuantityId::POSITION}, true,
        [&](Size i, Size j, const V2& grad, const PairGeometry<2>& pair, bool sym, Sums& out) {
            const Float vr = f::approachRate(u[i], u[j], pair.dx);
            if (vr >= 0) return;
            const Float pi =
                f::artificialViscosityPi(alpha * c0 * h, vr, pair.inverseR2, rho[i], rho[j]);
            if (fluid(i)) addVec(out, 0, i, grad * pi * m[j], -1);
            if (sym && fluid(j)) addVec(out, 0, j, grad * pi * m[i]);
        });
}

/// Laminar viscosity, with a viscosity per particle and some particles without it.
void expectLaminarViscosityPart(const Storage<2>& s) {
    const auto rho = s.getValue<Float>(QuantityId::DENSITY);
    const auto kind = s.getValue<int>(QuantityId::KIND);
    const auto V = s.getValue<Float>(FluidId::VOLUME);
    const auto u = s.getValue<V2>(FluidId::PAIR_VELOCITY);
    const auto fluid = [&](Size a) { return isFluid(kind[a]); };

    auto viscous = std::make_shared<ViscousData<2>>();
    for (Size i = 0; i < s.size(); ++i) {
        viscous->mu.push_back(f::dynamicViscosity(rho[i], 1e-3 * (1 + Float(i % 4))));
        viscous->active.push_back(i % 7 != 3);
    }
    expectFormulas(
        "laminar viscosity", s, [&] { return LaminarViscosityPart<2>(viscous); },
        {QuantityId::POSITION}, true,
        [&](Size i, Size j, const V2&, const PairGeometry<2>& pair, bool sym, Sums& out) {
            if (!viscous->active[i] || !viscous->active[j]) return;
            const Float factor =
                f::laminarViscosityFactor(viscous->mu[i], viscous->mu[j], pair.laplacian);
            const V2 dv = u[i] - u[j];
            if (fluid(i))
                addVec(out, 0, i, f::laminarViscosityAcceleration(dv, factor, V[j], 1 / rho[i]));
            if (sym && fluid(j))
                addVec(out, 0, j, f::laminarViscosityAcceleration(dv, factor, V[i], 1 / rho[j]),
                       -1);
        });
}

/// The kernel sum, and its part over the neighbours at a free surface.
void expectKernelSumPart(const Storage<2>& s) {
    const auto kind = s.getValue<int>(QuantityId::KIND);
    const auto V = s.getValue<Float>(FluidId::VOLUME);
    const auto fluid = [&](Size a) { return isFluid(kind[a]); };
    // With V ~ 1 and the previous sums of particles(), W(0) = 0.7 puts a third at a surface.
    const Float w0 = 0.7;
    const auto previous = s.getValue<Float>(FluidId::KERNEL_SUM);
    const auto atSurface = [&](Size a) { return fluid(a) && atFreeSurface(previous[a], V[a], w0); };
    expectFormulas(
        "kernel sum", s, [&] { return KernelSumPart<2>(w0); },
        {FluidId::KERNEL_SUM, FluidId::SURFACE_NEIGHBOURS}, false,
        [&](Size i, Size j, const V2&, const PairGeometry<2>& pair, bool sym, Sums& out) {
            out[0][i] += f::kernelSumWeight(V[j], pair.w);
            if (atSurface(j)) out[1][i] += f::kernelSumWeight(V[j], pair.w);
            if (!sym) return;
            out[0][j] += f::kernelSumWeight(V[i], pair.w);
            if (atSurface(i)) out[1][j] += f::kernelSumWeight(V[i], pair.w);
        });
}

/// Particle shifting: the gradients of the kernel sum, density and velocity, and the direction
/// to the walls.
void expectShiftingPart(const Storage<2>& s) {
    const auto rho = s.getValue<Float>(QuantityId::DENSITY);
    const auto kind = s.getValue<int>(QuantityId::KIND);
    const auto V = s.getValue<Float>(FluidId::VOLUME);
    const auto u = s.getValue<V2>(FluidId::PAIR_VELOCITY);
    const auto fluid = [&](Size a) { return isFluid(kind[a]); };

    auto shifting = std::make_shared<ShiftingData<2>>();
    for (Size i = 0; i < s.size(); ++i)  // some pairs closer than the local spacing
        shifting->inverseWAtSpacing.push_back((1.2 + 0.1 * Float(i % 3)) / Kernel::W(0, h));
    const std::vector<Float>& invW = shifting->inverseWAtSpacing;
    expectFormulas(
        "particle shifting", s, [&] { return ParticleShiftingPart<2>(shifting); },
        {FluidId::KERNEL_SUM_GRADIENT, FluidId::DENSITY_GRADIENT, FluidId::WALL_DIRECTION,
         velocityGradientId<2>(0), velocityGradientId<2>(1)},
        true,
        [&](Size i, Size j, const V2& grad, const PairGeometry<2>& pair, bool sym, Sums& out) {
            const V2 gradR = grad * f::shiftingTensileFactor(pair.w, invW[i], invW[j]);
            const V2 dv = u[j] - u[i];
            const Float drho = rho[j] - rho[i];
            addVec(out, 0, i, gradR * V[j]);
            addVec(out, 2, i, f::densityGradientTerm(grad, V[j], drho));
            if (!fluid(j)) addVec(out, 4, i, grad * V[j]);
            for (int b = 0; b < 2; ++b)
                addVec(out, 6 + 2 * b, i, f::velocityGradientTerm(dv, V[j], grad[b]));
            if (!sym) return;
            if (!fluid(i)) addVec(out, 4, j, grad * V[i], -1);
            addVec(out, 0, j, gradR * V[i], -1);
            addVec(out, 2, j, f::densityGradientTerm(grad, V[i], drho));
            for (int b = 0; b < 2; ++b)
                addVec(out, 6 + 2 * b, j, f::velocityGradientTerm(dv, V[i], grad[b]));
        });
}

TEST(Formulas, FluidPartsAreAPlainLoopOverTheFormulasBitwise) {
    const Storage<2> s = particles();
    expectDensityParts(s);
    expectPressureParts(s);
    expectLaminarViscosityPart(s);
    expectKernelSumPart(s);
    expectShiftingPart(s);
}

TEST(Formulas, HeatConductionIsAPlainLoopOverTheFormulasBitwise) {
    const Storage<2> s = particles();
    const auto m = s.getValue<Float>(QuantityId::MASS);
    const auto rho = s.getValue<Float>(QuantityId::DENSITY);
    const auto T = s.getValue<Float>(QuantityId::TEMPERATURE);
    const auto Tb = s.getValue<Float>(heat_ids::BOUNDARY_TEMPERATURE);
    const auto mat = s.getValue<int>(QuantityId::MATERIAL);
    const auto cond = s.getValue<int>(heat_ids::THERMAL_CONDITION);
    const Float k[2] = {0.6, 45.0}, invC[2] = {1 / (4186.0 / 0.6), 1 / (4186.0 / 45.0)};
    const auto shown = [&](Size a) { return f::conductionTemperature(cond[a], T[a], Tb[a]); };
    expectFormulas(
        "heat conduction", s, [] { return HeatConductionDerivative<2>(); },
        {QuantityId::TEMPERATURE}, false,
        [&](Size a, Size b, const V2&, const PairGeometry<2>& pair, bool sym, Sums& out) {
            if (!conductsHeat(cond[a], cond[b])) return;
            const Float ka = k[mat[a]], kb = k[mat[b]];
            const Float exchange =
                f::heatExchange(ka, kb, rho[a], rho[b], shown(a), shown(b), pair.laplacian);
            out[0][a] += f::heatRate(m[b], exchange, invC[mat[a]]);
            if (sym) out[0][b] -= f::heatRate(m[a], exchange, invC[mat[b]]);
        });
}

}  // namespace
