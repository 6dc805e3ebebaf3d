// Bad plugins and bad plugin scenes: each a one-line error with its exit code
// (docs/scenes.md), never a crash; and restarts with other plugins refused.
#include <filesystem>
#include <functional>

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
                "was built against plugin API version 1001, fluid_sim has version 3");
}

TEST(PluginErrors, UnknownTerm) {
    expectError("unknown_term",
                sceneWith(SPRING_PLUGIN, json::array({{{"term", "sprung"}, {"stiffness", 1}}})),
                kScene,
                "plugins.0.terms.0.term: expected a term of libspring_plugin.so (spring), found "
                "the string \"sprung\" (did you mean \"spring\"?)");
}

TEST(PluginErrors, CudaBackendRefusesAPluginTermByName) {
    json s = sceneWith(SPRING_PLUGIN, kSpring);
    s["numerics"] = {{"backend", "cuda"}};
    expectError("cuda", s, kScene,
                "numerics.backend \"cuda\" does not support this scene yet: term \"spring\" "
                "(plugins.0.terms.0, libspring_plugin.so) runs on the CPU back end only");
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

// A plugin's field that leaves the range the plugin declares stops the run as unstable (exit 9),
// whether the scene writes the field or not (issue 47).
TEST(PluginErrors, FieldLeavingItsDeclaredRange) {
    json scene = sceneWith(SPRING_PLUGIN, kSpring);
    scene["plugins"].push_back(
        {{"library", FAULTY_PLUGIN},
         {"terms", json::array({{{"term", "leaves_its_range"}, {"rate", 20}}})}});
    const std::string dir = apptest::freshDir("plugin_error_leaves_its_range");
    const auto r = plugintest::runScene(FLUID_SIM, scene, dir);
    EXPECT_EQ(r.code, 9) << r.output;
    const auto lines = plugintest::errorLines(r.output);
    ASSERT_EQ(lines.size(), 1u) << r.output;
    EXPECT_TRUE(contains(lines[0], "s a particle's level reached 1.")) << lines[0];
    EXPECT_TRUE(contains(lines[0],
                         ", above 1: the range the plugin libtest_faulty_plugin.so "
                         "declares for it"))
        << lines[0];
    const json summary = json::parse(apptest::readFile(dir + "/out/summary.json"));
    EXPECT_EQ(summary["status"], "unstable");
}

// Code that throws plain values (an int) is reported as a plugin failure, not an abort.
TEST(PluginErrors, EntryPointOrFactoryThrowingSomethingElse) {
    expectError("entry_throws_int", sceneWith(THROWING_ENTRY_PLUGIN, kSpring), kPlugin,
                "the plugin failed to register: its entry point threw something that is not a "
                "std::exception");
    expectError("factory_throws_int",
                sceneWith(FAULTY_PLUGIN, json::array({{{"term", "throws_int_when_made"}}})),
                kPlugin,
                "term \"throws_int_when_made\" (plugins.0.terms.0, libtest_faulty_plugin.so) "
                "failed when made from its parameters: it threw something that is not a "
                "std::exception");
}

/// A copy of a plugin library in the test's folder, changed by `edit`.
std::string editedCopy(const std::string& name, const std::string& library,
                       const std::function<void(std::string&)>& edit) {
    const std::string dir = apptest::freshDir("plugin_copy_" + name);
    std::string bytes = apptest::readFile(library);
    edit(bytes);
    const std::string copy = dir + "/lib" + name + ".so";
    apptest::writeFile(copy, bytes);
    return copy;
}

// An interrupted copy ended the app with SIGBUS inside dlopen (its segments reach past the end).
TEST(PluginErrors, TruncatedLibrary) {
    for (const double part : {0.5, 0.9}) {
        const std::string copy = editedCopy("truncated", SPRING_PLUGIN,
                                            [&](std::string& b) { b.resize(b.size() * part); });
        expectError("truncated", sceneWith(copy, kSpring), kPlugin,
                    "cannot load " + copy + ": the file is truncated (");
    }
    const std::string header =
        editedCopy("header_only", SPRING_PLUGIN, [](std::string& b) { b.resize(40); });
    expectError("header_only", sceneWith(header, kSpring), kPlugin,
                "it is not a shared library (no ELF header");
}

// A library for another machine was reported by dlopen as a file it cannot open.
TEST(PluginErrors, LibraryForAnotherMachine) {
#if defined(__aarch64__)
    const char machine = 62, *other = "x86-64";  // EM_X86_64
#else
    const char machine = char(183), *other = "AArch64 (64-bit ARM)";  // EM_AARCH64
#endif
    const std::string copy = editedCopy("other_machine", SPRING_PLUGIN, [&](std::string& b) {
        b[18] = machine, b[19] = 0;  // e_machine, little-endian
    });
    expectError("other_machine", sceneWith(copy, kSpring), kPlugin,
                std::string("it was built for ") + other + ", this program runs on ");
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
