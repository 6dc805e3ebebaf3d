// Checkpoints: a run restarted from a checkpoint ends bitwise identical to the uninterrupted run
// (same threads and backend); Ctrl-C stops cleanly with a final output and a checkpoint.
#include <gtest/gtest.h>

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

TEST(Interrupt, CtrlCWritesFinalOutputAndCheckpoint) {
    const std::string dir = freshDir("interrupt");
    // Runs for minutes unless interrupted: SIGINT once the second output exists (the time loop
    // runs); `timeout` ends the test if the app ignored it. --foreground: without it, timeout
    // passes the SIGINT on to the app and to its whole process group, so the app would get
    // two, and a second Ctrl-C ends it at once, before the checkpoint (a race seen under load).
    writeFile(
        dir + "/interrupt.sh",
        "timeout --foreground 120 '" + std::string(FLUID_SIM) + "' '" + scene("tiny_2d.json") +
            "' --quiet --out out --end-time 1000 & pid=$!\n"
            "for i in $(seq 600); do [ -e out/particles_0001.vtu ] && break; sleep 0.1; done\n"
            "kill -INT $pid\nwait $pid\necho exit=$?\n");
    const Result r = run("/bin/sh", "interrupt.sh", dir);
    EXPECT_TRUE(contains(r.output, "exit=130")) << r.output;
    ASSERT_TRUE(std::filesystem::exists(dir + "/out/checkpoint_interrupted.chk")) << r.output;
    const auto s = nlohmann::json::parse(readFile(dir + "/out/summary.json"));
    EXPECT_EQ(s["status"], "interrupted");
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
