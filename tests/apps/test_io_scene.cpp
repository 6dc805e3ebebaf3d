// The scene reader on its own: defaults, overrides by dotted path, every scene in scenes/ loads.
#include <gtest/gtest.h>

#include <filesystem>

#include "app/density_choice.hpp"
#include "app/scene_loader.hpp"
#include "scene/boundary_types.hpp"
#include "sph/equation_of_state_choice.hpp"
#include "sph/evaluation_mode.hpp"
#include "sph/integrator_choice.hpp"
#include "sph/kernel_table.hpp"

using namespace num::app;

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
    EXPECT_TRUE(s.sides[0][1]->heldTemperature().has_value());
    EXPECT_STREQ(s.sides[1][1]->type(), "open");
    EXPECT_THROW(doc.set("fluids.7.temperature=3"), AppError);
}

TEST(SceneReader, EveryShippedSceneLoads) {
    int count = 0;
    for (const auto& e : std::filesystem::directory_iterator(std::string(NUMERICS_SCENES_DIR))) {
        if (e.path().extension() != ".json") continue;
        SCOPED_TRACE(e.path().string());
        const SceneDocument doc = SceneDocument::fromFile(e.path().string());
        // No shipped scene has an open side facing sideways to gravity (water lost sideways).
        if (doc.dimension() == 2)
            EXPECT_TRUE(readScene<2>(doc).warnings.empty());
        else
            EXPECT_TRUE(readScene<3>(doc).warnings.empty());
        ++count;
    }
    EXPECT_GE(count, 3);
}

TEST(SceneReader, SideNamesAreAxisAndEnd) {
    SceneDocument doc = SceneDocument::fromFile(std::string(APP_TEST_SCENES_DIR) + "/tiny_3d.json");
    doc.set("boundaries.z_min.thermal={\"temperature\": 50}");
    const Scene<3> s = readScene<3>(doc);
    EXPECT_EQ(s.sides[2][0]->heldTemperature(), 50.0);  // z_min: axis 2, low end
    EXPECT_STREQ(s.sides[2][1]->type(), "open");        // z_max: the top, against gravity
    EXPECT_TRUE(s.warnings.empty());
}

TEST(SceneReader, OpenSideSidewaysToGravityWarns) {
    SceneDocument doc = SceneDocument::fromFile(std::string(APP_TEST_SCENES_DIR) + "/tiny_3d.json");
    doc.set("boundaries.z_max.type=wall");
    doc.set("boundaries.y_max.type=open");
    const Scene<3> s = readScene<3>(doc);
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("boundaries.y_max"), std::string::npos) << s.warnings[0];
    EXPECT_NE(s.warnings[0].find("sideways to gravity"), std::string::npos) << s.warnings[0];
    EXPECT_NE(s.warnings[0].find("z_max"), std::string::npos) << s.warnings[0];
}

TEST(SceneReader, SetCreatesAMissingParentObject) {
    SceneDocument doc = SceneDocument::fromFile(std::string(APP_TEST_SCENES_DIR) + "/tiny_2d.json");
    ASSERT_FALSE(doc.json().contains("physics"));
    doc.set("physics.shifting=false");
    doc.set("physics.density_diffusion=0.05");
    EXPECT_FALSE(readScene<2>(doc).physics.shifting);
    EXPECT_EQ(readScene<2>(doc).physics.densityDiffusion, 0.05);
    // A misspelt parent is created too, then refused by the reader with a suggestion.
    doc.set("physcs.heat=false");
    try {
        readScene<2>(doc);
        ADD_FAILURE() << "a misspelt key was accepted";
    } catch (const AppError& e) {
        EXPECT_EQ(e.code(), ExitCode::SCENE);
        EXPECT_NE(std::string(e.what()).find("did you mean 'physics'"), std::string::npos)
            << e.what();
    }
    // A value that is not an object is not replaced by one.
    EXPECT_THROW(doc.set("time.end.value=1"), AppError);
}

TEST(SceneReader, PairLoopEvaluation) {
    SceneDocument doc = SceneDocument::fromFile(std::string(APP_TEST_SCENES_DIR) + "/tiny_2d.json");
    EXPECT_EQ(readScene<2>(doc).evaluation, "asymmetric");  // defaults::evaluation
    doc.set("particles.evaluation=\"symmetric\"");
    EXPECT_EQ(readScene<2>(doc).evaluation, "symmetric");
    doc.set("particles.evaluation=\"pairs\"");
    EXPECT_THROW(readScene<2>(doc), AppError);
}

