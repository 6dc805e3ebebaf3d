// A plugin's writer run from a scene: the scene loads a plugin that registers the writer
// "particle_count" (count_writer_plugin.cpp) and names it in output.formats; the app calls its
// start, write at every output time, finish, and resume after a restart. An unknown format lists
// the writers there are, the plugin's among them.
#include <filesystem>

#include "plugin_test_support.hpp"

namespace {

using apptest::contains;
using apptest::readFile;
using plugintest::json;

constexpr int kScene = 5;

/// The spring drop of `dim` D for 0.1 s (outputs 0 to 4) with the writer plugin only (no
/// terms) and `formats`.
json countScene(int dim, const json& formats) {
    json s = plugintest::exampleScene("spring_" + std::to_string(dim) + "d.json");
    s["time"]["end"] = 0.1;
    s["plugins"] = json::array({{{"library", COUNT_WRITER_PLUGIN}}});
    s["output"]["formats"] = formats;
    return s;
}

void expectCountsWritten(const std::string& dir, int dim) {
    for (int k = 0; k <= 4; ++k) {
        const std::string text = readFile(dir + "/out/particles_000" + std::to_string(k) + ".txt");
        EXPECT_TRUE(contains(text, "dimension " + std::to_string(dim) + "\n")) << text;
        EXPECT_TRUE(contains(text, "fields velocity density pressure")) << text;
        EXPECT_TRUE(
            std::filesystem::exists(dir + "/out/particles_000" + std::to_string(k) + ".csv"));
    }
    EXPECT_TRUE(contains(readFile(dir + "/out/particles_0004.txt"), "time 0.1\n"));
    EXPECT_EQ(readFile(dir + "/out/particle_count.log"),
              "start\nwrite 0\nwrite 1\nwrite 2\nwrite 3\nwrite 4\nfinish completed\n");
}

TEST(PluginWriters, RunFromTheSceneIn2D) {
    const std::string dir = apptest::freshDir("plugin_writer_2d");
    const auto r = plugintest::runScene(FLUID_SIM, countScene(2, {"csv", "particle_count"}), dir);
    ASSERT_EQ(r.code, 0) << r.output;
    expectCountsWritten(dir, 2);
}

TEST(PluginWriters, RunFromTheSceneIn3D) {
    const std::string dir = apptest::freshDir("plugin_writer_3d");
    json s = countScene(3, {"particle_count", "csv"});
    s["particles"]["spacing"] = 0.04;
    const auto r = plugintest::runScene(FLUID_SIM_3D, s, dir);
    ASSERT_EQ(r.code, 0) << r.output;
    expectCountsWritten(dir, 3);
}

TEST(PluginWriters, TheRunReportListsItsFiles) {
    const std::string dir = apptest::freshDir("plugin_writer_report");
    apptest::writeFile(dir + "/scene.json", countScene(2, {"particle_count"}).dump(2));
    const auto r = apptest::run(FLUID_SIM, "scene.json --out out --threads 1", dir);
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_TRUE(contains(r.output, "particles_*.txt          particle counts")) << r.output;
}

TEST(PluginWriters, ResumedAfterARestart) {
    const std::string dir = apptest::freshDir("plugin_writer_restart");
    const auto first = plugintest::runScene(FLUID_SIM, countScene(2, {"particle_count"}), dir,
                                            "--checkpoint-every 0.05");
    ASSERT_EQ(first.code, 0) << first.output;
    const auto again =
        apptest::run(FLUID_SIM, "--restart out/checkpoint_0001.chk --out out --threads 1 -q", dir);
    ASSERT_EQ(again.code, 0) << again.output;
    const std::string log = readFile(dir + "/out/particle_count.log");
    EXPECT_TRUE(
        contains(log, "finish completed\nresume 0.05\nwrite 3\nwrite 4\nfinish completed\n"))
        << log;
}

TEST(PluginWriters, AnExceptionStopsTheRunNamingTheWriter) {
    const std::string dir = apptest::freshDir("plugin_writer_throws");
    const auto r =
        plugintest::runScene(FLUID_SIM, countScene(2, {"csv", "fails_at_second_output"}), dir);
    EXPECT_EQ(r.code, 10) << r.output;
    EXPECT_TRUE(contains(r.output,
                         "writer \"fails_at_second_output\" "
                         "(libtest_count_writer_plugin.so) failed in write at t = 0.05 "
                         "s: no room for output 2"))
        << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir + "/out/particles_0001.csv"));
}

/// Runs the scene and expects exit code 5 with one error line that holds `message`.
void expectSceneError(const std::string& name, const json& scene, const std::string& message,
                      const char* app = FLUID_SIM) {
    const std::string dir = apptest::freshDir("plugin_writer_" + name);
    const auto r = plugintest::runScene(app, scene, dir);
    EXPECT_EQ(r.code, kScene) << r.output;
    const auto lines = plugintest::errorLines(r.output);
    ASSERT_EQ(lines.size(), 1u) << r.output;
    EXPECT_TRUE(contains(lines[0], message)) << lines[0];
}

TEST(PluginWriters, AnUnknownFormatListsThePluginsWriters) {
    expectSceneError("unknown", countScene(2, {"csv", "particle_cnt"}),
                     "scene.json: output.formats.1: expected one of \"vtu\", \"csv\", "
                     "\"particle_count\", \"fails_at_second_output\", found the string "
                     "\"particle_cnt\" (did you mean "
                     "\"particle_count\"?)");
    expectSceneError("unknown_3d", countScene(3, {"xyz"}),
                     "scene.json: output.formats.0: expected one of \"vtu\", \"csv\", "
                     "\"particle_count\", \"fails_at_second_output\", found the string \"xyz\"",
                     FLUID_SIM_3D);
}

TEST(PluginWriters, WithoutThePluginItsWriterIsUnknown) {
    json s = countScene(2, {"vtu", "particle_count"});
    s.erase("plugins");
    expectSceneError("without_plugin", s,
                     "scene.json: output.formats.1: expected one of \"vtu\", \"csv\", found the "
                     "string \"particle_count\"");
}

}  // namespace
