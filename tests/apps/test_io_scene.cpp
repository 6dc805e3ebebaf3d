// The scene reader on its own: defaults, overrides by dotted path, every scene in scenes/ loads.
#include <gtest/gtest.h>

#include <filesystem>

#include "io/scene_loader.hpp"

using namespace num::io;

TEST(SceneReader, DefaultsAndOverrides) {
    SceneDocument doc = SceneDocument::fromFile(std::string(APP_TEST_SCENES_DIR) + "/tiny_2d.json");
    doc.set("time.cfl=0.2");
    doc.set("fluids.0.velocity=[1, \"2*t\"]");
    const Scene<2> s = readScene<2>(doc);
    EXPECT_EQ(s.cfl, 0.2);
    EXPECT_EQ(s.hOverSpacing, 1.3);
    EXPECT_EQ(s.fluids[0].velocity[0](0, 0, 0, 0), 1.0);
    EXPECT_EQ(s.fluids[0].velocity[1](0, 0, 0, 0.5), 1.0);
    EXPECT_EQ(s.gravity[1](0, 0, 0, 0.005), -9.81 * 0.5);  // "-9.81*min(t/0.01, 1)"
    EXPECT_EQ(s.sides[0][1].thermal.kind, ThermalCondition::Kind::TEMPERATURE);
    EXPECT_EQ(s.sides[1][1].type, SideType::OPEN);
    EXPECT_THROW(doc.set("fluids.7.temperature=3"), AppError);
}

TEST(SceneReader, EveryShippedSceneLoads) {
    int count = 0;
    for (const auto& e : std::filesystem::directory_iterator(std::string(NUMERICS_SCENES_DIR))) {
        if (e.path().extension() != ".json") continue;
        SCOPED_TRACE(e.path().string());
        const SceneDocument doc = SceneDocument::fromFile(e.path().string());
        if (doc.dimension() == 2)
            EXPECT_NO_THROW(readScene<2>(doc));
        else
            EXPECT_NO_THROW(readScene<3>(doc));
        ++count;
    }
    EXPECT_GE(count, 3);
}
