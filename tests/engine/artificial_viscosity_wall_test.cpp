// The artificial viscosity against a wall (terms/artificial_viscosity.hpp): only the part of
// the relative velocity along the wall's normal counts, so a particle sliding along a wall feels
// no friction from it while one approaching the wall is pushed back; between fluid particles the
// whole relative velocity counts, as in Monaghan (1992).
#include <gtest/gtest.h>

#include <vector>

#include "numerics.hpp"
#include "sph/terms/artificial_viscosity.hpp"

namespace {

using namespace num::sph;
using V2 = Vector<2>;

constexpr double dx = 0.01, h = 1.3 * dx;

/// A floor of 11 boundary particles on y = 0 (normal +y, at rest) and one fluid particle above
/// it, off the lattice so that its pairs are not mirror images; the floor particles are fluid
/// instead where `floorIsFluid`. Returns the artificial viscosity's acceleration of the fluid
/// particle moving at v.
V2 accelerationAbove(const V2& v, bool floorIsFluid = false) {
    std::vector<V2> x, velocity, normal;
    std::vector<int> kind;
    for (int k = -5; k <= 5; ++k) {
        x.push_back(V2{k * dx, 0.0}), velocity.push_back(V2{}), normal.push_back(V2{0.0, 1.0});
        kind.push_back(int(floorIsFluid ? ParticleKind::FLUID : ParticleKind::WALL));
    }
    x.push_back(V2{0.3 * dx, 0.7 * dx}), velocity.push_back(v), normal.push_back(V2{});
    kind.push_back(int(ParticleKind::FLUID));
    const Size fluid = x.size() - 1;

    Storage<2> s;
    s.insert<V2>(QuantityId::POSITION, OrderEnum::SECOND, x);
    s.insert<Float>(QuantityId::MASS, OrderEnum::ZERO, 1000 * dx * dx);
    s.insert<Float>(QuantityId::DENSITY, OrderEnum::ZERO, 1000.0);
    s.insert<int>(QuantityId::KIND, OrderEnum::ZERO, kind);
    s.insert<V2>(FluidId::PAIR_VELOCITY, OrderEnum::ZERO, velocity);
    s.insert<V2>(QuantityId::NORMAL, OrderEnum::ZERO, normal);

    ArtificialViscosityPart<2> part(0.02, 30.0, h);
    Accumulated<2> r;
    part.create(r);
    r.reset(s.size());
    part.initialize(s, r);
    // Every floor particle within 2h, with a gradient along r_ij of a made-up kernel.
    std::vector<Size> neighs;
    std::vector<V2> offsets, grads;
    std::vector<Float> distances, values;
    for (Size j = 0; j < fluid; ++j) {
        const V2 d = x[fluid] - x[j];
        if (num::norm(d) >= 2 * h) continue;
        neighs.push_back(j), offsets.push_back(d), distances.push_back(num::norm(d));
        grads.push_back(d * (-1 / (2 * h))), values.push_back(1 - num::norm(d) / (2 * h));
    }
    EXPECT_GE(neighs.size(), 4u);
    const NeighbourGeometry<2> geometry{ArrayView<const V2>(offsets.data(), offsets.size()),
                                        ArrayView<const Float>(distances.data(), distances.size()),
                                        ArrayView<const Float>(values.data(), values.size())};
    part.gatherNeighbours(fluid, ArrayView<const Size>(neighs.data(), neighs.size()),
                          ArrayView<const V2>(grads.data(), grads.size()), geometry);
    return r.getValue<V2>(QuantityId::POSITION)[fluid];
}

TEST(ArtificialViscosityAtWalls, SlidingAlongAWallFeelsNoFriction) {
    const V2 a = accelerationAbove(V2{1.0, 0.0});
    EXPECT_EQ(a[0], 0.0);
    EXPECT_EQ(a[1], 0.0);
}

TEST(ArtificialViscosityAtWalls, ApproachingAWallIsPushedBack) {
    const V2 approach = accelerationAbove(V2{0.0, -1.0});
    EXPECT_GT(approach[1], 0.0);
    // Its tangential part changes nothing: the same sums of the same numbers.
    const V2 oblique = accelerationAbove(V2{1.0, -1.0});
    EXPECT_EQ(oblique[0], approach[0]);
    EXPECT_EQ(oblique[1], approach[1]);
    // Moving away from the wall, the pairs recede and the term is silent.
    const V2 away = accelerationAbove(V2{0.5, 1.0});
    EXPECT_EQ(away[0], 0.0);
    EXPECT_EQ(away[1], 0.0);
}

TEST(ArtificialViscosityAtWalls, BetweenFluidParticlesTheShearCounts) {
    // The same particles, all fluid: the sliding particle approaches the ones ahead of it
    // (v_ij . r_ij < 0) and is slowed.
    const V2 a = accelerationAbove(V2{1.0, 0.0}, true);
    EXPECT_LT(a[0], 0.0);
}

}  // namespace
