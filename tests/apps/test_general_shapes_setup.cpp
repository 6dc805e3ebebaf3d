// The set-up and containment with shapes other than boxes and balls (any geometry::Solid): fluid
// fills the inside of its shape outside every body and wall, an interior wall is a layer of wall
// particles as thick as the box walls' under its surface, and a fluid particle that enters a
// wall or body is put back out along the solid's normal. A rotated square of this file's own
// stands in for the shapes library.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "sph/fluid_model.hpp"
#include "sph/scheduler.hpp"

using namespace num;
using namespace num::sph;

namespace {

/// A square of half-size `a` centred at `c`, rotated by `angle` (radians): exact signed distance.
class RotatedSquare : public geometry::Solid<2> {
  public:
    RotatedSquare(Vector<2> c, double a, double angle)
        : c_(c), a_(a), cos_(std::cos(angle)), sin_(std::sin(angle)) {}
    double signedDistance(const Vector<2>& x) const override {
        const Vector<2> d = x - c_;
        const double u = std::abs(cos_ * d[0] + sin_ * d[1]) - a_,
                     v = std::abs(-sin_ * d[0] + cos_ * d[1]) - a_;
        const double outside = std::hypot(std::max(u, 0.0), std::max(v, 0.0));
        return outside > 0 ? outside : std::max(u, v);
    }
    geometry::Bounds<2> bounds() const override {
        const double r = a_ * std::sqrt(2.0);
        return {c_ - Vector<2>::filled(r), c_ + Vector<2>::filled(r)};
    }

  private:
    Vector<2> c_;
    double a_, cos_, sin_;
};

constexpr double kDx = 0.02;

RunSettings settings() {
    RunSettings s;
    s.set("kernel", std::string("cubic_spline")).set("smoothing_length", 1.3 * kDx);
    return s;
}

/// The unit box with walls, filled with fluid, and a rotated square wall in its middle.
FluidGeometry<2> boxWithSquareWall() {
    FluidGeometry<2> g;
    g.spacing = kDx;
    g.domain.max = Vector<2>{{1, 1}};
    g.fluid.push_back(FluidRegion<2>::filling(BoxOrBall<2>::box(g.domain.min, g.domain.max)));
    InteriorWall<2> wall;
    wall.solid = std::make_shared<RotatedSquare>(Vector<2>{{0.5, 0.5}}, 0.2, 0.5);
    g.interiorWalls.push_back(wall);
    return g;
}

bool insideBox(const Vector<2>& x) { return x[0] > 0 && x[0] < 1 && x[1] > 0 && x[1] < 1; }

}  // namespace

TEST(GeneralShapes, PlacedBoxAndBallAreTheirShapes) {
    PlacedShape<2> box, ball;
    box.shape = BoxOrBall<2>::box(Vector<2>{{0.1, 0.2}}, Vector<2>{{0.4, 0.9}});
    ball.shape = BoxOrBall<2>::ball(Vector<2>{{0.3, 0.3}}, 0.25);
    for (const Vector<2> x : {Vector<2>{{0.2, 0.3}}, Vector<2>{{0.7, 0.1}}, Vector<2>{{0.3, 0.95}}})
        for (const PlacedShape<2>* p : {&box, &ball}) {
            EXPECT_EQ(p->signedDistance(x), p->shape.signedDistance(x));
            EXPECT_EQ(p->outwardNormal(x), p->shape.outwardNormal(x));
        }
    EXPECT_FALSE(box.isGeneral());
}

