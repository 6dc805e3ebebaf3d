// The flat form of the solids (geometry/flat_solid.hpp), as the CUDA back end evaluates them:
// at 4096 pseudo-random points in and around each solid's bounds (and at a few special ones),
// its signed distance and outward normal equal the Solid's bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <vector>

#include "geometry/flat_solid.hpp"
#include "geometry/mesh_solid.hpp"

namespace {

using namespace num::geometry;
using P2 = Point<2>;
using P3 = Point<3>;

constexpr int POINTS = 4096;

/// splitmix64: the same points on every platform.
struct Random {
    std::uint64_t state;
    double uniform() {  // in [0, 1)
        std::uint64_t z = (state += 0x9e3779b97f4a7c15u);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
        return double((z ^ (z >> 31)) >> 11) * 0x1p-53;
    }
};

/// The solid's bounds grown by a quarter on each side; [-3, 3] on unbounded axes.
template <int Dim>
Bounds<Dim> around(const Solid<Dim>& solid) {
    Bounds<Dim> b = solid.bounds();
    for (int k = 0; k < Dim; ++k) {
        if (!std::isfinite(b.max[k] - b.min[k])) b.min[k] = -3, b.max[k] = 3;
        const double grow = (b.max[k] - b.min[k]) / 4;
        b.min[k] -= grow, b.max[k] += grow;
    }
    return b;
}

/// Compares the flat form with the solid at POINTS points and at `extra`; the points are also
/// rounded to a grid of 1/8 now and then, to land on vertices, edges and axes exactly.
template <int Dim>
void expectSame(const Solid<Dim>& solid, const std::vector<Point<Dim>>& extra = {}) {
    const std::optional<FlatSolid<Dim>> flat = flatten(solid);
    ASSERT_TRUE(flat.has_value());
    const FlatSolidView<Dim> view = flat->view();
    const Bounds<Dim> box = around(solid);
    Random random{std::uint64_t(flat->nodes.size() * 1000 + flat->data.size())};
    std::vector<Point<Dim>> points = extra;
    for (int i = 0; i < POINTS; ++i) {
        Point<Dim> x;
        for (int k = 0; k < Dim; ++k)
            x[k] = box.min[k] + (box.max[k] - box.min[k]) * random.uniform();
        if (i % 8 == 0)
            for (int k = 0; k < Dim; ++k) x[k] = std::round(x[k] * 8) / 8;
        points.push_back(x);
    }
    int inside = 0;
    for (const Point<Dim>& x : points) {
        const double d = solid.signedDistance(x);
        inside += d < 0;
        ASSERT_EQ(view.signedDistance(x), d) << "at " << x[0] << ", " << x[1];
        const Point<Dim> n = solid.outwardNormal(x), m = view.outwardNormal(x);
        for (int k = 0; k < Dim; ++k) ASSERT_EQ(m[k], n[k]) << "at " << x[0] << ", " << x[1];
    }
    EXPECT_GT(inside, 0);  // the points test both sides
    EXPECT_LT(inside, int(points.size()));
}

Rotation<3> turn3(double x, double y, double z) { return Rotation<3>(Angles<3>{{x, y, z}}); }

TEST(FlatSolid, Primitives2D) {
    expectSame(Ball<2>(P2{{0.5, -0.25}}, 0.75), {P2{{0.5, -0.25}}});  // the centre: differences
    expectSame(Box<2>(P2{{-1, 0}}, P2{{2, 0.5}}));
    expectSame(HalfSpace<2>(P2{{0.1, 0.2}}, P2{{-1, 2}}));
    expectSame(*rotatedBox(P2{{1, 2}}, P2{{0.5, 0.25}}, Rotation<2>(Angles<2>{{30}})));
    expectSame(Transformed<2>(std::make_shared<Box<2>>(P2{{0, 0}}, P2{{1, 2}}), 1.7,
                              Rotation<2>(Angles<2>{{-70}}), P2{{0.3, -0.4}}));
}

TEST(FlatSolid, Primitives3D) {
    expectSame(Ball<3>(P3{{0.5, -0.25, 1}}, 0.75), {P3{{0.5, -0.25, 1}}});
    expectSame(Box<3>(P3{{-1, 0, 0.25}}, P3{{2, 0.5, 1}}));
    expectSame(HalfSpace<3>(P3{{0.1, 0.2, 0.3}}, P3{{-1, 2, 0.5}}));
    expectSame(*rotatedBox(P3{{1, 2, 3}}, P3{{0.5, 0.25, 1}}, turn3(10, 20, 30)));
    expectSame(Transformed<3>(std::make_shared<Ball<3>>(P3{{1, 0, 0}}, 0.5), 2.5,
                              turn3(-40, 15, 75), P3{{0.3, -0.4, 2}}));
}

TEST(FlatSolid, Combinations2D) {
    auto ball = std::make_shared<Ball<2>>(P2{{0, 0}}, 1.0);
    auto box = rotatedBox(P2{{0.8, 0.3}}, P2{{0.6, 0.3}}, Rotation<2>(Angles<2>{{25}}));
    auto half = std::make_shared<HalfSpace<2>>(P2{{0, 0.2}}, P2{{0.3, 1}});
    auto cut = std::make_shared<Box<2>>(P2{{-0.3, -0.3}}, P2{{0.3, 0.5}});
    auto both =
        std::make_shared<Combination<2>>(Combine::UNION, std::vector<SolidPtr<2>>{ball, box});
    auto inner = std::make_shared<Combination<2>>(Combine::INTERSECTION,
                                                  std::vector<SolidPtr<2>>{cut, half});
    auto shape = std::make_shared<Combination<2>>(Combine::DIFFERENCE,
                                                  std::vector<SolidPtr<2>>{both, inner, half});
    expectSame(*shape);
    expectSame(Transformed<2>(shape, 0.6, Rotation<2>(Angles<2>{{45}}), P2{{-1, 2}}));
    expectSame(Combination<2>(Combine::INTERSECTION, {shape, ball, box}));
}

TEST(FlatSolid, Combinations3D) {
    auto ball = std::make_shared<Ball<3>>(P3{{0, 0, 0}}, 1.0);
    auto box = rotatedBox(P3{{0.8, 0.3, 0}}, P3{{0.6, 0.3, 0.5}}, turn3(5, 25, 45));
    auto half = std::make_shared<HalfSpace<3>>(P3{{0, 0.2, 0}}, P3{{0.3, 1, 0.2}});
    auto rod = cylinder(P3{{-1, 0, 0}}, P3{{1, 0.2, 0.1}}, 0.3);
    auto both =
        std::make_shared<Combination<3>>(Combine::UNION, std::vector<SolidPtr<3>>{ball, box});
    auto inner = std::make_shared<Combination<3>>(Combine::INTERSECTION,
                                                  std::vector<SolidPtr<3>>{rod, half});
    auto shape = std::make_shared<Combination<3>>(Combine::DIFFERENCE,
                                                  std::vector<SolidPtr<3>>{both, inner, half});
    expectSame(*shape);
    expectSame(Transformed<3>(shape, 1.3, turn3(30, -60, 10), P3{{-1, 2, 0.5}}));
}

TEST(FlatSolid, PolygonsAndPolylines) {
    const Loop outer{P2{{0, 0}}, P2{{3, 0}}, P2{{3, 2}}, P2{{1.5, 1}}, P2{{0, 2}}};
    const Loop hole{P2{{0.5, 0.25}}, P2{{1, 0.75}}, P2{{2.5, 0.25}}};
    const PolygonSet set({outer, hole});
    expectSame(set, {P2{{1.5, 1}}, P2{{0.75, 0.25}}, P2{{3, 1}}, P2{{-1, 2}}});
    expectSame(*polygon(outer));
    auto star = polygon(Loop{P2{{0, 1}}, P2{{0.2, 0.2}}, P2{{1, 0}}, P2{{0.2, -0.2}}, P2{{0, -1}},
                             P2{{-0.2, -0.2}}, P2{{-1, 0}}, P2{{-0.2, 0.2}}});
    expectSame(Transformed<2>(star, 2, Rotation<2>(Angles<2>{{10}}), P2{{1, 1}}));
    auto line = std::make_shared<Polyline<2>>(
        std::vector<P2>{P2{{0, 0}}, P2{{1, 0.5}}, P2{{1, 0.5}}, P2{{2, -0.5}}}, 0.1);
    expectSame(*line);
    expectSame(Combination<2>(Combine::UNION, {line, star}));
    expectSame(Polyline<3>({P3{{0, 0, 0}}, P3{{1, 0.5, 0.2}}, P3{{2, -0.5, 1}}}, 0.2));
}

TEST(FlatSolid, Revolved) {
    expectSame(Cone(P3{{0, 0, 0}}, P3{{0, 0, 2}}, 1, 0.25), {P3{{0, 0, 1}}, P3{{0, 0, 0}}});
    expectSame(Cone(P3{{1, -1, 0.5}}, P3{{-0.5, 2, 1}}, 0.2, 0.7));
    expectSame(Cone(P3{{0, 0, 0}}, P3{{1, 1, 1}}, 0.5, 0));  // a tip
    expectSame(*cylinder(P3{{0, 0, 0}}, P3{{0, 3, 0}}, 0.5));
    expectSame(Transformed<3>(cylinder(P3{{0, 0, 0}}, P3{{0, 0, 1}}, 0.5), 0.5, turn3(90, 0, 0),
                              P3{{0, 0, 1}}));
}

/// A tetrahedron's mesh: no flat form, alone or in a combination; nor a class flatten does not
/// know.
TEST(FlatSolid, MeshesAndUnknownSolidsHaveNone) {
    TriangleMesh mesh;
    mesh.vertices = {P3{{0, 0, 0}}, P3{{1, 0, 0}}, P3{{0, 1, 0}}, P3{{0, 0, 1}}};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    auto tetra = std::make_shared<MeshSolid>(mesh, "tetrahedron");
    EXPECT_FALSE(flatten<3>(*tetra).has_value());
    auto ball = std::make_shared<Ball<3>>(P3{{0, 0, 0}}, 1.0);
    EXPECT_FALSE(flatten<3>(Combination<3>(Combine::UNION, {ball, tetra})).has_value());
    struct Strip final : Solid<2> {
        double signedDistance(const P2& x) const override { return std::abs(x[1]) - 1; }
        Bounds<2> bounds() const override { return {}; }
    };
    EXPECT_FALSE(flatten<2>(Strip()).has_value());
}

/// 16 transformations and combinations nested are evaluated; 17 are refused.
TEST(FlatSolid, DepthLimit) {
    SolidPtr<2> shape = std::make_shared<Box<2>>(P2{{0, 0}}, P2{{1, 1}});
    auto ball = std::make_shared<Ball<2>>(P2{{0.5, 1}}, 0.4);
    for (int level = 0; level < FLAT_MAX_DEPTH; ++level)
        shape = level % 2 ? SolidPtr<2>(std::make_shared<Transformed<2>>(
                                shape, 1.1, Rotation<2>(Angles<2>{{7}}), P2{{0.1, 0}}))
                          : std::make_shared<Combination<2>>(
                                level % 4 ? Combine::DIFFERENCE : Combine::UNION,
                                std::vector<SolidPtr<2>>{shape, ball});
    expectSame(*shape);
    auto deeper = std::make_shared<Transformed<2>>(shape, 2.0, Rotation<2>(), P2{{0, 0}});
    EXPECT_THROW(flatten<2>(*deeper), std::invalid_argument);
}

}  // namespace