/// The message of readScene's refusal of `doc` (empty if it was accepted).
std::string refusal(const SceneDocument& doc) {
    try {
        readScene<2>(doc);
    } catch (const AppError& e) {
        EXPECT_EQ(e.code(), ExitCode::SCENE);
        return e.what();
    }
    ADD_FAILURE() << "accepted";
    return "";
}

// Every choice's table (sph/choice_table.hpp) gives the values the reader accepts and lists them
// all when it refuses one.
template <class Table>
void expectTheTableDrivesTheChoice(const std::string& key, const Table& table) {
    SCOPED_TRACE(key);
    SceneDocument doc = SceneDocument::fromFile(std::string(APP_TEST_SCENES_DIR) + "/tiny_2d.json");
    for (const std::string& name : num::sph::choiceNames(table)) {
        doc.set(key + "=\"" + name + "\"");
        EXPECT_NO_THROW(readScene<2>(doc)) << name;
    }
    doc.set(key + "=\"no_such_choice\"");
    const std::string message = refusal(doc);
    EXPECT_NE(message.find(key), std::string::npos) << message;
    for (const std::string& name : num::sph::choiceNames(table))
        EXPECT_NE(message.find("\"" + name + "\""), std::string::npos) << message;
}

TEST(SceneReader, TheTablesDriveTheChoices) {
    expectTheTableDrivesTheChoice("particles.kernel", num::sph::kernelTable);
    expectTheTableDrivesTheChoice("particles.evaluation", num::sph::evaluationTable);
    expectTheTableDrivesTheChoice("time.integrator", num::sph::integratorTable);
    expectTheTableDrivesTheChoice("physics.eos", num::sph::eosTable);
    expectTheTableDrivesTheChoice("physics.density", densityTable);
}

TEST(SceneReader, BoundaryTypesComeFromTheTable) {
    const std::string tiny = std::string(APP_TEST_SCENES_DIR) + "/tiny_2d.json";
    SceneDocument doc = SceneDocument::fromFile(tiny);
    doc.set("boundaries.x_min.type=sloshing");
    const std::string unknown = refusal(doc);
    for (const BoundaryType<2>& type : boundaryTypes<2>())
        EXPECT_NE(unknown.find("\"" + type.name + "\""), std::string::npos) << unknown;

    nlohmann::json j = SceneDocument::fromFile(tiny).json();
    j["boundaries"].erase("x_min");
    const std::string missing = refusal(SceneDocument::fromText(j.dump(), "tiny_2d.json"));
    EXPECT_NE(missing.find(boundaryTypeChoices<2>()), std::string::npos) << missing;

    // A key of one type on a side of another names the types it applies to.
    doc = SceneDocument::fromFile(tiny);
    doc.set("boundaries.y_max.type=open");
    doc.set("boundaries.y_max.slip=true");
    const std::string other = refusal(doc);
    EXPECT_NE(other.find("boundaries.y_max.slip"), std::string::npos) << other;
    EXPECT_NE(other.find("no 'slip' on an open side (it applies to wall sides only)"),
              std::string::npos)
        << other;
}

TEST(SceneReader, EveryTableTypeReadsIntoItsModule) {
    for (const BoundaryType<2>& type : boundaryTypes<2>()) {
        SceneDocument doc =
            SceneDocument::fromFile(std::string(APP_TEST_SCENES_DIR) + "/tiny_2d.json");
        // An inlet needs its velocity, into the domain on each side.
        for (const char* side : {"x_min", "x_max"})
            doc.set(std::string("boundaries.") + side + "=" + "{\"type\": \"" + type.name + "\"" +
                    (type.name == "inlet" ? side == std::string("x_min")
                                                ? R"(, "velocity": [1, 0])"
                                                : R"(, "velocity": [-1, 0])"
                                          : "") +
                    "}");
        const Scene<2> s = readScene<2>(doc);
        EXPECT_EQ(s.sides[0][0]->type(), type.name);
        EXPECT_EQ(s.sides[0][1]->type(), type.name);
    }
}
