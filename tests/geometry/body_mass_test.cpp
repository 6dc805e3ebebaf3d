// Free bodies read from scene text take the exact mass properties of their shapes: a polygon's
// (2D) and a turned box's (3D), which a lattice quadrature would give only to the lattice's
// resolution; a plain box keeps its closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/scene_loader.hpp"
#include "scene/moving_bodies.hpp"

namespace {

using nlohmann::json;
using num::app::readScene;
using num::app::SceneDocument;

/// The moving bodies of a scene of the given dimension in walls whose only body is `body`.
template <int Dim>
std::shared_ptr<num::sph::MovingBodies<Dim>> bodiesOf(const std::string& body) {
    json j = json::parse(R"({"particles": {"spacing": 0.05}, "time": {"end": 0.1},
        "materials": {"water": {"density": 1000, "sound_speed": 20}}})");
    j["dimension"] = Dim;
    j["domain"] = {{"min", std::vector<double>(Dim, 0)}, {"max", std::vector<double>(Dim, 1)}};
    for (const char* side : {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"})
        if (Dim == 3 || side[0] != 'z') j["boundaries"][side] = {{"type", "wall"}};
    std::vector<double> top(Dim, 1);
    top.back() = 0.1;
    j["fluids"] = {
        {{"material", "water"}, {"shape", "box"}, {"min", j["domain"]["min"]}, {"max", top}}};
    j["bodies"] = {json::parse(body)};
    return num::app::makeMovingBodies(
        readScene<Dim>(SceneDocument::fromText(j.dump(), "scene.json")));
}

// A triangle (0.2, 0.3), (0.8, 0.3), (0.5, 0.9) of density 500: A = 0.18, centroid (0.5, 0.5),
// J = A (|ab|^2 + |bc|^2 + |ca|^2) / 36 = 0.18 (0.36 + 0.45 + 0.45) / 36.
TEST(BodyMass, APolygonBodyTakesThePolygonsExactInertia) {
    const auto bodies = bodiesOf<2>(R"({"shape": "polygon",
        "points": [[0.2, 0.3], [0.8, 0.3], [0.5, 0.9]], "motion": {"type": "free", "density": 500}})");
    ASSERT_TRUE(bodies);
    const auto& body = bodies->bodies.at(0);
    EXPECT_NEAR(body.motion.mass, 500 * 0.18, 1e-12);
    EXPECT_NEAR(body.initialPosition[0], 0.5, 1e-14);
    EXPECT_NEAR(body.initialPosition[1], 0.5, 1e-14);
    EXPECT_NEAR(body.motion.inertia.zz, 500 * 0.18 * 1.26 / 36, 1e-14);
}

// A box [0.3, 0.5] x [0.4, 0.8] x [0.4, 0.6] turned by 90 degrees about z (a SOLID, not the box
// fast path) has the diagonal inertia of the box it becomes, V (b^2 + c^2) / 12 and so on.
TEST(BodyMass, ATurnedBoxHasTheRotatedTensor) {
    const auto bodies = bodiesOf<3>(R"({"shape": "box", "min": [-0.1, -0.2, -0.1],
        "max": [0.1, 0.2, 0.1], "rotate": [0, 0, 90], "translate": [0.5, 0.5, 0.5],
        "motion": {"type": "free", "density": 1000}})");
    ASSERT_TRUE(bodies);
    const auto& m = bodies->bodies.at(0).motion;
    const double mass = 1000 * 0.2 * 0.4 * 0.2;
    EXPECT_NEAR(m.mass, mass, 1e-12);
    const double expected[3] = {mass * (0.04 + 0.04) / 12, mass * (0.16 + 0.04) / 12,
                                mass * (0.16 + 0.04) / 12};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            EXPECT_EQ(m.inertia.rows[i][j], m.inertia.rows[j][i]);
            EXPECT_NEAR(m.inertia.rows[i][j], i == j ? expected[i] : 0, 1e-14) << i << j;
        }
}

// A plain box (the fast path) keeps its closed form.
TEST(BodyMass, APlainBoxKeepsItsClosedForm) {
    const auto bodies = bodiesOf<2>(R"({"shape": "box", "min": [0.2, 0.4], "max": [0.5, 0.6],
        "motion": {"type": "free", "density": 800}})");
    ASSERT_TRUE(bodies);
    const auto& m = bodies->bodies.at(0).motion;
    const double area = (0.5 - 0.2) * (0.6 - 0.4), e2 = 0.3 * 0.3 + 0.2 * 0.2;
    EXPECT_EQ(m.mass, 800 * area);
    EXPECT_NEAR(m.inertia.zz, 800 * area * e2 / 12, 1e-15);
}

}  // namespace
