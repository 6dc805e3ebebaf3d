// Exact volumes, centroids and inertias of the solids against closed forms: polygons (squares,
// rectangles, a turned and moved triangle, both orientations), meshes of boxes, cylinders and
// cones, and scaled, rotated and moved solids; empty where no exact rule applies.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "geometry/combination.hpp"
#include "geometry/mesh_solid.hpp"
#include "geometry/polygon.hpp"
#include "geometry/primitives.hpp"
#include "geometry/revolved.hpp"

namespace {

using namespace num::geometry;
using P2 = Point<2>;
using P3 = Point<3>;
constexpr double pi = std::numbers::pi;

/// |a - b| <= 1e-12 max(|b|, scale)
void expectClose(double a, double b, double scale = 1) {
    EXPECT_NEAR(a, b, 1e-12 * std::max(std::abs(b), scale));
}

template <int Dim>
void expectClose(const Point<Dim>& a, const Point<Dim>& b, double scale = 1) {
    for (int k = 0; k < Dim; ++k) expectClose(a[k], b[k], scale);
}

/// Expects the tensor to be exactly symmetric and close to `expected` (relative to `scale`).
void expectTensor(const Rows<3>& I, const Rows<3>& expected, double scale) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            EXPECT_EQ(I[i][j], I[j][i]) << i << ", " << j;
            EXPECT_NEAR(I[i][j], expected[i][j], 1e-12 * scale) << i << ", " << j;
        }
}

Rows<3> diagonal(const P3& d) {
    Rows<3> I{};
    for (int k = 0; k < 3; ++k) I[k][k] = d[k];
    return I;
}

