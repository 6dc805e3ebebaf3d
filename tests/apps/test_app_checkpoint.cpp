// Checkpoints: a run restarted from a checkpoint ends bitwise identical to the uninterrupted run
// (same threads and backend); Ctrl-C stops cleanly with a final output and a checkpoint.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "app_runner.hpp"
#include "vtu_reader.hpp"

using namespace apptest;

class Restart : public ::testing::TestWithParam<int> {};

TEST_P(Restart, IsBitwiseIdenticalToTheUninterruptedRun) {
    const int dim = GetParam();
    const std::string app = dim == 2 ? FLUID_SIM : FLUID_SIM_3D;
    const std::string sc = scene(dim == 2 ? "tiny_2d.json" : "tiny_3d.json");
    const std::string dir = freshDir("restart_" + std::to_string(dim));
    const std::string common = "--quiet --backend omp --threads 2 --end-time 0.03 ";
    const Result full =
        run(app, "'" + sc + "' " + common + "--out full --checkpoint-every 0.01", dir);
    ASSERT_EQ(full.code, 0) << full.output;
    ASSERT_TRUE(std::filesystem::exists(dir + "/full/checkpoint_0001.chk"));
    const Result resumed =
        run(app, common + "--out resumed --restart full/checkpoint_0001.chk", dir);
    ASSERT_EQ(resumed.code, 0) << resumed.output;
    // The final output of both runs: the same bytes (positions, velocities, every field).
    const std::string a = readFile(dir + "/full/particles_0003.vtu");
    const std::string b = readFile(dir + "/resumed/particles_0003.vtu");
    ASSERT_FALSE(a.empty());
    EXPECT_TRUE(a == b) << "restarted run differs from the uninterrupted run";
    EXPECT_NEAR(readVtu(b).time, 0.03, 1e-12);
    // The resumed series continues the earlier outputs.
    EXPECT_TRUE(contains(readFile(dir + "/resumed/particles.pvd"), "particles_0003.vtu"));
}

INSTANTIATE_TEST_SUITE_P(Apps, Restart, ::testing::Values(2, 3));

class RestartAt : public ::testing::TestWithParam<std::string> {};

TEST_P(RestartAt, AnyStopTimeIsBitwiseTheUninterruptedRun) {
    // Outputs every 0.01 s. 0.023 is between output times (the run's last step is cut short);
    // 0.03 is an output time up to round-off (3 * 0.01 = 0.030000000000000002).
    const std::string stop = GetParam();
    const std::string dir = freshDir("restart_at_" + stop);
    const std::string common = "--quiet --backend seq '" + scene("tiny_2d.json") + "' ";
    const Result full = run(FLUID_SIM, common + "--end-time 0.05 --out full", dir);
    ASSERT_EQ(full.code, 0) << full.output;
    const Result first =
        run(FLUID_SIM,
            common + "--end-time " + stop + " --checkpoint-every " + stop + " --out part", dir);
    ASSERT_EQ(first.code, 0) << first.output;
    const Result resumed = run(FLUID_SIM,
                               "--quiet --backend seq --end-time 0.05 --out part --restart "
                               "part/checkpoint_0001.chk",
                               dir);
    ASSERT_EQ(resumed.code, 0) << resumed.output;
    const std::string a = readFile(dir + "/full/particles_0005.vtu");
    ASSERT_FALSE(a.empty());
    EXPECT_TRUE(a == readFile(dir + "/part/particles_0005.vtu"))
        << "the run restarted at " << stop << " differs from the uninterrupted run";
    EXPECT_EQ(readFile(dir + "/full/probes.csv"), readFile(dir + "/part/probes.csv"));
}

INSTANTIATE_TEST_SUITE_P(Apps, RestartAt, ::testing::Values("0.023", "0.03"), [](const auto& info) {
    std::string n = info.param;
    n[1] = '_';
    return "t" + n;
});