TEST(GeneralShapes, InteriorWallIsALayerAsThickAsTheBoxWalls) {
    const FluidGeometry<2> g = boxWithSquareWall();
    const Storage<2> st = makeFluidStorage(FluidModel<2>{}, g, settings());
    const auto x = st.getValue<Vector<2>>(QuantityId::POSITION);
    const auto kind = st.getValue<int>(QuantityId::KIND);
    const int layers = wallLayersFor(RunKernel<2>(settings()).supportRadius(), kDx);
    const auto& wall = g.interiorWalls[0];
    int inner = 0, fluid = 0;
    for (Size i = 0; i < st.size(); ++i) {
        const double d = wall.signedDistance(x[i]);
        if (kind[i] == int(ParticleKind::FLUID)) {
            ++fluid;
            EXPECT_GE(d, 0) << "fluid in the wall at " << x[i][0] << ", " << x[i][1];
        } else if (kind[i] == int(ParticleKind::WALL) && insideBox(x[i])) {
            ++inner;
            EXPECT_LT(d, 0);
            EXPECT_GT(d, -layers * kDx);
        }
    }
    // Every lattice point of the box is fluid, a wall particle or deep inside the wall.
    int deep = 0, layer = 0;
    forEachLatticePoint<2>(g.domain.min, g.domain.max, kDx, [&](const Vector<2>& p) {
        const double d = wall.signedDistance(p);
        deep += d <= -layers * kDx, layer += d < 0 && d > -layers * kDx;
    });
    EXPECT_EQ(inner, layer);
    EXPECT_GT(deep, 0);
    EXPECT_EQ(fluid + inner + deep, 50 * 50);
}

TEST(GeneralShapes, FluidFillsItsShapeOutsideBodies) {
    FluidGeometry<2> g;
    g.spacing = kDx;
    g.domain.max = Vector<2>{{1, 1}};
    FluidRegion<2> region;
    region.solid = std::make_shared<RotatedSquare>(Vector<2>{{0.5, 0.5}}, 0.3, 0.3);
    g.fluid.push_back(region);
    SolidBody<2> body;
    body.solid = std::make_shared<RotatedSquare>(Vector<2>{{0.5, 0.5}}, 0.1, 0.9);
    g.bodies.push_back(body);
    const auto particles = generateParticles(g, 3);
    int fluid = 0, bodies = 0;
    for (const auto& p : particles) {
        if (p.kind == ParticleKind::FLUID) {
            ++fluid;
            EXPECT_TRUE(region.contains(p.x));
            EXPECT_FALSE(body.contains(p.x));
        }
        if (p.kind == ParticleKind::BODY) {
            ++bodies;
            EXPECT_TRUE(body.contains(p.x));
        }
    }
    // About the areas (0.6^2 - 0.2^2) / dx^2 and 0.2^2 / dx^2, within the lattice's rounding.
    EXPECT_NEAR(fluid, (0.36 - 0.04) / (kDx * kDx), 0.05 * 0.32 / (kDx * kDx));
    EXPECT_NEAR(bodies, 0.04 / (kDx * kDx), 0.1 * 0.04 / (kDx * kDx));
}

TEST(GeneralShapes, ContainmentPutsFluidBackOutOfAWall) {
    const FluidGeometry<2> g = boxWithSquareWall();
    Storage<2> st = makeFluidStorage(FluidModel<2>{}, g, settings());
    auto x = st.getValue<Vector<2>>(QuantityId::POSITION);
    auto v = st.getDt<Vector<2>>(QuantityId::POSITION);
    const auto kind = st.getValue<int>(QuantityId::KIND);
    Size i = 0;
    while (kind[i] != int(ParticleKind::FLUID)) ++i;
    const auto& wall = g.interiorWalls[0];
    const Vector<2> entered{{0.5 + 0.2 * std::cos(0.5) - 0.005, 0.5 + 0.2 * std::sin(0.5)}};
    const double depth = wall.signedDistance(entered);
    ASSERT_LT(depth, 0);
    x[i] = entered;
    v[i] = Vector<2>{{-1.0, 0.3}};  // into the wall, and along it
    SequentialScheduler scheduler;
    ParticleContainment<2>(g).postStep(scheduler, st, 0, 0);
    EXPECT_NEAR(wall.signedDistance(x[i]), -depth, 1e-9);
    const Vector<2> n = wall.outwardNormal(x[i]);
    EXPECT_GE(dot(v[i], n), -1e-9);
    EXPECT_GT(norm(v[i]), 0.1);  // the tangential part is kept
}
