// Blocks of the pair loop share what block 0's derivatives precomputed per particle
// (IDerivative::initializeLike): checked against every block initialising itself.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "numerics.hpp"
#include "sph/terms/free_surface.hpp"
#include "test_physics.hpp"

namespace {

using namespace num::sph;
using V2 = Vector<2>;

/// Random particles with kinds, volumes and previous kernel sums such that some fluid
/// particles were at a free surface and some were not.
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
    return s;
}

/// Every particle's sum over all others within `radius`, as one block of the asymmetric loop.
template <class Holder>
void evaluateAll(Holder& holder, const Storage<2>& s, Float radius) {
    const auto x = s.getValue<V2>(QuantityId::POSITION);
    for (Size i = 0; i < s.size(); ++i) {
        std::vector<Size> j;
        std::vector<V2> dx, grad;
        std::vector<Float> r, w;
        for (Size k = 0; k < s.size(); ++k) {
            const Float d = num::norm(x[i] - x[k]);
            if (k == i || d >= radius) continue;
            j.push_back(k), dx.push_back(x[i] - x[k]), grad.push_back(V2{}), r.push_back(d);
            w.push_back(1 - d / radius);
        }
        const NeighbourGeometry<2> geometry{ArrayView<const V2>(dx.data(), dx.size()),
                                            ArrayView<const Float>(r.data(), r.size()),
                                            ArrayView<const Float>(w.data(), w.size())};
        holder.evalAsymmetric(i, ArrayView<const Size>(j.data(), j.size()),
                              ArrayView<const V2>(grad.data(), grad.size()), geometry);
    }
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

}  // namespace
