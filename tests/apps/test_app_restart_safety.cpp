// Restarts that are always safe: a checkpoint refuses a scene or set-up that differs from the one
// it was written for (exit code 8, naming what differs), accepts what may change (end time,
// outputs, threads, backend), and a restarted run is bitwise the uninterrupted one for any stop
// time, aligned with output.every or not.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "app_runner.hpp"

using namespace apptest;

namespace {

constexpr int kCheckpoint = 8;

/// Restarts, with `extra` options, from a checkpoint of tiny_2d at t = 0.01 made in a directory
/// of the test's own (ctest runs tests in parallel: no two share a directory).
Result restart(const std::string& extra) {
    const std::string dir =
        freshDir(std::string("restart_safety_") +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
    const Result r = run(
        FLUID_SIM,
        "'" + scene("tiny_2d.json") + "' --quiet --out out --end-time 0.01 --checkpoint-every 0.01",
        dir);
    EXPECT_EQ(r.code, 0) << r.output;
    return run(FLUID_SIM,
               "--quiet --out again --restart out/checkpoint_0001.chk --end-time 0.015 " + extra,
               dir);
}

void expectRefused(const Result& r, std::initializer_list<const char*> parts) {
    EXPECT_EQ(r.code, kCheckpoint) << r.output;
    for (const char* p : parts) EXPECT_TRUE(contains(r.output, p)) << p << " in:\n" << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

}  // namespace

TEST(RestartSafety, AnotherSpacingIsRefused) {
    expectRefused(
        restart("--set particles.spacing=0.025"),
        {"checkpoint_0001.chk", "particles.spacing is 0.025 here, 0.02 in the checkpoint"});
}

TEST(RestartSafety, HeatSwitchedOnOrOffIsRefused) {
    expectRefused(restart("--set physics.heat=false"), {"physics.heat is false here, absent"});
}

TEST(RestartSafety, AnotherGeometryIsRefused) {
    expectRefused(restart("--set 'fluids.0.max=[0.1, 0.1]'"), {"fluids[0].max[1] is 0.1 here"});
}

TEST(RestartSafety, MoreEmittersThanTheCheckpointIsRefused) {
    const std::string emitter =
        "{\"position\": [0.05, 0.15], \"direction\": [0, -1], \"speed\": 0.5, \"radius\": 0.02, "
        "\"material\": \"water\"}";
    expectRefused(restart("--set 'emitters=[" + emitter + "]'"),
                  {"emitters[0].", "absent in the checkpoint"});
}

TEST(RestartSafety, EndTimeOutputsThreadsAndBackendMayChange) {
    const Result r = restart(
        "--set output.every=0.0025 --set output.images=false --threads 1 "
        "--backend seq --set name=renamed");
    EXPECT_EQ(r.code, 0) << r.output;
}
