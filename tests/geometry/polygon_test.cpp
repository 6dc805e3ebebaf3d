// Polygons (exact signed distance either orientation, even-odd holes, self-crossings refused)
// and polyline walls. The edge tree behind polygons is checked against the plain loops over
// every edge (the oracles below) bit for bit, on random and adversarial outlines.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>

#include "geometry/polygon.hpp"

namespace {

using namespace num::geometry;
using P2 = Point<2>;
using std::numbers::pi;

// ---- Oracles: the plain loops over every edge (the code before the edge tree) ----

/// The signed distance by a loop over every edge: nearest edge, even-odd ray towards +x.
double plainSignedDistance(const std::vector<Loop>& loops, const P2& x) {
    double d2 = HUGE_VAL;
    bool inside = false;
    for (const Loop& loop : loops)
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const P2 &a = loop[i], &b = loop[(i + 1) % loop.size()];
            d2 = std::min(d2, segmentDistanceSqr(x, a, b));
            if ((a[1] > x[1]) != (b[1] > x[1])) {
                const double xCross = a[0] + (x[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
                if (x[0] < xCross) inside = !inside;
            }
        }
    return inside ? -std::sqrt(d2) : std::sqrt(d2);
}

double cross2(const P2& a, const P2& b) { return a[0] * b[1] - a[1] * b[0]; }

/// Whether two segments share a point, as polygon() decides it (boxes apart never meet).
bool plainMeet(const P2& p1, const P2& p2, const P2& q1, const P2& q2) {
    for (int k = 0; k < 2; ++k)
        if (std::max(p1[k], p2[k]) < std::min(q1[k], q2[k]) ||
            std::max(q1[k], q2[k]) < std::min(p1[k], p2[k]))
            return false;
    const double d1 = cross2(q2 - q1, p1 - q1), d2 = cross2(q2 - q1, p2 - q1);
    const double d3 = cross2(p2 - p1, q1 - p1), d4 = cross2(p2 - p1, q2 - p1);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
        return true;
    auto on = [](const P2& a, const P2& b, const P2& x) {
        return std::min(a[0], b[0]) <= x[0] && x[0] <= std::max(a[0], b[0]) &&
               std::min(a[1], b[1]) <= x[1] && x[1] <= std::max(a[1], b[1]);
    };
    return (d1 == 0 && on(q1, q2, p1)) || (d2 == 0 && on(q1, q2, p2)) ||
           (d3 == 0 && on(p1, p2, q1)) || (d4 == 0 && on(p1, p2, q2));
}

std::string plainEdge(std::size_t i, std::size_t n) {
    return "edge " + std::to_string(i) + " (points " + std::to_string(i) + "-" +
           std::to_string((i + 1) % n) + ")";
}

/// The message polygon() throws for `p`, by the quadratic loop over pairs of edges ("" when
/// it accepts the outline).
std::string plainPolygonError(const Loop& p) {
    const std::size_t n = p.size();
    if (n < 3) return "a polygon needs 3 points or more, found " + std::to_string(n);
    for (std::size_t i = 0; i < n; ++i)
        if (p[i] == p[(i + 1) % n])
            return "points " + std::to_string(i) + " and " + std::to_string((i + 1) % n) +
                   " of the polygon coincide (list each corner once)";
    for (std::size_t i = 0; i < n; ++i) {
        const P2 &a = p[i], &b = p[(i + 1) % n], &c = p[(i + 2) % n];
        if (cross2(b - a, c - b) == 0 && dot(b - a, c - b) < 0)
            return "the polygon folds back on itself at point " + std::to_string((i + 1) % n) +
                   " (" + plainEdge(i, n) + " and " + plainEdge((i + 1) % n, n) + " overlap)";
        for (std::size_t j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1) continue;
            if (plainMeet(a, b, p[j], p[(j + 1) % n]))
                return "the polygon crosses itself: " + plainEdge(i, n) + " and " +
                       plainEdge(j, n) + " meet (list the points in order around the outline)";
        }
    }
    return "";
}

std::string polygonError(const Loop& p) {
    try {
        polygon(p);
    } catch (const GeometryError& e) {
        return e.what();
    }
    return "";
}

// ---- Outlines: random, and the hard cases for a tree ----

/// A star-shaped outline about `c`: n points at sorted random angles and random radii.
Loop randomStar(std::mt19937_64& rng, int n, const P2& c, double rMin, double rMax) {
    std::uniform_real_distribution<double> angle(0, 2 * pi), radius(rMin, rMax);
    std::vector<double> t(n);
    for (double& v : t) v = angle(rng);
    std::sort(t.begin(), t.end());
    Loop p;
    for (const double v : t) {
        const double r = radius(rng);
        p.push_back(P2{{c[0] + r * std::cos(v), c[1] + r * std::sin(v)}});
    }
    return p;
}

/// A regular n-gon of radius r about c (every vertex as far from c as the others).
Loop regular(int n, const P2& c, double r) {
    Loop p;
    for (int i = 0; i < n; ++i)
        p.push_back(P2{{c[0] + r * std::cos(2 * pi * i / n), c[1] + r * std::sin(2 * pi * i / n)}});
    return p;
}

/// A band along a spiral of `turns` turns: out along the outer side, back along the inner.
Loop spiral(int perTurn, int turns) {
    Loop out, in;
    for (int i = 0; i <= perTurn * turns; ++i) {
        const double t = 2 * pi * i / perTurn, r = 1 + 0.5 * t / (2 * pi);
        out.push_back(P2{{(r + 0.2) * std::cos(t), (r + 0.2) * std::sin(t)}});
        in.push_back(P2{{r * std::cos(t), r * std::sin(t)}});
    }
    out.insert(out.end(), in.rbegin(), in.rend());
    return out;
}

/// A comb of `teeth` teeth of height 1 and width 0.5, 1 apart, on a back 0.25 thick; its tips
/// and roots share their y, so rays run along many edges at once.
Loop comb(int teeth) {
    Loop p{P2{{0, -0.25}}, P2{{double(teeth), -0.25}}};
    for (int k = teeth - 1; k >= 0; --k) {
        p.push_back(P2{{k + 0.5, 0}});
        p.push_back(P2{{k + 0.5, 1}});
        p.push_back(P2{{double(k), 1}});
        p.push_back(P2{{double(k), 0}});
    }
    p.erase(p.end() - 1);  // the last root lies on the back's corner line: join it directly
    return p;
}

/// Query points: random ones over the box of the loops and around it, every vertex, the
/// midpoints of edges, points at the height of vertices (rays through vertices and along
/// horizontal edges) and the centre of the box.
std::vector<P2> queries(std::mt19937_64& rng, const std::vector<Loop>& loops, int random) {
    P2 lo = loops[0][0], hi = loops[0][0];
    std::vector<P2> q;
    for (const Loop& l : loops)
        for (std::size_t i = 0; i < l.size(); ++i) {
            for (int k = 0; k < 2; ++k)
                lo[k] = std::min(lo[k], l[i][k]), hi[k] = std::max(hi[k], l[i][k]);
            if (i % 7 == 0) {
                const P2& b = l[(i + 1) % l.size()];
                q.push_back(l[i]);
                q.push_back((l[i] + b) / 2.0);
                q.push_back(P2{{l[i][0] - 1e-3, l[i][1]}});
            }
        }
    const P2 size = hi - lo;
    std::uniform_real_distribution<double> u(-0.2, 1.2);
    for (int i = 0; i < random; ++i)
        q.push_back(P2{{lo[0] + u(rng) * size[0], lo[1] + u(rng) * size[1]}});
    q.push_back((lo + hi) / 2.0);
    q.push_back(P2{{lo[0] - 10 * size[0], hi[1] + 3 * size[1]}});
    return q;
}

/// Every query's signed distance equals the plain loop's bit for bit (sign of zero included).
void expectSameAsPlain(const std::vector<Loop>& loops, const std::vector<P2>& points) {
    const PolygonSet set(loops);
    int differing = 0;
    for (const P2& x : points) {
        const double fast = set.signedDistance(x), plain = plainSignedDistance(loops, x);
        if (std::bit_cast<std::uint64_t>(fast) != std::bit_cast<std::uint64_t>(plain) &&
            ++differing <= 5)
            ADD_FAILURE() << "at (" << x[0] << ", " << x[1] << "): " << fast << " vs " << plain;
    }
    EXPECT_EQ(differing, 0) << "of " << points.size() << " queries";
}

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

TEST(PolygonTree, RandomStarsEqualThePlainLoop) {
    std::mt19937_64 rng(7);
    for (int n : {3, 4, 5, 9, 17, 64, 300, 2000}) {
        const std::vector<Loop> loops{randomStar(rng, n, P2{{0.3, -0.2}}, 0.1, 1.0)};
        expectSameAsPlain(loops, queries(rng, loops, 2000));
    }
}

TEST(PolygonTree, AdversarialOutlinesEqualThePlainLoop) {
    std::mt19937_64 rng(11);
    const std::vector<std::vector<Loop>> cases{
        {spiral(64, 6)},
        {comb(200)},
        {regular(4096, P2{{0, 0}}, 1)},           // the centre is equally far from all
        {regular(10000, P2{{1e6, -3e6}}, 1e-3)},  // tiny edges far from the origin
        {regular(1000, P2{{0, 0}}, 1e-9)},        // a tiny polygon
        {Loop{P2{{0, 0}}, P2{{1, 0}}, P2{{1, 1}}, P2{{0, 1}}}},  // rays along edges
    };
    for (const auto& loops : cases) expectSameAsPlain(loops, queries(rng, loops, 3000));
}

TEST(PolygonTree, SetsOfLoopsWithHolesEqualThePlainLoop) {
    std::mt19937_64 rng(13);
    // A square with three holes, one holding an island; and loops that touch at a vertex.
    const std::vector<Loop> holes{
        Loop{P2{{0, 0}}, P2{{10, 0}}, P2{{10, 10}}, P2{{0, 10}}},
        regular(50, P2{{3, 3}}, 2),
        regular(7, P2{{7, 7}}, 1.5),
        randomStar(rng, 100, P2{{7, 2.5}}, 1, 2),
        regular(30, P2{{3, 3}}, 1),
    };
    expectSameAsPlain(holes, queries(rng, holes, 5000));
    const std::vector<Loop> touching{Loop{P2{{0, 0}}, P2{{1, 0}}, P2{{1, 1}}},
                                     Loop{P2{{1, 1}}, P2{{2, 1}}, P2{{2, 2}}}};
    expectSameAsPlain(touching, queries(rng, touching, 2000));
}

TEST(PolygonTree, NonFiniteVerticesEqualThePlainLoop) {
    // A vertex not a number or at infinity: no crash, and the plain loop's answers.
    std::mt19937_64 rng(23);
    for (const double bad : {std::nan(""), HUGE_VAL, -HUGE_VAL}) {
        Loop star = randomStar(rng, 40, P2{{0, 0}}, 0.5, 1);
        star[5][0] = bad, star[17][1] = bad;
        const std::vector<Loop> loops{star, regular(12, P2{{0, 0}}, 0.2)};
        expectSameAsPlain(loops, queries(rng, {regular(12, P2{{0, 0}}, 1)}, 2000));
    }
}

TEST(PolygonTree, CrossingCheckEqualsThePlainLoop) {
    // Random points on a 5 x 5 grid: crossings, touchings, collinear overlaps and folds of
    // every kind; the message (which fault, which edges) must be the plain loop's.
    std::mt19937_64 rng(17);
    std::uniform_int_distribution<int> cell(0, 4);
    int accepted = 0, folds = 0, crossings = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        Loop p(3 + trial % 10);
        for (P2& v : p) v = P2{{double(cell(rng)), double(cell(rng))}};
        const std::string expected = plainPolygonError(p);
        ASSERT_EQ(polygonError(p), expected) << "trial " << trial;
        accepted += expected.empty();
        folds += expected.find("folds") != std::string::npos;
        crossings += expected.find("crosses") != std::string::npos;
    }
    EXPECT_GT(accepted, 100);
    EXPECT_GT(folds, 100);
    EXPECT_GT(crossings, 1000);
    // Simple outlines of many points are accepted; one moved vertex is named as the plain loop
    // names it.
    for (int n : {50, 400}) {
        Loop star = randomStar(rng, n, P2{{0, 0}}, 0.5, 1);
        EXPECT_EQ(polygonError(star), "");
        star[n / 3] = P2{{1.5, -0.3}};
        EXPECT_EQ(polygonError(star), plainPolygonError(star));
    }
    EXPECT_EQ(polygonError(spiral(64, 6)), "");
    EXPECT_EQ(polygonError(comb(200)), "");
}

