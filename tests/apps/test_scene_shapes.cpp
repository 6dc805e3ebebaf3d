// Shapes and walls as the scene reader and set-up take them: a box or ball without a
// transformation keeps its fast path (the CUDA back end's BoxOrBall), any other shape becomes a
// solid; an interior wall's particles take its velocity, slip and thermal condition.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "app/scene_loader.hpp"
#include "app/scene_setup.hpp"
#include "sph/boundary/thermal_condition.hpp"

using namespace num;
using nlohmann::json;

namespace {

json tinyScene() {
    return json::parse(R"({
      "dimension": 2,
      "domain": {"min": [0, 0], "max": [0.4, 0.4]},
      "boundaries": {"x_min": {"type": "wall"}, "x_max": {"type": "wall"},
                     "y_min": {"type": "wall"}, "y_max": {"type": "wall"}},
      "particles": {"spacing": 0.02},
      "time": {"end": 0.01},
      "gravity": [0, -9.81],
      "materials": {"water": {"density": 1000}},
      "fluids": [{"material": "water", "shape": "box", "min": [0, 0], "max": [0.2, 0.2]}]
    })");
}

app::Scene<2> read(const json& j) {
    return app::readScene<2>(app::SceneDocument::fromText(j.dump(), "scene.json"));
}

bool insideDomain(const sph::Vector<2>& x) {
    return x[0] > 0 && x[0] < 0.4 && x[1] > 0 && x[1] < 0.4;
}

}  // namespace

TEST(SceneShapes, BoxesAndBallsKeepTheirFastPath) {
    json j = tinyScene();
    j["bodies"] = json::array({{{"shape", "circle"}, {"center", {0.3, 0.1}}, {"radius", 0.05}}});
    const app::Scene<2> plain = read(j);
    EXPECT_EQ(plain.fluids[0].shape, app::ShapeKind::BOX);
    EXPECT_EQ(plain.bodies[0].shape, app::ShapeKind::CIRCLE);
    EXPECT_FALSE(plain.bodies[0].solid);
    j["bodies"][0]["translate"] = {0.01, 0};
    j["fluids"][0]["rotate"] = 0;
    const app::Scene<2> moved = read(j);
    EXPECT_EQ(moved.bodies[0].shape, app::ShapeKind::SOLID);
    EXPECT_EQ(moved.fluids[0].shape, app::ShapeKind::SOLID);
    EXPECT_NEAR(moved.bodies[0].solid->signedDistance({{0.31, 0.1}}), -0.05, 1e-12);
}

TEST(SceneShapes, InteriorWallsTakeVelocitySlipAndThermalCondition) {
    json j = tinyScene();
    j["walls"] = json::array({{{"shape", "polygon"},
                               {"points", {{0.25, 0.25}, {0.35, 0.25}, {0.3, 0.35}}},
                               {"thermal", {{"temperature", 50}}},
                               {"velocity", {0.1, 0}},
                               {"slip", true}},
                              {{"shape", "box"},
                               {"min", {0.25, 0.02}},
                               {"max", {0.38, 0.1}},
                               {"thermal", {{"heat_flux", 1000}}}}});
    const app::Scene<2> scene = read(j);
    ASSERT_EQ(scene.walls.size(), 2u);
    app::SceneSetup<2> setup = app::makeSceneSetup(scene, 1);
    const sph::Storage<2> st = app::makeInitialStorage(scene, setup);
    const auto x = st.getValue<sph::Vector<2>>(sph::QuantityId::POSITION);
    const auto kind = st.getValue<int>(sph::QuantityId::KIND);
    const auto T = st.getValue<double>(sph::QuantityId::TEMPERATURE);
    const auto v = st.getValue<sph::Vector<2>>(sph::QuantityId::WALL_VELOCITY);
    const auto cond = st.getValue<int>(sph::heat_ids::THERMAL_CONDITION);
    int held = 0, heaters = 0;
    for (sph::Size i = 0; i < st.size(); ++i) {
        if (kind[i] != int(sph::ParticleKind::WALL) || !insideDomain(x[i])) continue;
        if (setup.geometry.interiorWalls[0].contains(x[i])) {
            ++held;
            EXPECT_EQ(cond[i], int(sph::ThermalCondition::FIXED_TEMPERATURE));
            EXPECT_EQ(T[i], 50);
            EXPECT_EQ(v[i][0], 0.1);
        } else {
            ASSERT_TRUE(setup.geometry.interiorWalls[1].contains(x[i]));
            heaters += cond[i] == int(sph::ThermalCondition::HEAT_FLUX);
        }
    }
    EXPECT_GT(held, 0);
    EXPECT_GT(heaters, 0);
    EXPECT_EQ(setup.geometry.interiorWalls[0].slip, sph::WallSlip::FREE_SLIP);
    EXPECT_EQ(setup.geometry.interiorWalls[1].slip, sph::WallSlip::NO_SLIP);
}