TEST(RestartWithOtherOutputs, OutputsGoOnFromTheCheckpointWithoutOverwriting) {
    // Outputs every 0.01 s to a checkpoint at t = 0.025, then resumed with outputs every
    // 0.002 s (finer) and every 0.02 s (coarser). The resumed outputs fall on the new interval's
    // multiples after 0.025, in files numbered on from the last one written: before, the finer
    // interval asked for its next output at 3 x 0.002 = 0.006 s, behind the checkpoint, and the
    // run stepped backwards in time until it went unstable.
    const std::string dir = freshDir("restart_other_outputs");
    const std::string common = "--quiet --backend seq '" + scene("tiny_2d.json") + "' ";
    const Result first =
        run(FLUID_SIM, common + "--end-time 0.025 --checkpoint-every 0.025 --out part", dir);
    ASSERT_EQ(first.code, 0) << first.output;
    for (const std::string every : {"0.002", "0.02"}) {
        SCOPED_TRACE("output.every " + every);
        std::filesystem::remove_all(dir + "/resumed");
        std::filesystem::create_directories(dir + "/resumed");
        for (const auto& e : std::filesystem::directory_iterator(dir + "/part"))
            std::filesystem::copy(e.path(), dir + "/resumed/" + e.path().filename().string());
        const std::string earlier = readFile(dir + "/resumed/particles_0002.vtu");
        const Result resumed = run(FLUID_SIM,
                                   "--quiet --backend seq --end-time 0.04 --out resumed "
                                   "--set output.every=" +
                                       every + " --restart resumed/checkpoint_0001.chk",
                                   dir);
        ASSERT_EQ(resumed.code, 0) << resumed.output;
        EXPECT_EQ(readFile(dir + "/resumed/particles_0002.vtu"), earlier);  // t = 0.02 kept
        // Files 0000-0002 at 0, 0.01, 0.02; 0003 is the first run's end (0.025), which the
        // resumed run writes again as its first output after the checkpoint.
        const double firstAfter = every == "0.002" ? 0.026 : 0.04;
        EXPECT_NEAR(readVtu(readFile(dir + "/resumed/particles_0003.vtu")).time, firstAfter, 1e-12);
        const auto s = nlohmann::json::parse(readFile(dir + "/resumed/summary.json"));
        EXPECT_EQ(s["status"], "completed");
        EXPECT_NEAR(s["final_time"].get<double>(), 0.04, 1e-12);
    }
}

class Interrupt : public ::testing::TestWithParam<int> {};

TEST_P(Interrupt, SignalWritesFinalOutputSummaryAndCheckpoint) {
    // The app raises the signal itself after step 3 (NUMERICS_TEST_SIGNAL): the same handler as
    // a signal from outside, at a known point whatever the machine's load.
    const int sig = GetParam();
    const std::string dir = freshDir("interrupt_" + std::to_string(sig));
    const Result r =
        run("/usr/bin/env",
            "NUMERICS_TEST_SIGNAL=" + std::to_string(sig) + ":3 '" + std::string(FLUID_SIM) +
                "' '" + scene("tiny_2d.json") + "' --quiet --out out --end-time 1000",
            dir);
    EXPECT_EQ(r.code, 130) << r.output;
    ASSERT_TRUE(std::filesystem::exists(dir + "/out/checkpoint_interrupted.chk")) << r.output;
    const auto s = nlohmann::json::parse(readFile(dir + "/out/summary.json"));
    EXPECT_EQ(s["status"], "interrupted");
    EXPECT_EQ(s["steps"], 3);
    const double t = s["final_time"];
    EXPECT_GT(t, 0.0);
    // The last output is at the time the run stopped, and the checkpoint continues from there.
    const std::string pvd = readFile(dir + "/out/particles.pvd");
    const auto last = pvd.rfind("file=\"");
    const std::string file = pvd.substr(last + 6, pvd.find('"', last + 6) - last - 6);
    EXPECT_NEAR(readVtu(readFile(dir + "/out/" + file)).time, t, 1e-12);
    const Result resumed =
        run(FLUID_SIM,
            "--quiet --out out --restart out/checkpoint_interrupted.chk --end-time " +
                std::to_string(t + 0.005),
            dir);
    EXPECT_EQ(resumed.code, 0) << resumed.output;
}

// Ctrl-C, kill (SIGTERM) and a closed terminal (SIGHUP).
INSTANTIATE_TEST_SUITE_P(Apps, Interrupt, ::testing::Values(SIGINT, SIGTERM, SIGHUP));

TEST(ClosedStdout, CostsNoResult) {
    // `fluid_sim scene | true`: stdout is closed from the start; the run completes anyway.
    const std::string dir = freshDir("closed_stdout");
    const Result r = run("/bin/sh",
                         "-c \"{ '" + std::string(FLUID_SIM) + "' '" + scene("tiny_2d.json") +
                             "' --out out; echo \\$? > code; } | true\"",
                         dir);
    EXPECT_EQ(readFile(dir + "/code"), "0\n") << r.output;
    const auto s = nlohmann::json::parse(readFile(dir + "/out/summary.json"));
    EXPECT_EQ(s["status"], "completed");
}

