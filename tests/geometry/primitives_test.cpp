// Signed distances of the primitives at points where they are known by hand, the
// transformations and the combinations.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "geometry/combination.hpp"
#include "geometry/primitives.hpp"
#include "geometry/revolved.hpp"

namespace {

using namespace num::geometry;
using P2 = Point<2>;
using P3 = Point<3>;

TEST(Primitives, BallAndBox) {
    const Ball<3> ball(P3{{1, 0, 0}}, 0.5);
    EXPECT_DOUBLE_EQ(ball.signedDistance(P3{{1, 0, 0}}), -0.5);
    EXPECT_DOUBLE_EQ(ball.signedDistance(P3{{1, 2, 0}}), 1.5);
    const Box<2> box(P2{{0, 0}}, P2{{2, 1}});
    EXPECT_DOUBLE_EQ(box.signedDistance(P2{{1, 0.5}}), -0.5);
    EXPECT_DOUBLE_EQ(box.signedDistance(P2{{1.8, 0.5}}), -0.2);
    EXPECT_DOUBLE_EQ(box.signedDistance(P2{{3, 0.5}}), 1);
    EXPECT_DOUBLE_EQ(box.signedDistance(P2{{5, 5}}), 5);  // to the corner (2, 1): 3-4-5
    EXPECT_NEAR(box.outwardNormal(P2{{2.5, 0.5}})[0], 1, 1e-9);
}

TEST(Primitives, HalfSpace) {
    const HalfSpace<3> below(P3{{0, 0, 1}}, P3{{0, 0, 2}});
    EXPECT_DOUBLE_EQ(below.signedDistance(P3{{5, 3, 0.25}}), -0.75);
    EXPECT_EQ(below.bounds().max[2], 1);
    EXPECT_TRUE(std::isinf(below.bounds().min[2]));
    const HalfSpace<2> slope(P2{{0, 0}}, P2{{-1, 1}});
    EXPECT_NEAR(slope.signedDistance(P2{{0, 1}}), std::sqrt(0.5), 1e-15);
    EXPECT_TRUE(std::isinf(slope.bounds().max[0]));
}

TEST(Primitives, CylinderAndCone) {
    const auto cyl = cylinder(P3{{0, 0, 0}}, P3{{0, 0, 2}}, 1);
    EXPECT_DOUBLE_EQ(cyl->signedDistance(P3{{0, 0, 1}}), -1);
    EXPECT_NEAR(cyl->signedDistance(P3{{0.5, 0, 1.9}}), -0.1, 1e-15);  // nearest the top
    EXPECT_DOUBLE_EQ(cyl->signedDistance(P3{{3, 0, 1}}), 2);           // beside
    EXPECT_DOUBLE_EQ(cyl->signedDistance(P3{{0, 0.2, 3}}), 1);         // above the top
    EXPECT_DOUBLE_EQ(cyl->signedDistance(P3{{4, 0, -4}}), 5);          // from the rim: 3-4-5
    const auto slanted = cylinder(P3{{0, 0, 0}}, P3{{1, 1, 1}}, 0.1);
    EXPECT_NEAR(slanted->signedDistance(P3{{0.5, 0.5, 0.5}}), -0.1, 1e-15);
    EXPECT_NEAR(slanted->bounds().max[0], 1 + 0.1 * std::sqrt(2.0 / 3), 1e-15);
    // A cone of height 1 and base radius 1: its side is at 45 degrees.
    const Cone cone(P3{{0, 0, 0}}, P3{{0, 0, 1}}, 1, 0);
    EXPECT_NEAR(cone.signedDistance(P3{{0, 0, 0.5}}), -0.5 / std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(cone.signedDistance(P3{{0, 0, 0.1}}), -0.1, 1e-15);  // nearest the base
    EXPECT_NEAR(cone.signedDistance(P3{{0, 0, 2}}), 1, 1e-15);       // above the tip
    EXPECT_NEAR(cone.signedDistance(P3{{1, 0, 1}}), std::sqrt(0.5), 1e-15);
}

TEST(Transformed, ScaleRotateTranslate) {
    // A box [0, 2] x [0, 1] scaled by 3, turned by 90 degrees, moved by (10, 0):
    // it becomes [7, 10] x [0, 6].
    auto box = std::make_shared<Box<2>>(P2{{0, 0}}, P2{{2, 1}});
    const Transformed<2> t(box, 3, Rotation<2>(Angles<2>{{90}}), P2{{10, 0}});
    EXPECT_NEAR(t.signedDistance(P2{{8.5, 3}}), -1.5, 1e-12);
    EXPECT_NEAR(t.signedDistance(P2{{12, 3}}), 2, 1e-12);
    const Bounds<2> b = t.bounds();
    EXPECT_NEAR(b.min[0], 7, 1e-12);
    EXPECT_NEAR(b.max[1], 6, 1e-12);
    EXPECT_NEAR(t.outwardNormal(P2{{12, 3}})[0], 1, 1e-9);
}

TEST(Transformed, RotationOrderIsXThenYThenZ) {
    // (1, 0, 0) about x by 90: unchanged; about y by 90: to (0, 0, -1); about z by 90: stays.
    const Rotation<3> r(Angles<3>{{90, 90, 90}});
    const P3 p = r.apply(P3{{1, 0, 0}});
    EXPECT_NEAR(p[0], 0, 1e-15);
    EXPECT_NEAR(p[1], 0, 1e-15);
    EXPECT_NEAR(p[2], -1, 1e-15);
    // (0, 1, 0): about x to (0, 0, 1); about y to (1, 0, 0); about z to (0, 1, 0).
    const P3 q = r.apply(P3{{0, 1, 0}});
    EXPECT_NEAR(q[1], 1, 1e-15);
    const P3 back = r.applyInverse(q);
    EXPECT_NEAR(back[1], 1, 1e-15);
}

TEST(Transformed, RotatedBox) {
    const auto box = rotatedBox(P2{{1, 1}}, P2{{1, 0.5}}, Rotation<2>(Angles<2>{{45}}));
    EXPECT_NEAR(box->signedDistance(P2{{1, 1}}), -0.5, 1e-12);
    EXPECT_NEAR(box->signedDistance(P2{{1.7, 1.7}}), -1 + 0.7 * std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(box->bounds().max[0], 1 + 1.5 / std::sqrt(2.0), 1e-12);
}

TEST(Combination, UnionIntersectionDifference) {
    auto a = std::make_shared<Box<2>>(P2{{0, 0}}, P2{{2, 2}});
    auto b = std::make_shared<Ball<2>>(P2{{2, 1}}, 0.5);
    const Combination<2> both(Combine::UNION, {a, b});
    const Combination<2> common(Combine::INTERSECTION, {a, b});
    const Combination<2> cut(Combine::DIFFERENCE, {a, b});
    const P2 inBallOutsideBox{{2.3, 1}}, inBoth{{1.8, 1}}, inBoxOnly{{1, 1}};
    EXPECT_LT(both.signedDistance(inBallOutsideBox), 0);
    EXPECT_GT(common.signedDistance(inBallOutsideBox), 0);
    EXPECT_LT(common.signedDistance(inBoth), 0);
    EXPECT_GT(cut.signedDistance(inBoth), 0);
    EXPECT_DOUBLE_EQ(cut.signedDistance(inBoxOnly), -0.5);  // the ball's edge is nearest
    EXPECT_DOUBLE_EQ(cut.signedDistance(P2{{1.8, 1}}), 0.3);
    EXPECT_NEAR(cut.outwardNormal(P2{{1.4, 1}})[0], 1, 1e-12);  // into the hole
    EXPECT_DOUBLE_EQ(both.bounds().max[0], 2.5);
    EXPECT_DOUBLE_EQ(common.bounds().min[0], 1.5);
    EXPECT_DOUBLE_EQ(cut.bounds().max[0], 2);
}

TEST(Combination, CupAsDifferenceOfCylinders) {
    auto outer = cylinder(P3{{0, 0, 0}}, P3{{0, 0, 1}}, 0.5);
    auto inner = cylinder(P3{{0, 0, 0.1}}, P3{{0, 0, 2}}, 0.4);
    const Combination<3> cup(Combine::DIFFERENCE, {outer, inner});
    EXPECT_LT(cup.signedDistance(P3{{0.45, 0, 0.5}}), 0);  // in the side wall
    EXPECT_LT(cup.signedDistance(P3{{0, 0, 0.05}}), 0);    // in the bottom
    EXPECT_GT(cup.signedDistance(P3{{0, 0, 0.5}}), 0);     // in the cavity
    EXPECT_NEAR(cup.signedDistance(P3{{0, 0, 0.5}}), 0.4, 1e-15);
}

}  // namespace
