// The pair loop's optimised paths against plain ones, bitwise: blocks sharing what block 0's
// derivatives precomputed per particle (IDerivative::initializeLike) against every block
// initialising itself, and the fluid parts' gather loops (gatherNeighbours) against the
// generic loop calling eval for one pair at a time.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "numerics.hpp"
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
using V2 = Vector<2>;

/// Random particles with kinds, volumes and previous kernel sums such that some fluid
/// particles were at a free surface and some were not.
/// The volumes and pair velocities the fluid parts read, as the fluid model's PairInputs
/// prepares them each evaluation.
void preparePairInputs(Storage<2>& s) {
    SequentialScheduler scheduler;
    PairInputs<2>().initialize(scheduler, s, 0.0);
}

Storage<2> particlesWithSurface() {
    Storage<2> s = enginetest::randomParticles<2>(300, 11);
    std::vector<int> kind(s.size());
    std::vector<Float> previous(s.size());
    for (Size i = 0; i < s.size(); ++i) {
        kind[i] = i % 5 == 0 ? int(ParticleKind::WALL) : int(ParticleKind::FLUID);
        previous[i] = i % 3 == 0 ? 0.1 : 2.0;
    }
    s.insert<int>(QuantityId::KIND, OrderEnum::ZERO, kind);
    s.insert<Float>(FluidId::KERNEL_SUM, OrderEnum::ZERO, previous);
    s.insert<Float>(FluidId::VOLUME, OrderEnum::ZERO, 0.0);
    // The walls show (0.25, -0.5); PairInputs sets the fluid particles' own velocity.
    s.insert<V2>(FluidId::PAIR_VELOCITY, OrderEnum::ZERO, V2{0.25, -0.5});
    preparePairInputs(s);
    return s;
}

/// Calls visit(i, neighbours, gradients, geometry) for every particle with all others within
/// `radius` (brute force; a made-up kernel, nonzero in value and gradient).
template <class Visit>
void forEachParticle(const Storage<2>& s, Float radius, Visit&& visit) {
    const auto x = s.getValue<V2>(QuantityId::POSITION);
    for (Size i = 0; i < s.size(); ++i) {
        std::vector<Size> j;
        std::vector<V2> dx, grad;
        std::vector<Float> r, w, laplacian, inverseR2;
        for (Size k = 0; k < s.size(); ++k) {
            const Float d = num::norm(x[i] - x[k]);
            if (k == i || d >= radius) continue;
            j.push_back(k), dx.push_back(x[i] - x[k]), r.push_back(d);
            grad.push_back((x[i] - x[k]) * (-1 / radius)), w.push_back(1 - d / radius);
            laplacian.push_back(num::dot(dx.back(), grad.back()) /
                                (d * d + 1e-3 * radius * radius));
            inverseR2.push_back(1 / (d * d + 1e-2 * radius * radius));
        }
        const auto view = [](const std::vector<Float>& a) {
            return ArrayView<const Float>(a.data(), a.size());
        };
        const NeighbourGeometry<2> geometry{ArrayView<const V2>(dx.data(), dx.size()), view(r),
                                            view(w), view(laplacian), view(inverseR2)};
        visit(i, ArrayView<const Size>(j.data(), j.size()),
              ArrayView<const V2>(grad.data(), grad.size()), geometry);
    }
}

/// Every particle's sum over all others within `radius`, as one block of the asymmetric loop.
template <class Holder>
void evaluateAll(Holder& holder, const Storage<2>& s, Float radius) {
    forEachParticle(s, radius, [&](Size i, auto neighs, auto grads, const auto& geometry) {
        holder.evalAsymmetric(i, neighs, grads, geometry);
    });
}