/// The box [lo, hi] as 12 triangles facing out (vertex v = x + 2 y + 4 z, 1 for the hi side).
TriangleMesh boxMesh(const P3& lo, const P3& hi) {
    TriangleMesh mesh;
    for (int v = 0; v < 8; ++v)
        mesh.vertices.push_back(
            P3{{v & 1 ? hi[0] : lo[0], v & 2 ? hi[1] : lo[1], v & 4 ? hi[2] : lo[2]}});
    mesh.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                      {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    return mesh;
}

TEST(MassProperties, PolygonSquareAndRectangle) {
    const auto square = polygon({P2{{1, 1}}, P2{{3, 1}}, P2{{3, 3}}, P2{{1, 3}}});
    const auto s = square->massProperties();
    ASSERT_TRUE(s);
    expectClose(s->volume, 4);
    expectClose(s->centroid, P2{{2, 2}});
    expectClose(s->inertia, 4 * (4 + 4) / 12.0);
    // 3 x 0.5, clockwise: the same as counter-clockwise.
    const Loop ccw{P2{{-1, 2}}, P2{{2, 2}}, P2{{2, 2.5}}, P2{{-1, 2.5}}};
    const Loop cw(ccw.rbegin(), ccw.rend());
    for (const Loop& loop : {ccw, cw}) {
        const auto r = polygon(loop)->massProperties();
        ASSERT_TRUE(r);
        expectClose(r->volume, 1.5);
        expectClose(r->centroid, P2{{0.5, 2.25}});
        expectClose(r->inertia, 1.5 * (9 + 0.25) / 12);
    }
}

// A triangle turned by 30 degrees and moved: A = |(b - a) x (c - a)| / 2, the centroid the mean
// of the corners, J = A (|ab|^2 + |bc|^2 + |ca|^2) / 36 about it.
TEST(MassProperties, PolygonTriangleTurnedAndMoved) {
    const Rotation<2> turn(Angles<2>{{30}});
    const P2 shift{{5, -3}};
    Loop corners;
    for (const P2& p : {P2{{0, 0}}, P2{{4, 0}}, P2{{1, 3}}})
        corners.push_back(shift + turn.apply(p));
    const P2 &a = corners[0], &b = corners[1], &c = corners[2];
    const double area = 6;
    const double J = area * (normSqr(b - a) + normSqr(c - b) + normSqr(a - c)) / 36;
    const Loop reversed{c, b, a};
    for (const Loop& loop : {corners, reversed}) {
        const auto m = polygon(loop)->massProperties();
        ASSERT_TRUE(m);
        expectClose(m->volume, area);
        expectClose(m->centroid, (a + b + c) / 3);
        expectClose(m->inertia, J);
    }
}

TEST(MassProperties, PolygonWithAHoleIsNotKnown) {
    const PolygonSet ring({{P2{{0, 0}}, P2{{4, 0}}, P2{{4, 4}}, P2{{0, 4}}},
                           {P2{{1, 1}}, P2{{3, 1}}, P2{{3, 3}}, P2{{1, 3}}}});
    EXPECT_FALSE(ring.massProperties());
}

TEST(MassProperties, PrimitivesAndTheirTransforms) {
    const auto disc = Ball<2>(P2{{1, 2}}, 0.5).massProperties();
    ASSERT_TRUE(disc);
    expectClose(disc->volume, pi / 4);
    expectClose(disc->inertia, pi / 4 * 0.25 / 2);
    const auto sphere = Ball<3>(P3{{1, 2, 3}}, 2).massProperties();
    ASSERT_TRUE(sphere);
    expectClose(sphere->volume, 32 * pi / 3);
    expectTensor(sphere->inertia, diagonal(P3::filled(0.4 * 32 * pi / 3 * 4)), 100);
    // A box [0, 2] x [0, 1] scaled by 3, turned by 90 degrees, moved by (10, 0): [7, 10] x [0, 6].
    const auto box2 = std::make_shared<Box<2>>(P2{{0, 0}}, P2{{2, 1}});
    const auto moved =
        Transformed<2>(box2, 3, Rotation<2>(Angles<2>{{90}}), P2{{10, 0}}).massProperties();
    ASSERT_TRUE(moved);
    expectClose(moved->volume, 18);
    expectClose(moved->centroid, P2{{8.5, 3}});
    expectClose(moved->inertia, 18 * (9 + 36) / 12.0);
    EXPECT_FALSE(HalfSpace<2>(P2{{0, 0}}, P2{{0, 1}}).massProperties());
    const Combination<2> both(Combine::UNION, {box2, std::make_shared<Ball<2>>(P2{{5, 5}}, 1)});
    EXPECT_FALSE(both.massProperties());
}

TEST(MassProperties, MeshCube) {
    const double a = 0.7;
    const MeshSolid cube(boxMesh(P3{{-1, 2, 0.5}}, P3{{-1 + a, 2 + a, 0.5 + a}}), "cube");
    const auto m = cube.massProperties();
    ASSERT_TRUE(m);
    const double volume = a * a * a;
    expectClose(m->volume, volume);
    expectClose(m->centroid, P3{{-1 + a / 2, 2 + a / 2, 0.5 + a / 2}});
    expectTensor(m->inertia, diagonal(P3::filled(volume * a * a / 6)), volume * a * a);
}

TEST(MassProperties, MeshBoxOfThreeSides) {
    const P3 lo{{3, -4, 1}}, e{{1, 2, 3}};
    const auto m = MeshSolid(boxMesh(lo, lo + e), "box").massProperties();
    ASSERT_TRUE(m);
    expectClose(m->volume, 6);
    expectClose(m->centroid, lo + e / 2);
    expectTensor(m->inertia,
                 diagonal(P3{{6 * (4 + 9) / 12.0, 6 * (1 + 9) / 12.0, 6 * (1 + 4) / 12.0}}), 10);
}

// x' = t + R (s x): volume s^3 V, centroid t + R (s c), and R e_k a principal axis of moment
// s^5 I_kk; the same as the transformed primitive box.
TEST(MassProperties, TransformedMeshBox) {
    const P3 lo{{-0.5, -1, -1.5}}, hi{{0.5, 1, 1.5}};
    const double s = 1.5;
    const Rotation<3> R(Angles<3>{{30, 45, 60}});
    const P3 t{{1, -2, 3}};
    const auto mesh = std::make_shared<MeshSolid>(boxMesh(lo, hi), "box");
    const auto m = Transformed<3>(mesh, s, R, t).massProperties();
    ASSERT_TRUE(m);
    const double volume = 6 * s * s * s;
    expectClose(m->volume, volume);
    expectClose(m->centroid, t);
    const P3 principal{{6 * (4 + 9) / 12.0, 6 * (1 + 9) / 12.0, 6 * (1 + 4) / 12.0}};
    for (int k = 0; k < 3; ++k) {
        P3 axis{};
        axis[k] = 1;
        const P3 n = R.apply(axis);
        const P3 In{{dot(m->inertia[0], n), dot(m->inertia[1], n), dot(m->inertia[2], n)}};
        expectClose(In, n * (std::pow(s, 5) * principal[k]), 100);
    }
    const auto box = std::make_shared<Box<3>>(lo, hi);
    const auto viaBox = Transformed<3>(box, s, R, t).massProperties();
    ASSERT_TRUE(viaBox);
    expectTensor(m->inertia, viaBox->inertia, 100);
    // The mesh of the turned, scaled and moved box itself (products of inertia from triangles).
    TriangleMesh turned = boxMesh(lo, hi);
    for (P3& v : turned.vertices) v = t + R.apply(v * s);
    const auto direct = MeshSolid(turned, "turned box").massProperties();
    ASSERT_TRUE(direct);
    expectClose(direct->volume, volume);
    expectClose(direct->centroid, t, 10);
    expectTensor(direct->inertia, viaBox->inertia, 100);
    // Moved off the origin first: the centroid follows t + R (s c).
    const P3 c{{2, 0, -1}};
    const auto off =
        Transformed<3>(std::make_shared<MeshSolid>(boxMesh(lo + c, hi + c), "box"), s, R, t)
            .massProperties();
    ASSERT_TRUE(off);
    expectClose(off->centroid, t + R.apply(c * s), 10);
    expectTensor(off->inertia, m->inertia, 100);
}

// A cylinder: V = pi r^2 h, I = V r^2 / 2 about the axis, V (3 r^2 + h^2) / 12 across it.
// A cone with a tip: V = pi r^2 h / 3, centroid h / 4 from the base, I = 3/10 V r^2 about the
// axis and 3/80 V (4 r^2 + h^2) across it.
TEST(MassProperties, CylinderAndCone) {
    const double r = 0.3, h = 2;
    const auto cyl = cylinder(P3{{1, 1, 1}}, P3{{1, 1, 1 + h}}, r)->massProperties();
    ASSERT_TRUE(cyl);
    const double vc = pi * r * r * h;
    expectClose(cyl->volume, vc);
    expectClose(cyl->centroid, P3{{1, 1, 1 + h / 2}});
    const double across = vc * (3 * r * r + h * h) / 12;
    expectTensor(cyl->inertia, diagonal(P3{{across, across, vc * r * r / 2}}), vc);
    const auto cone = Cone(P3{{0, 0, 0}}, P3{{h, 0, 0}}, r, 0).massProperties();
    ASSERT_TRUE(cone);
    const double v = pi * r * r * h / 3, side = 3 * v * (4 * r * r + h * h) / 80;
    expectClose(cone->volume, v);
    expectClose(cone->centroid, P3{{h / 4, 0, 0}});
    expectTensor(cone->inertia, diagonal(P3{{0.3 * v * r * r, side, side}}), v);
}

}  // namespace