TEST(PolygonTree, CollinearEdgesFarApartDoNotMeet) {
    // Edges 0 and 3 lie on one line, apart. Rounded, the signs of their cross products say
    // that each crosses the other's line: the plain test without the box test refused this
    // outline ("edge 0 and edge 3 meet").
    const P2 p1{{0.005359356248338599, 0.00033471497975352013}},
        p2{{0.043938522119803806, 0.0027441507636833925}},
        q1{{0.0480682777889114, 0.003002071868592372}},
        q2{{0.21565064182853697, 0.013468315385051824}};
    EXPECT_EQ(polygonError({p1, p2, P2{{0.046, 0.05}}, q1, q2, P2{{0.1, -0.05}}}), "");
}

TEST(PolygonTree, LargeOutlineAnswersItsArea) {
    // 200,000 points (the plain loops took minutes for this set-up and these queries; the speed is
    // measured in docs/geometry.md, not here): the share of random points inside is the area's.
    Loop star;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const double r = i % 2 ? 1 : 1 - 1e-5;
        star.push_back(P2{{r * std::cos(2 * pi * i / n), r * std::sin(2 * pi * i / n)}});
    }
    const auto solid = polygon(star);
    std::mt19937_64 rng(19);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    int inside = 0;
    for (int i = 0; i < 20000; ++i) inside += solid->signedDistance(P2{{u(rng), u(rng)}}) < 0;
    EXPECT_NEAR(inside / 20000.0, pi / 9, 0.02);
}

TEST(Polyline, BandOfHalfThickness) {
    const Polyline<2> wall({P2{{0, 0}}, P2{{1, 0}}, P2{{1, 1}}}, 0.1);
    EXPECT_DOUBLE_EQ(wall.signedDistance(P2{{0.5, 0}}), -0.1);
    EXPECT_DOUBLE_EQ(wall.signedDistance(P2{{0.5, 0.5}}), 0.4);
    EXPECT_DOUBLE_EQ(wall.signedDistance(P2{{-1, 0}}), 0.9);
    EXPECT_DOUBLE_EQ(wall.bounds().min[1], -0.1);
}

}  // namespace