TEST(Unstable, StopsWithTimeStepAndCause) {
    // A sound speed far below the flow speed: the fluid is crushed into the walls.
    nlohmann::json j = nlohmann::json::parse(readFile(scene("tiny_2d.json")));
    j["materials"]["water"]["sound_speed"] = 0.01;
    j["time"]["end"] = 5.0;
    j["output"]["every"] = 0.5;
    const std::string dir = freshDir("unstable");
    writeFile(dir + "/scene.json", j.dump());
    const Result r = run(FLUID_SIM, "scene.json --quiet --out out", dir);
    EXPECT_EQ(r.code, 9) << r.output;  // docs/scenes.md: 9 = unstable
    for (const char* part : {"unstable at t =", "step", "Likely cause", "last good output kept"})
        EXPECT_TRUE(contains(r.output, part)) << part << "\n" << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir + "/out/particles_0000.vtu"));
    EXPECT_EQ(nlohmann::json::parse(readFile(dir + "/out/summary.json"))["status"], "unstable");
}

namespace {

/// The frames of a movie (ffprobe counts them), or -1 without ffprobe.
int movieFrames(const std::string& path) {
    const Result r = run("/bin/sh",
                         "-c 'command -v ffprobe >/dev/null || { echo none; exit 0; }; ffprobe -v "
                         "error -count_frames -select_streams v:0 -show_entries "
                         "stream=nb_read_frames -of csv=p=0 \"" +
                             path + "\"'",
                         ".");
    return contains(r.output, "none") ? -1 : std::atoi(r.output.c_str());
}

bool anyFileStartingWith(const std::string& dir, const std::string& head) {
    for (const auto& e : std::filesystem::directory_iterator(dir))
        if (e.path().filename().string().rfind(head, 0) == 0) return true;
    return false;
}

}  // namespace

// A shorter run into a folder an earlier run used encoded the earlier run's pictures into its
// movie and left its series and checkpoints beside the new ones (issue 47): a new run removes
// the files an earlier run wrote under the names it writes, and says so.
TEST(OutputFolder, ANewRunReplacesAnEarlierRunsFiles) {
    const std::string dir = freshDir("output_folder_reused");
    const std::string common = "'" + scene("tiny_2d.json") + "' --quiet --backend seq --out out ";
    const Result first = run(FLUID_SIM, common + "--end-time 0.05 --checkpoint-every 0.02", dir);
    ASSERT_EQ(first.code, 0) << first.output;
    ASSERT_TRUE(std::filesystem::exists(dir + "/out/particles_0005.png"));
    ASSERT_TRUE(std::filesystem::exists(dir + "/out/checkpoint_0002.chk"));
    std::filesystem::copy_file(dir + "/out/checkpoint_0001.chk", dir + "/kept.chk");
    writeFile(dir + "/out/notes.txt", "a file of the user's");

    const Result second = run(FLUID_SIM, common + "--end-time 0.02", dir);
    ASSERT_EQ(second.code, 0) << second.output;
    for (const char* gone : {"particles_0003.vtu", "particles_0003.csv", "particles_0005.png",
                             "checkpoint_0001.chk", "checkpoint_0002.chk"})
        EXPECT_FALSE(std::filesystem::exists(dir + "/out/" + gone)) << gone;
    for (const char* kept : {"particles_0002.vtu", "particles_0002.png", "notes.txt"})
        EXPECT_TRUE(std::filesystem::exists(dir + "/out/" + kept)) << kept;
    EXPECT_FALSE(anyFileStartingWith(dir + "/out", "checkpoint_"));
    EXPECT_FALSE(contains(readFile(dir + "/out/particles.pvd"), "particles_0003.vtu"));
    const auto summary = nlohmann::json::parse(readFile(dir + "/out/summary.json"));
    bool said = false;
    for (const auto& w : summary.at("warnings"))
        said |= contains(w.get<std::string>(), "removed ") &&
                contains(w.get<std::string>(), "files an earlier run wrote");
    EXPECT_TRUE(said) << summary.at("warnings").dump();
    if (const int frames = movieFrames(dir + "/out/particles.mp4"); frames >= 0)
        EXPECT_EQ(frames, 3);
    else
        EXPECT_FALSE(std::filesystem::exists(dir + "/out/particles.mp4"));

    // A restart into the folder continues it; its movie holds this run's pictures only, though
    // the earlier run's later pictures stay in the folder.
    const Result longer = run(FLUID_SIM, common + "--end-time 0.05 --checkpoint-every 0.02", dir);
    ASSERT_EQ(longer.code, 0) << longer.output;
    const Result restart = run(FLUID_SIM,
                               "--quiet --backend seq --out out --end-time 0.03 --restart "
                               "out/checkpoint_0001.chk",
                               dir);
    ASSERT_EQ(restart.code, 0) << restart.output;
    EXPECT_TRUE(std::filesystem::exists(dir + "/out/particles_0003.vtu"));
    EXPECT_FALSE(contains(readFile(dir + "/out/particles.pvd"), "particles_0004.vtu"));
    if (const int frames = movieFrames(dir + "/out/particles.mp4"); frames >= 0) {
        EXPECT_EQ(frames, 4);
    }
    // The checkpoint copied away from the first run still restarts.
    const Result kept =
        run(FLUID_SIM, "--quiet --backend seq --out other --end-time 0.03 --restart kept.chk", dir);
    EXPECT_EQ(kept.code, 0) << kept.output;
}

