// Bad plugins and bad plugin scenes: each a one-line error with its exit code
// (docs/scenes.md), never a crash; and restarts with other plugins refused.
#include <filesystem>

#include "plugin_test_support.hpp"

namespace {

using apptest::contains;
using plugintest::json;

constexpr int kScene = 5, kCheckpoint = 8, kPlugin = 10;

/// The 2D spring scene, short, with one plugin entry of `library` and `terms`.
json sceneWith(const std::string& library, const json& terms, int dim = 2) {
    json s = plugintest::exampleScene("spring_" + std::to_string(dim) + "d.json");
    s["time"]["end"] = 0.1;
    s["plugins"] = json::array({{{"library", library}, {"terms", terms}}});
    return s;
}

/// Runs the scene and expects exit `code` with one error line that holds `message`.
void expectError(const std::string& name, const json& scene, int code, const std::string& message,
                 const char* app = FLUID_SIM) {
    const std::string dir = apptest::freshDir("plugin_error_" + name);
    const auto r = plugintest::runScene(app, scene, dir);
    EXPECT_EQ(r.code, code) << r.output;
    const auto lines = plugintest::errorLines(r.output);
    ASSERT_EQ(lines.size(), 1u) << r.output;
    EXPECT_TRUE(contains(lines[0], message)) << lines[0];
    EXPECT_FALSE(contains(r.output, "internal error")) << r.output;
}

const json kSpring = json::array({{{"term", "spring"}, {"stiffness", 63.2}}});

TEST(PluginErrors, MissingLibrary) {
    expectError("missing", sceneWith("no_such_plugin.so", kSpring), kScene,
                "scene.json: plugins.0.library: no plugin library " + std::string(APP_TEST_WORK) +
                    "/plugin_error_missing/no_such_plugin.so (expected a file");
}

TEST(PluginErrors, NotAPlugin) {
    expectError("not_a_plugin", sceneWith(NOT_A_PLUGIN, kSpring), kPlugin,
                "is not a numerics plugin: it does not export numerics_plugin_entry");
}

TEST(PluginErrors, ApiVersionMismatch) {
    expectError("version", sceneWith(WRONG_VERSION_PLUGIN, kSpring), kPlugin,
                "was built against plugin API version 999, fluid_sim has version 1");
}

TEST(PluginErrors, UnknownTerm) {
    expectError("unknown_term",
                sceneWith(SPRING_PLUGIN, json::array({{{"term", "sprung"}, {"stiffness", 1}}})),
                kScene,
                "plugins.0.terms.0.term: expected a term of libspring_plugin.so (spring), found "
                "the string \"sprung\" (did you mean \"spring\"?)");
}

TEST(PluginErrors, BadParameters) {
    json terms = kSpring;
    terms.push_back({{"term", "spring"}, {"stiffness", -3}});
    expectError("bad_parameter", sceneWith(SPRING_PLUGIN, terms), kScene,
                "scene.json: plugins.0.terms.1.stiffness: expected a positive number [N/m], "
                "found -3");
    expectError("unknown_parameter",
                sceneWith(SPRING_PLUGIN, json::array({{{"term", "spring"}, {"stifness", 1}}})),
                kScene,
                "plugins.0.terms.0.stifness: expected one of the keys stiffness, "
                "steps_per_radian, found the unknown key 'stifness' (did you mean "
                "'stiffness'?)");
}

TEST(PluginErrors, KeysTheFactoryDidNotReadAreErrors) {
    // The term reads "strength" without allow(): a misspelt key is still caught.
    expectError(
        "unread_key",
        sceneWith(FAULTY_PLUGIN, json::array({{{"term", "reads_strength"}, {"strenght", 2}}})),
        kScene,
        "scene.json: plugins.0.terms.0.strenght: expected one of the parameters strength "
        "of the term \"reads_strength\", found the unknown key 'strenght' (did you mean "
        "'strength'?)");
}

TEST(PluginErrors, TermThrowsDuringSetUp) {
    expectError("throws_when_made",
                sceneWith(FAULTY_PLUGIN, json::array({{{"term", "throws_when_made"}}})), kPlugin,
                "term \"throws_when_made\" (plugins.0.terms.0, libtest_faulty_plugin.so) failed "
                "when made from its parameters: the test factory refuses its parameters");
    expectError("throws_in_create",
                sceneWith(FAULTY_PLUGIN, json::array({{{"term", "throws_in_create"}}})), kPlugin,
                "term \"throws_in_create\" (plugins.0.terms.0, libtest_faulty_plugin.so) failed "
                "in create: the test term refuses to be created");
}

TEST(PluginErrors, TermThrowsDuringAStepKeepsTheLastGoodOutput) {
    // Outputs every 0.025 s; the term fails from t = 0.06 s on: outputs 0, 1, 2 stay.
    json scene = sceneWith(SPRING_PLUGIN, kSpring);
    scene["plugins"].push_back(
        {{"library", FAULTY_PLUGIN},
         {"terms", json::array({{{"term", "throws_in_step"}, {"after", 0.06}}})}});
    expectError("throws_in_step", scene, kPlugin,
                "term \"throws_in_step\" (plugins.1.terms.0, libtest_faulty_plugin.so) failed in "
                "finalize at t = 0.06");
    const std::string out = std::string(APP_TEST_WORK) + "/plugin_error_throws_in_step/out/";
    for (const char* f : {"particles_0000.csv", "particles_0001.csv", "particles_0002.csv"})
        EXPECT_TRUE(std::filesystem::exists(out + f)) << f;
    EXPECT_FALSE(std::filesystem::exists(out + "particles_0003.csv"));
    const json summary = json::parse(apptest::readFile(out + "summary.json"));
    EXPECT_EQ(summary["status"], "failed");
}

TEST(PluginErrors, TermOfTheOtherDimension) {
    expectError("other_dimension",
                sceneWith(FAULTY_PLUGIN, json::array({{{"term", "only_2d"}}}), 3), kScene,
                "the plugin provides \"only_2d\" for 2D only; fluid_sim_3d runs 3D scenes",
                FLUID_SIM_3D);
}

TEST(PluginErrors, FieldTheLibraryDoesNotDeclare) {
    json scene = sceneWith(SPRING_PLUGIN, kSpring);
    scene["plugins"][0]["fields"] = {"energy"};
    expectError("unknown_field", scene, kScene,
                "plugins.0.fields.0: expected a field of libspring_plugin.so (it declares none)");
}

/// A checkpoint records the plugins and their parameters: a restart with others is refused.
TEST(PluginRestart, OtherPluginsOrParametersAreRefused) {
    const std::string dir = apptest::freshDir("plugin_restart");
    json scene = sceneWith(SPRING_PLUGIN, kSpring);
    auto r = plugintest::runScene(FLUID_SIM, scene, dir, "--checkpoint-every 0.05");
    ASSERT_EQ(r.code, 0) << r.output;
    const std::string restart = " --restart out/checkpoint_0001.chk --end-time 0.15";

    r = plugintest::runScene(FLUID_SIM, scene, dir, restart);
    EXPECT_EQ(r.code, 0) << r.output;  // the same plugins: continues
    r = apptest::run(FLUID_SIM, "--out out2 -q --threads 1" + restart, dir);
    EXPECT_EQ(r.code, 0) << r.output;  // the scene stored in the checkpoint finds its library

    json stiffer = scene;
    stiffer["plugins"][0]["terms"][0]["stiffness"] = 70;
    r = plugintest::runScene(FLUID_SIM, stiffer, dir, restart);
    EXPECT_EQ(r.code, kCheckpoint) << r.output;
    EXPECT_TRUE(contains(r.output, "plugins[0].terms[0].stiffness is 70 here, 63.2")) << r.output;

    json more = scene;
    more["plugins"].push_back({{"library", HEAT_SOURCE_PLUGIN},
                               {"terms",
                                {{{"term", "heat_source"},
                                  {"power_density", 1},
                                  {"min", {0, 0}},
                                  {"max", {0.1, 0.1}}}}}});
    r = plugintest::runScene(FLUID_SIM, more, dir, restart);
    EXPECT_EQ(r.code, kCheckpoint) << r.output;
    EXPECT_TRUE(contains(r.output, "plugin 1 library")) << r.output;
}

}  // namespace