template <class Require>
void expectSharedEqualsOwn(Require&& require) {
    Storage<2> s = particlesWithSurface();
    DerivativeHolder<2> first, shared, own;
    require(first), require(shared), require(own);
    Accumulated<2> rFirst, rShared, rOwn;
    first.create(rFirst), shared.create(rShared), own.create(rOwn);
    // Two evaluations: the second with other densities, so a stale copy would show.
    for (int evaluation = 0; evaluation < 2; ++evaluation) {
        for (Accumulated<2>* r : {&rFirst, &rShared, &rOwn}) r->reset(s.size());
        first.initialize(s, rFirst);
        shared.initializeLike(first, s, rShared);
        own.initialize(s, rOwn);
        evaluateAll(shared, s, 0.1);
        evaluateAll(own, s, 0.1);
        double largest = 0;
        for (QuantityId id : {FluidId::KERNEL_SUM, FluidId::SURFACE_NEIGHBOURS}) {
            const auto a = rShared.getValue<Float>(id), b = rOwn.getValue<Float>(id);
            for (Size i = 0; i < s.size(); ++i) {
                EXPECT_EQ(a[i], b[i]) << "evaluation " << evaluation << ", particle " << i;
                largest = std::max(largest, std::abs(b[i]));
            }
        }
        EXPECT_GT(largest, 0.0);  // the sums are not all zero
        for (Float& rho : s.getValue<Float>(QuantityId::DENSITY)) rho *= 1.5;
        preparePairInputs(s);
    }
}

TEST(SharedInitialization, KernelSumSharedEqualsOwnBitwise) {
    expectSharedEqualsOwn([](DerivativeHolder<2>& d) { d.require<KernelSumPart<2>>(0.7); });
}

TEST(SharedInitialization, FusedKernelSumSharedEqualsOwnBitwise) {
    using Fused = FusedDerivative<2, OptionalPart<KernelSumPart<2>, 2>>;
    expectSharedEqualsOwn([](DerivativeHolder<2>& d) {
        d.require(
            std::make_unique<Fused>(OptionalPart<KernelSumPart<2>, 2>(KernelSumPart<2>(0.7))));
    });
}

/// The sums the parts below accumulate, by type, and the nonzero values each starts from (as
/// after an earlier part of a fused loop).
template <class T>
struct Sums;
template <>
struct Sums<Float> {
    static inline const std::vector<QuantityId> ids = {QuantityId::DENSITY, QuantityId::TEMPERATURE,
                                                       FluidId::KERNEL_SUM,
                                                       FluidId::SURFACE_NEIGHBOURS};
    static Float start(Size i) { return 0.1 * Float(i % 7); }
};
template <>
struct Sums<V2> {
    static inline const std::vector<QuantityId> ids = {
        QuantityId::POSITION,    FluidId::KERNEL_SUM_GRADIENT, FluidId::DENSITY_GRADIENT,
        FluidId::WALL_DIRECTION, velocityGradientId<2>(0),     velocityGradientId<2>(1)};
    static V2 start(Size i) { return V2{0.3 * Float(i % 5), -0.2 * Float(i % 3)}; }
};

template <class T>
void setStartingSums(Accumulated<2>& r) {
    for (QuantityId id : Sums<T>::ids)
        if (r.has(id))
            for (Size i = 0; auto& x : r.getValue<T>(id)) x = Sums<T>::start(i++);
}

/// Every sum of type T bitwise the same in both, and changed from its start for most particles.
template <class T>
void expectSumsEqual(Accumulated<2>& gather, Accumulated<2>& pairs, Size n,
                     const std::string& part) {
    for (QuantityId id : Sums<T>::ids) {
        if (!pairs.has(id)) continue;
        std::size_t changed = 0;
        const auto a = gather.getValue<T>(id), b = pairs.getValue<T>(id);
        for (Size i = 0; i < n; ++i) {
            EXPECT_EQ(a[i], b[i]) << part << ", particle " << i;
            changed += b[i] != Sums<T>::start(i);
        }
        // The wall direction sums wall neighbours only; the others every neighbour.
        const std::size_t least = id == FluidId::WALL_DIRECTION ? n / 4 : n / 2;
        EXPECT_GT(changed, least) << part << ", quantity " << int(id);
    }
}

/// A part's gather loop against the generic loop of its DerivativeTemplate (eval per pair),
/// both starting from the same nonzero sums.
template <class Part>
void expectGatherEqualsPairByPair(Part gather, Part pairByPair, const Storage<2>& s) {
    Accumulated<2> rGather, rPairs;
    gather.create(rGather), pairByPair.create(rPairs);
    for (Accumulated<2>* r : {&rGather, &rPairs}) {
        r->reset(s.size());
        setStartingSums<Float>(*r), setStartingSums<V2>(*r);
    }
    gather.initialize(s, rGather), pairByPair.initialize(s, rPairs);
    forEachParticle(s, 0.12, [&](Size i, auto neighs, auto grads, const auto& geometry) {
        gather.template evalNeighbours<false>(i, neighs, grads, geometry);
        for (std::size_t k = 0; k < neighs.size(); ++k)
            pairByPair.template evalPair<false>(i, neighs[k], grads[k], geometry.pair(k));
    });
    expectSumsEqual<Float>(rGather, rPairs, s.size(), typeName(gather));
    expectSumsEqual<V2>(rGather, rPairs, s.size(), typeName(gather));
}