namespace {

/// The unit cube [0, 1]^3 as an ASCII STL, its faces turned outwards.
std::string cubeStl() {
    const int faces[12][3][3] = {
        {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {{0, 0, 0}, {1, 1, 0}, {1, 0, 0}},
        {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}}, {{0, 0, 1}, {1, 1, 1}, {0, 1, 1}},
        {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}}, {{0, 0, 0}, {1, 0, 1}, {0, 0, 1}},
        {{0, 1, 0}, {0, 1, 1}, {1, 1, 1}}, {{0, 1, 0}, {1, 1, 1}, {1, 1, 0}},
        {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}}, {{0, 0, 0}, {0, 1, 1}, {0, 1, 0}},
        {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}}, {{1, 0, 0}, {1, 1, 1}, {1, 0, 1}}};
    std::string stl = "solid cube\n";
    for (const auto& f : faces) {
        stl += "facet normal 0 0 0\n outer loop\n";
        for (const auto& v : f)
            stl += " vertex " + std::to_string(v[0]) + " " + std::to_string(v[1]) + " " +
                   std::to_string(v[2]) + "\n";
        stl += " endloop\nendfacet\n";
    }
    return stl + "endsolid cube\n";
}

}  // namespace

// A mesh scene restarted from its checkpoint alone looked for its mesh beside the checkpoint,
// not beside the scene (issue 57): the checkpoint stores the mesh's path absolute, and a restart
// with the scene file, whose path is relative, is still the same run.
TEST(RestartOfAMeshScene, FindsTheMeshFromTheCheckpointAlone) {
    const std::string dir = freshDir("restart_mesh_scene");
    std::filesystem::create_directories(dir + "/scene");
    nlohmann::json j = nlohmann::json::parse(readFile(scene("tiny_3d.json")));
    j.erase("emitters");
    j["bodies"] = nlohmann::json::array({{{"shape", "mesh"},
                                          {"file", "cube.stl"},
                                          {"scale", 0.06},
                                          {"translate", {0.09, 0.03, 0.03}},
                                          {"temperature", 60}}});
    j["output"]["images"] = false;
    writeFile(dir + "/scene/scene.json", j.dump());
    writeFile(dir + "/scene/cube.stl", cubeStl());
    const Result first = run(FLUID_SIM_3D,
                             "scene/scene.json --quiet --backend seq --out first --end-time 0.01 "
                             "--checkpoint-every 0.005",
                             dir);
    ASSERT_EQ(first.code, 0) << first.output;
    const Result alone = run(
        FLUID_SIM_3D, "--quiet --backend seq --restart first/checkpoint_0001.chk --out alone", dir);
    EXPECT_EQ(alone.code, 0) << alone.output;
    const Result withScene =
        run(FLUID_SIM_3D, "scene/scene.json --quiet --restart first/checkpoint_0001.chk --out with",
            dir);
    EXPECT_EQ(withScene.code, 0) << withScene.output;
    const std::string end = readFile(dir + "/first/particles_0001.vtu");  // t = 0.01
    ASSERT_FALSE(end.empty());
    EXPECT_TRUE(readFile(dir + "/alone/particles_0001.vtu") == end);
    // An edited mesh is still noticed.
    writeFile(dir + "/scene/cube.stl", cubeStl() + "\n");
    const Result edited =
        run(FLUID_SIM_3D, "--quiet --restart first/checkpoint_0001.chk --out edited", dir);
    EXPECT_EQ(edited.code, 8) << edited.output;
    EXPECT_TRUE(contains(edited.output, "bodies[0].file content (FNV-1a)")) << edited.output;
}
