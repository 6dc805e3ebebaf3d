// Triangle meshes: every file format, the exact volume, lattice-counted volumes against it, the
// tree against brute force, a mesh against the equivalent primitive, sections, and each bad mesh
// with its message. The meshes are those of scenes/meshes/ (scripts/make_meshes.py).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <random>
#include <string>

#include "geometry/combination.hpp"
#include "geometry/mesh_solid.hpp"
#include "geometry/polygon.hpp"
#include "geometry/revolved.hpp"
#include "geometry/scale_check.hpp"
#include "triangle_tree.hpp"

namespace {

using namespace num::geometry;
using P2 = Point<2>;
using P3 = Point<3>;
constexpr double pi = std::numbers::pi;

std::string meshFile(const std::string& name) { return std::string(GEOMETRY_MESHES) + "/" + name; }

MeshSolid solidOf(const std::string& name) { return MeshSolid(readMesh(meshFile(name)), name); }

/// The volume of a profile polygon (r, z) revolved in n flat sectors: each cross-section is a
/// regular n-gon of area (n/2) sin(2 pi/n) r^2, so V = n sin(2 pi/n) * integral of r dA over
/// the profile, the integral by the polygon formula sum (r_i z_j - r_j z_i)(r_i + r_j) / 6.
double revolvedVolume(const std::vector<P2>& profile, int n) {
    double moment = 0;
    for (std::size_t i = 0; i < profile.size(); ++i) {
        const P2 &a = profile[i], &b = profile[(i + 1) % profile.size()];
        moment += (a[0] * b[1] - b[0] * a[1]) * (a[0] + b[0]) / 6;
    }
    return std::abs(n * std::sin(2 * pi / n) * moment);
}

/// The profiles of make_meshes.py: a half circle of 0.1 m in n/2 rings; a circle of 0.04 m at
/// 0.1 m from the axis in n/2 points.
std::vector<P2> sphereProfile(int n) {
    std::vector<P2> p;
    for (int j = 0; j <= n / 2; ++j)
        p.push_back(P2{{0.1 * std::sin(pi * j / (n / 2)), -0.1 * std::cos(pi * j / (n / 2))}});
    return p;
}
std::vector<P2> torusProfile(int n) {
    std::vector<P2> p;
    for (int j = 0; j < n / 2; ++j)
        p.push_back(P2{
            {0.1 + 0.04 * std::cos(2 * pi * j / (n / 2)), 0.04 * std::sin(2 * pi * j / (n / 2))}});
    return p;
}

/// Points of the lattice of spacing h (cell centres) inside the solid, times h^3.
double latticeVolume(const Solid<3>& s, double h) {
    const Bounds<3> b = s.bounds();
    long count = 0;
    for (double x = std::floor(b.min[0] / h) * h + h / 2; x < b.max[0]; x += h)
        for (double y = std::floor(b.min[1] / h) * h + h / 2; y < b.max[1]; y += h)
            for (double z = std::floor(b.min[2] / h) * h + h / 2; z < b.max[2]; z += h)
                count += s.contains(P3{{x, y, z}});
    return count * h * h * h;
}

TEST(Mesh, EveryFormatReadsTheSameSphere) {
    const double exact = revolvedVolume(sphereProfile(12), 12);
    for (const char* name : {"sphere_coarse.stl", "sphere_coarse_ascii.stl", "sphere_coarse.obj",
                             "sphere_coarse.ply"}) {
        TriangleMesh mesh = readMesh(meshFile(name));
        EXPECT_EQ(mesh.vertices.size(), 62u) << name;  // 5 rings of 12 and the two poles
        EXPECT_EQ(mesh.triangles.size(), 120u) << name;
        checkClosedVolume(mesh, name);
        EXPECT_NEAR(enclosedVolume(mesh), exact, 1e-6 * exact) << name;  // float coordinates
    }
}

TEST(Mesh, ExactVolumeOfTheFacetedShapes) {
    const double sphere = enclosedVolume(solidOf("sphere.stl").mesh());
    EXPECT_NEAR(sphere, revolvedVolume(sphereProfile(48), 48), 1e-6 * sphere);
    // The faceting error of 48 sectors and 24 rings against the round sphere: 0.7 %.
    EXPECT_NEAR(sphere, 4 * pi / 3 * 1e-3, 0.008 * sphere);
    const double torus = enclosedVolume(solidOf("torus.stl").mesh());
    EXPECT_NEAR(torus, revolvedVolume(torusProfile(48), 48), 1e-6 * torus);
    EXPECT_NEAR(torus, 2 * pi * pi * 0.1 * 0.04 * 0.04, 0.02 * torus);
}

/// Lattice-counted volumes within 1 % of the mesh's exact volume at the documented spacing
/// h = 0.005 m (the sphere's radius / 20, the torus's minor radius / 8), and at h / 2; the error
/// at h / 2 below the one at 2 h.
TEST(Mesh, LatticeVolumeConverges) {
    for (const char* name : {"sphere.stl", "torus.stl"}) {
        const MeshSolid s = solidOf(name);
        const double exact = enclosedVolume(s.mesh()), h = 0.005;
        double error[3];
        for (int i = 0; i < 3; ++i)
            error[i] = std::abs(latticeVolume(s, 2 * h / (1 << i)) / exact - 1);
        EXPECT_LT(error[1], 0.01) << name;
        EXPECT_LT(error[2], 0.01) << name;
        EXPECT_LT(error[2], error[0]) << name;
        std::printf("%s: lattice volume error %.3f %%, %.3f %%, %.3f %% at spacing %g, %g, %g\n",
                    name, 100 * error[0], 100 * error[1], 100 * error[2], 2 * h, h, h / 2);
    }
}

TEST(Mesh, TreeAgreesWithBruteForceAndSphere) {
    const MeshSolid s = solidOf("sphere.stl");
    const TriangleMesh& m = s.mesh();
    std::mt19937 random(7);
    std::uniform_real_distribution<double> u(-0.15, 0.15);
    for (int i = 0; i < 300; ++i) {
        const P3 x{{u(random), u(random), u(random)}};
        double best = HUGE_VAL;
        for (const auto& t : m.triangles)
            best = std::min(
                best, normSqr(x - detail::nearestOnTriangle(x, m.vertices[t[0]], m.vertices[t[1]],
                                                            m.vertices[t[2]])
                                      .point));
        const double d = s.signedDistance(x);
        EXPECT_NEAR(std::abs(d), std::sqrt(best), 1e-15);
        // Within the faceting error of the round sphere's: at most R (1 - cos^2(pi/48)) = 4.3e-4 m
        // at the middle of a facet of 7.5 by 7.5 degrees.
        EXPECT_NEAR(d, norm(x) - 0.1, 0.1 * (1 - std::pow(std::cos(pi / 48), 2)));
    }
    EXPECT_NEAR(s.outwardNormal(P3{{0, 0, 0.2}})[2], 1, 1e-12);
    EXPECT_NEAR(s.outwardNormal(P3{{0.05, 0, 0}})[0], 1, 0.01);
}

/// Lattice points (spacing h over the solid's box and a margin) where the mesh and the
/// primitive agree on inside or outside, counting only those farther from the primitive's
/// surface than the faceting error; fails on the first that differs.
int samePoints(const Solid<3>& mesh, const Solid<3>& primitive, double h, double faceting) {
    const Bounds<3> b = primitive.bounds();
    int compared = 0;
    for (double x = b.min[0] - 2.1 * h; x < b.max[0] + 2 * h; x += h)
        for (double y = b.min[1] - 2.1 * h; y < b.max[1] + 2 * h; y += h)
            for (double z = b.min[2] - 2.1 * h; z < b.max[2] + 2 * h; z += h) {
                const P3 p{{x, y, z}};
                if (std::abs(primitive.signedDistance(p)) <= faceting) continue;
                EXPECT_EQ(mesh.contains(p), primitive.contains(p)) << x << " " << y << " " << z;
                if (mesh.contains(p) != primitive.contains(p)) return compared;
                ++compared;
            }
    return compared;
}

TEST(Mesh, CylinderAndCupMeshesHoldThePointsOfTheirPrimitives) {
    const auto round = cylinder(P3{{0, 0, 0}}, P3{{0, 0, 0.1}}, 0.05);
    EXPECT_GT(samePoints(solidOf("cylinder.stl"), *round, 0.005, 0.05 * (1 - std::cos(pi / 48))),
              10000);
    // The cup: a cylinder of radius 0.04 m and height 0.1 m less one of radius 0.035 m from
    // 0.005 m up; its thin wall and inner corners test the signs of edges and vertices.
    const Combination<3> cup(Combine::DIFFERENCE,
                             {cylinder(P3{{0, 0, 0}}, P3{{0, 0, 0.1}}, 0.04),
                              cylinder(P3{{0, 0, 0.005}}, P3{{0, 0, 0.2}}, 0.035)});
    EXPECT_GT(samePoints(solidOf("cup.stl"), cup, 0.002, 0.04 * (1 - std::cos(pi / 48))), 50000);
}

TEST(Mesh, SectionOfASphereIsACircle) {
    const TriangleMesh m = solidOf("sphere.stl").mesh();
    const double z = 0.03, r = std::sqrt(0.1 * 0.1 - z * z);
    const auto loops = sectionLoops(m, 2, z);
    ASSERT_EQ(loops.size(), 1u);
    const PolygonSet section(loops);
    for (const P2& p : loops[0]) EXPECT_NEAR(norm(p), r, 0.1 * (1 - std::cos(pi / 24)));
    EXPECT_NEAR(section.signedDistance(P2{{0, 0}}), -r, 0.1 * (1 - std::cos(pi / 24)));
    EXPECT_TRUE(sectionLoops(m, 0, 0.2).empty());
    // Through a ring of vertices: still one loop, of the ring's 48 points.
    std::size_t k = 0;
    while (!(m.vertices[k][2] > 0.02)) ++k;
    const auto ring = sectionLoops(m, 2, m.vertices[k][2]);
    ASSERT_EQ(ring.size(), 1u);
    EXPECT_EQ(ring[0].size(), 48u);
    for (const P2& p : ring[0])
        EXPECT_NEAR(norm(p), std::hypot(m.vertices[k][0], m.vertices[k][1]),
                    1e-7);  // float coordinates
    // The torus cut through its axis: two circles.
    EXPECT_EQ(sectionLoops(solidOf("torus.stl").mesh(), 0, 0.0).size(), 2u);
}

/// The message of the GeometryError that reading and checking `text` as `name` throws.
std::string meshError(const std::string& name, const std::string& text) {
    const std::string path = testing::TempDir() + name;
    std::ofstream(path) << text;
    try {
        MeshSolid(readMesh(path), name);
    } catch (const GeometryError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no error for " << name;
    return "";
}

/// A tetrahedron in OBJ, its faces outward, with `faces` replacing them when given.
std::string tetrahedron(const std::string& faces = "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n") {
    return "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n" + faces;
}

TEST(Mesh, BadMeshesSayWhatIsWrong) {
    EXPECT_NO_THROW(MeshSolid(readMesh(meshFile("obstacle.stl")), "obstacle.stl"));
    EXPECT_EQ(meshError("open.obj", tetrahedron("f 1 3 2\nf 1 2 4\nf 2 3 4\n")),
              "open.obj is not closed: 3 open edges (one from (0, 0, 0) to (0, 1, 0)): a volume "
              "needs a closed surface; fill the holes");
    EXPECT_EQ(
        meshError("flipped.obj", tetrahedron("f 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 3 4\n")),
        "flipped.obj is not consistently oriented: 3 edges where two triangles face opposite ways "
        "(one from (0, 0, 0) to (0, 1, 0)): unify the normals (repair the mesh)");
    // Two tetrahedra sharing the edge from (0, 0, 0) to (0, 0, 1).
    EXPECT_NE(meshError("shared.obj",
                        tetrahedron() + "v -1 0 0\nv 0 -1 0\nf 1 6 5\nf 1 5 4\nf 5 6 4\nf 1 4 6\n")
                  .find("shared.obj is not manifold: 1 edges shared by more than two triangles"),
              std::string::npos);
    EXPECT_EQ(meshError("flat.obj", tetrahedron() + "v 2 0 0\nf 1 2 5\n"),
              "flat.obj: triangle 4 at (0, 0, 0) has zero area: remove degenerate triangles "
              "(repair the mesh)");
    // Two tetrahedra, each closed, one through the other: the slanted face of the first crosses
    // the three faces of the second at x, y, z = 0.2.
    EXPECT_EQ(
        meshError("overlap.obj", "v 0.2 0.2 0.2\nv 1.2 0.2 0.2\nv 0.2 1.2 0.2\nv 0.2 0.2 1.2\n" +
                                     tetrahedron("f 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n"
                                                 "f 5 7 6\nf 5 6 8\nf 6 7 8\nf 5 8 7\n")),
        "overlap.obj intersects itself: 3 pairs of triangles cross (triangles 0 and 6, near "
        "(0.2, 0.2, 0.2)), where its inside is ambiguous: repair the mesh (a union of the "
        "overlapping parts)");
    const std::string notMesh = meshError("notes.stl", "these are notes, not a mesh\n");
    EXPECT_EQ(notMesh.rfind(testing::TempDir() + "notes.stl: not a readable mesh (", 0), 0u)
        << notMesh;
    EXPECT_NE(meshError("missing.stl", "").find("not a readable mesh"), std::string::npos);
}

TEST(Mesh, InsideOutMeshIsTurned) {
    const std::string path = testing::TempDir() + "inward.obj";
    std::ofstream(path) << tetrahedron("f 1 2 3\nf 1 4 2\nf 2 4 3\nf 1 3 4\n");
    const MeshSolid s(readMesh(path), "inward.obj");
    EXPECT_LT(s.signedDistance(P3{{0.1, 0.1, 0.1}}), 0);
    EXPECT_NEAR(enclosedVolume(s.mesh()), 1.0 / 6, 1e-15);
}

TEST(Mesh, ScaleWarning) {
    const Bounds<3> domain{P3{{0, 0, 0}}, P3{{1, 0.5, 0.5}}};
    EXPECT_EQ(scaleWarning(Bounds<3>{P3{{0, 0, 0}}, P3{{800, 100, 100}}}, domain),
              "the shape is about 1000 times larger than the domain: is it in other units? "
              "(\"scale\": 0.001 would fit it)");
    EXPECT_NE(
        scaleWarning(Bounds<3>{P3{{0, 0, 0}}, P3{{1e-3, 1e-3, 1e-3}}}, domain).find("smaller"),
        std::string::npos);
    EXPECT_EQ(scaleWarning(Bounds<3>{P3{{0, 0, 0}}, P3{{0.2, 0.2, 0.2}}}, domain), "");
    EXPECT_EQ(scaleWarning(Bounds<3>{}, domain), "");
}

}  // namespace
