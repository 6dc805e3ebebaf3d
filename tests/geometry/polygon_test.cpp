// Polygons (exact signed distance either orientation, even-odd holes, self-crossings refused)
// and polyline walls.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/polygon.hpp"

namespace {

using namespace num::geometry;
using P2 = Point<2>;

TEST(Polygon, TriangleEitherOrientation) {
    const Loop ccw{P2{{0, 0}}, P2{{1, 0}}, P2{{0, 1}}};
    const Loop cw{P2{{0, 0}}, P2{{0, 1}}, P2{{1, 0}}};
    for (const Loop& loop : {ccw, cw}) {
        const auto t = polygon(loop);
        EXPECT_DOUBLE_EQ(t->signedDistance(P2{{0.1, 0.2}}), -0.1);
        EXPECT_NEAR(t->signedDistance(P2{{1, 1}}), std::sqrt(0.5), 1e-15);
        EXPECT_DOUBLE_EQ(t->signedDistance(P2{{-2, 0}}), 2);
        EXPECT_NEAR(t->outwardNormal(P2{{0.5, -1}})[1], -1, 1e-9);
    }
}

TEST(Polygon, ConcaveOutline) {
    // An L: the point (1.5, 1.5) is in its notch, outside.
    const auto l =
        polygon({P2{{0, 0}}, P2{{2, 0}}, P2{{2, 1}}, P2{{1, 1}}, P2{{1, 2}}, P2{{0, 2}}});
    EXPECT_NEAR(l->signedDistance(P2{{1.5, 1.5}}), 0.5, 1e-15);
    EXPECT_NEAR(l->signedDistance(P2{{0.5, 1.5}}), -0.5, 1e-15);
    EXPECT_NEAR(l->signedDistance(P2{{1.5, 0.5}}), -0.5, 1e-15);
}

TEST(Polygon, SetWithAHole) {
    const PolygonSet ring({{P2{{0, 0}}, P2{{4, 0}}, P2{{4, 4}}, P2{{0, 4}}},
                           {P2{{1, 1}}, P2{{3, 1}}, P2{{3, 3}}, P2{{1, 3}}}});
    EXPECT_DOUBLE_EQ(ring.signedDistance(P2{{2, 2}}), 1);
    EXPECT_DOUBLE_EQ(ring.signedDistance(P2{{0.5, 2}}), -0.5);
}

TEST(Polygon, SelfCrossingRefusedNamingTheEdges) {
    try {
        polygon({P2{{0, 0}}, P2{{1, 1}}, P2{{1, 0}}, P2{{0, 1}}});
        FAIL() << "a bow-tie was accepted";
    } catch (const GeometryError& e) {
        EXPECT_STREQ(e.what(),
                     "the polygon crosses itself: edge 0 (points 0-1) and edge 2 (points 2-3) "
                     "meet (list the points in order around the outline)");
    }
    EXPECT_THROW(polygon({P2{{0, 0}}, P2{{1, 0}}, P2{{2, 0}}}), GeometryError);  // folds back
    EXPECT_THROW(polygon({P2{{0, 0}}, P2{{1, 0}}, P2{{1, 0}}, P2{{0, 1}}}), GeometryError);
    EXPECT_THROW(polygon({P2{{0, 0}}, P2{{1, 0}}}), GeometryError);
}

TEST(Polyline, BandOfHalfThickness) {
    const Polyline<2> wall({P2{{0, 0}}, P2{{1, 0}}, P2{{1, 1}}}, 0.1);
    EXPECT_DOUBLE_EQ(wall.signedDistance(P2{{0.5, 0}}), -0.1);
    EXPECT_DOUBLE_EQ(wall.signedDistance(P2{{0.5, 0.5}}), 0.4);
    EXPECT_DOUBLE_EQ(wall.signedDistance(P2{{-1, 0}}), 0.9);
    EXPECT_DOUBLE_EQ(wall.bounds().min[1], -0.1);
}

}  // namespace