/// particlesWithSurface with what heat conduction reads: temperatures, two materials, and
/// every thermal condition (one particle in six at a fixed temperature, one in eleven
/// adiabatic).
Storage<2> particlesWithHeat() {
    Storage<2> s = particlesWithSurface();
    std::vector<Float> T(s.size()), Tb(s.size());
    std::vector<int> material(s.size()), condition(s.size());
    for (Size i = 0; i < s.size(); ++i) {
        T[i] = 20 + Float(i % 13), Tb[i] = 80 - Float(i % 5);
        material[i] = int(i % 2);
        condition[i] = i % 6 == 0    ? int(ThermalCondition::FIXED_TEMPERATURE)
                       : i % 11 == 0 ? int(ThermalCondition::ADIABATIC)
                                     : int(ThermalCondition::CONDUCTING);
    }
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
    return s;
}

/// Particle data for the fluid parts beyond the storage's velocities, volumes and pair
/// velocities: pressures, viscosities; one particle in seven a free-slip wall particle
/// (inactive in the viscous term).
struct FluidPartData {
    explicit FluidPartData(const Storage<2>& s) {
        const auto rho = s.getValue<Float>(QuantityId::DENSITY);
        const auto p = s.getValue<Float>(QuantityId::PRESSURE);
        for (Size i = 0; i < s.size(); ++i) {
            pressure->pOverRho2.push_back(p[i] / (rho[i] * rho[i]));
            viscous->mu.push_back(1e-3 * (1 + Float(i % 4)));
            viscous->active.push_back(i % 7 != 3);
        }
        delta->gravityTerm = V2{0.0, -0.3};
    }
    std::shared_ptr<DeltaSphData<2>> delta = std::make_shared<DeltaSphData<2>>();
    std::shared_ptr<PressureGradientData> pressure = std::make_shared<PressureGradientData>();
    std::shared_ptr<ViscousData<2>> viscous = std::make_shared<ViscousData<2>>();
};

TEST(GatherLoops, FluidPartsEqualTheirPairByPairEvaluationBitwise) {
    const Storage<2> s = particlesWithSurface();
    const FluidPartData d(s);
    const Float h = 0.05, c0 = 10;
    expectGatherEqualsPairByPair(ContinuityDensityPart<2>(), ContinuityDensityPart<2>(), s);
    expectGatherEqualsPairByPair(DeltaSphPart<2>(d.delta, 0.1, c0, h),
                                 DeltaSphPart<2>(d.delta, 0.1, c0, h), s);
    expectGatherEqualsPairByPair(PressureGradientPart<2>(d.pressure),
                                 PressureGradientPart<2>(d.pressure), s);
    expectGatherEqualsPairByPair(ArtificialViscosityPart<2>(0.1, c0, h),
                                 ArtificialViscosityPart<2>(0.1, c0, h), s);
    expectGatherEqualsPairByPair(LaminarViscosityPart<2>(d.viscous),
                                 LaminarViscosityPart<2>(d.viscous), s);
    expectGatherEqualsPairByPair(KernelSumPart<2>(0.7), KernelSumPart<2>(0.7), s);
    auto shifting = std::make_shared<ShiftingData<2>>();
    for (Size i = 0; i < s.size(); ++i)  // some pairs closer than the local spacing
        shifting->inverseWAtSpacing.push_back(1.2 + 0.1 * Float(i % 3));
    expectGatherEqualsPairByPair(ParticleShiftingPart<2>(shifting),
                                 ParticleShiftingPart<2>(shifting), s);
    const Storage<2> heat = particlesWithHeat();
    expectGatherEqualsPairByPair(HeatConductionDerivative<2>(), HeatConductionDerivative<2>(),
                                 heat);
}

}  // namespace
