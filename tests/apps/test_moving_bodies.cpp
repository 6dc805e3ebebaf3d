// Moving bodies through the apps (bodies[i].motion): bodies.csv, bitwise for any thread count,
// restarts mid-motion, the refusals of bad motions (exit 5 or 6) and of bodies that leave the
// domain (exit 9), and "fixed" equal to no motion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app_runner.hpp"

using namespace apptest;
using json = nlohmann::json;

namespace {

constexpr int kScene = 5, kExpression = 6, kUnstable = 9;

json sceneJson(int dim) {
    return json::parse(
        readFile(scene(dim == 2 ? "moving_bodies_2d.json" : "moving_bodies_3d.json")));
}

/// Runs the app of the scene's dimension on the scene text in a fresh folder.
Result runText(const std::string& name, const json& j, const std::string& extra = "") {
    const std::string dir = freshDir("bodies_" + name);
    writeFile(dir + "/scene.json", j.dump());
    const std::string app = j["dimension"] == 2 ? FLUID_SIM : FLUID_SIM_3D;
    return run(app, "scene.json --quiet --out out " + extra, dir);
}

std::string outFile(const std::string& name, const std::string& file) {
    return std::string(APP_TEST_WORK) + "/bodies_" + name + "/out/" + file;
}

std::vector<std::vector<std::string>> csvRows(const std::string& text) {
    std::vector<std::vector<std::string>> rows;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        std::vector<std::string> row;
        std::istringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');) row.push_back(cell);
        rows.push_back(row);
    }
    return rows;
}

}  // namespace

// A row per moving body per output time; a prescribed body travels V t exactly and turns by
// the integral of its angular velocity; the fixed body is not listed.
TEST(MovingBodies, BodiesCsvHasARowPerMovingBodyPerOutput) {
    const Result r = runText("csv", sceneJson(2));
    ASSERT_EQ(r.code, 0) << r.output;
    const auto rows = csvRows(readFile(outFile("csv", "bodies.csv")));
    ASSERT_EQ(rows.size(), 1u + 2 * 5);  // header, t = 0, 0.01, ..., 0.04, two bodies
    EXPECT_EQ(rows[0].front(), "time");
    EXPECT_EQ(rows[0].back(), "heat");
    EXPECT_EQ(rows[0].size(), 12u);
    const auto& last = rows.back();
    EXPECT_EQ(last[1], "paddle");
    EXPECT_NEAR(std::stod(last[2]), 0.08 + 0.25 * 0.04, 1e-12);  // x = x0 + V t
    EXPECT_NEAR(std::stod(last[6]), 0.25 * 0.04 * 0.04, 1e-12);  // angle = 0.5 t^2 / 2
    EXPECT_EQ(rows[rows.size() - 2][1], "float");
    EXPECT_NEAR(std::stod(rows[1][11]), 0.12 * 0.08 * 1000 * 500 * 60,
                1e-3);  // sum m c T at t = 0 [J/m]
}

// The same bits with 1 and 2 threads, and from a restart mid-motion (2D and 3D).
class MovingRestart : public ::testing::TestWithParam<int> {};

TEST_P(MovingRestart, IsBitwiseForThreadsAndRestarts) {
    const int dim = GetParam();
    const std::string dir = freshDir("bodies_restart_" + std::to_string(dim));
    writeFile(dir + "/scene.json", sceneJson(dim).dump());
    const std::string app = dim == 2 ? FLUID_SIM : FLUID_SIM_3D;
    const std::string common = "--quiet --backend omp ";
    ASSERT_EQ(run(app, "scene.json " + common + "--threads 2 --out full", dir).code, 0);
    ASSERT_EQ(run(app, "scene.json " + common + "--threads 1 --out one", dir).code, 0);
    const Result first = run(
        app,
        "scene.json " + common + "--threads 2 --out part --end-time 0.02 --checkpoint-every 0.02",
        dir);
    ASSERT_EQ(first.code, 0) << first.output;
    const std::string end = dim == 2 ? "0.04" : "0.03";
    const Result resumed = run(
        app,
        common + "--threads 2 --out part --end-time " + end + " --restart part/checkpoint_0001.chk",
        dir);
    ASSERT_EQ(resumed.code, 0) << resumed.output;
    const std::string last = dim == 2 ? "particles_0004.vtu" : "particles_0003.vtu";
    const std::string a = readFile(dir + "/full/" + last);
    ASSERT_FALSE(a.empty());
    EXPECT_TRUE(a == readFile(dir + "/one/" + last)) << "1 thread differs from 2";
    EXPECT_TRUE(a == readFile(dir + "/part/" + last)) << "the restart differs";
    EXPECT_EQ(readFile(dir + "/full/bodies.csv"), readFile(dir + "/part/bodies.csv"));
    EXPECT_EQ(readFile(dir + "/full/bodies.csv"), readFile(dir + "/one/bodies.csv"));
}

INSTANTIATE_TEST_SUITE_P(Apps, MovingRestart, ::testing::Values(2, 3));

// "fixed" is the default: the same bytes as a body without motion.
TEST(MovingBodies, FixedIsTheBodyWithoutMotion) {
    json j = json::parse(readFile(scene("tiny_2d.json")));
    ASSERT_EQ(runText("plain", j).code, 0);
    j["bodies"][0]["motion"] = "fixed";
    ASSERT_EQ(runText("fixed_word", j).code, 0);
    j["bodies"][0]["motion"] = {{"type", "fixed"}};
    ASSERT_EQ(runText("fixed_object", j).code, 0);
    const std::string plain = readFile(outFile("plain", "particles_0002.vtu"));
    ASSERT_FALSE(plain.empty());
    EXPECT_TRUE(plain == readFile(outFile("fixed_word", "particles_0002.vtu")));
    EXPECT_TRUE(plain == readFile(outFile("fixed_object", "particles_0002.vtu")));
    EXPECT_FALSE(std::filesystem::exists(outFile("plain", "bodies.csv")));
}

TEST(MovingBodies, BadMotionsAreRefusedByKey) {
    json j = sceneJson(2);
    j["bodies"][0]["motion"] = {{"type", "free"}, {"density", 0}};
    expectOneLine(runText("zero_density", j), kScene, {"bodies[0].motion.density"});
    j["bodies"][0]["motion"] = {{"type", "free"}, {"density", 500}, {"mass", 3}};
    expectOneLine(runText("both", j), kScene, {"bodies[0].motion", "density", "mass"});
    j["bodies"][0]["motion"] = {{"type", "free"}, {"mass", -1}};
    expectOneLine(runText("negative_mass", j), kScene, {"bodies[0].motion.mass"});
    j["bodies"][0]["motion"] = {{"type", "free"}, {"density", 500}, {"locked", {"x", "spin"}}};
    expectOneLine(runText("locked", j), kScene, {"bodies[0].motion.locked[1]", "rotation"});
    j["bodies"][0]["motion"] = {{"type", "free"}, {"density", 500}, {"inertia", 0}};
    expectOneLine(runText("inertia", j), kScene, {"bodies[0].motion.inertia"});
    j["bodies"][0]["motion"] = {{"type", "sliding"}};
    expectOneLine(runText("type", j), kScene, {"bodies[0].motion.type", "prescribed"});
    j["bodies"][0]["motion"] = {{"type", "prescribed"}, {"velocity", {"x", 0}}};
    expectOneLine(runText("variable", j), kExpression, {"bodies[0].motion.velocity[0]", "x"});
    // The float moved into the paddle.
    j["bodies"][0]["motion"] = {{"type", "free"}, {"density", 500}};
    j["bodies"][0]["min"] = {0.04, 0.16};
    j["bodies"][0]["max"] = {0.16, 0.24};
    expectOneLine(runText("overlap", j), kScene, {"bodies[0]", "starts inside bodies[1]"});
}

TEST(MovingBodies, AThreeDimensionalInertiaMustBePositiveDefinite) {
    json j = sceneJson(3);
    j["bodies"][0]["motion"]["inertia"] = {{1, 0.5, 0}, {0, 1, 0}, {0, 0, 1}};
    expectOneLine(runText("inertia_3d", j), kScene, {"bodies[0].motion.inertia", "symmetric"});
    j["bodies"][0]["motion"]["inertia"] = {1, 2};
    expectOneLine(runText("inertia_3d_short", j), kScene, {"bodies[0].motion.inertia"});
}

// A prescribed body driven through the floor stops the run, naming it.
TEST(MovingBodies, ABodyThatLeavesTheDomainStopsTheRun) {
    json j = sceneJson(2);
    j["bodies"][1]["motion"] = {{"type", "prescribed"}, {"velocity", {0, -2}}};
    const Result r = runText("leaves", j);
    EXPECT_EQ(r.code, kUnstable) << r.output;
    EXPECT_TRUE(contains(r.output, "paddle left the domain")) << r.output;
    EXPECT_TRUE(contains(r.output, "y_min")) << r.output;
    EXPECT_TRUE(contains(r.output, "passed through the wall")) << r.output;
}

// The CUDA back end runs them (here its device step on the host execution, as on a machine
// without a GPU): bodies.csv is the CPU back end's to round-off (its 10 digits; the values near
// zero, a torque of round-off, within 1e-9).
TEST(MovingBodies, TheCudaBackEndRunsThemAsTheCpuBackEnd) {
    setenv("NUMERICS_TEST_DEVICE_EXECUTION", "host", 1);
    const Result cuda = runText("cuda", sceneJson(2), "--backend cuda");
    unsetenv("NUMERICS_TEST_DEVICE_EXECUTION");
    const Result cpu = runText("cuda_cpu", sceneJson(2), "--backend cpu");
    ASSERT_EQ(cuda.code, 0) << cuda.output;
    ASSERT_EQ(cpu.code, 0) << cpu.output;
    const auto a = csvRows(readFile(outFile("cuda", "bodies.csv")));
    const auto b = csvRows(readFile(outFile("cuda_cpu", "bodies.csv")));
    ASSERT_EQ(a.size(), b.size());
    ASSERT_EQ(a.size(), 1u + 2 * 5);
    for (std::size_t r = 1; r < a.size(); ++r) {
        ASSERT_EQ(a[r].size(), b[r].size());
        EXPECT_EQ(a[r][1], b[r][1]);
        for (std::size_t c = 2; c < a[r].size(); ++c)
            EXPECT_NEAR(std::stod(a[r][c]), std::stod(b[r][c]),
                        1e-7 * std::abs(std::stod(b[r][c])) + 1e-9)
                << "row " << r << ", " << b[0][c];
    }
}

// A heavy box dropped on the floor comes to rest on it, within half a spacing (the contact
// holds its particles one spacing from the wall's), and at rest.
TEST(MovingBodies, AHeavyBodyComesToRestOnTheFloor) {
    json j = sceneJson(2);
    j["bodies"] = json::array({{{"name", "stone"},
                                {"shape", "box"},
                                {"min", {0.26, 0.04}},
                                {"max", {0.34, 0.12}},
                                {"motion", {{"type", "free"}, {"density", 3000}}}}});
    j["time"]["end"] = 0.5;
    j["output"]["every"] = 0.1;
    ASSERT_EQ(runText("rest", j).code, 0);
    const auto rows = csvRows(readFile(outFile("rest", "bodies.csv")));
    const auto& last = rows.back();
    const double y = std::stod(last[3]), speed = std::hypot(std::stod(last[4]), std::stod(last[5]));
    EXPECT_NEAR(y, 0.04, 0.5 * 0.02) << "the centre half its height above the floor";
    EXPECT_LT(speed, 0.02);
}

// Two boxes in air (no gravity) joined by a stretched spring: the separation swings as
// L0 + A cos(omega t), omega = sqrt(k / mu), mu = m1 m2 / (m1 + m2) (rigid_body.hpp), within
// 5 % of A (the symplectic Euler's phase lag, omega dt / 2 ~ 0.01 rad, and the sampling);
// the pulls are equal and opposite, so the centre stays where it is (to 1e-12 m).
TEST(MovingBodies, ASpringBetweenTwoBodiesPullsBoth) {
    json j = sceneJson(2);
    j["gravity"] = {0, 0};
    j["physics"] = {{"max_speed", 1}};
    j["fluids"][0]["max"] = {0.6, 0.1};
    j["time"]["end"] = 0.25;
    j["output"]["every"] = 0.025;
    const json spring = {
        {"anchor", {0.14, 0.3}}, {"anchor_body", 0}, {"stiffness", 1000}, {"length", 0.2}};
    j["bodies"] =
        json::array({{{"shape", "box"},
                      {"min", {0.1, 0.26}},
                      {"max", {0.18, 0.34}},
                      {"motion", {{"type", "free"}, {"density", 500}}}},
                     {{"shape", "box"},
                      {"min", {0.38, 0.26}},
                      {"max", {0.46, 0.34}},
                      {"motion", {{"type", "free"}, {"density", 500}, {"springs", {spring}}}}}});
    ASSERT_EQ(runText("two_body_spring", j).code, 0);
    const auto rows = csvRows(readFile(outFile("two_body_spring", "bodies.csv")));
    ASSERT_EQ(rows.size(), 1u + 2 * 11);
    const double mu = 0.08 * 0.08 * 500 / 2, omega = std::sqrt(1000 / mu), A = 0.28 - 0.2;
    for (std::size_t r = 1; r + 1 < rows.size(); r += 2) {
        const double t = std::stod(rows[r][0]), xa = std::stod(rows[r][2]),
                     xb = std::stod(rows[r + 1][2]);
        EXPECT_NEAR(xb - xa, 0.2 + A * std::cos(omega * t), 0.05 * A) << "t = " << t;
        EXPECT_NEAR((xa + xb) / 2, 0.28, 1e-12) << "t = " << t;
    }
    j["bodies"][1]["motion"]["springs"][0]["anchor_body"] = 1;
    expectOneLine(runText("spring_to_itself", j), kScene,
                  {"bodies[1].motion.springs[0].anchor_body", "another"});
    j["bodies"][1]["motion"]["springs"][0]["anchor_body"] = 7;
    expectOneLine(runText("spring_to_nothing", j), kScene,
                  {"bodies[1].motion.springs[0].anchor_body", "2 bodies"});
}

// A rod (0.04 x 0.2 m) hinged at its top on a box carried at 0.2 m/s swings as a compound
// pendulum in the box's frame: theta = (omega0 / W) sin(W t), W^2 = M g d / I_P,
// I_P = M ((L^2 + w^2) / 12 + d^2), d = L / 2 (within 1 % of the amplitude: symplectic Euler's
// phase lag and the sampling), and the pin's two points stay together (1e-6 m). The two bodies
// touch at the pin: their contacts must not push them apart.
TEST(MovingBodies, AHingeOnAMovingBodyCarriesAPendulum) {
    json j = sceneJson(2);
    j["physics"] = {{"max_speed", 1}};
    j["fluids"][0]["max"] = {0.6, 0.06};
    j["time"]["end"] = 0.75;
    j["output"]["every"] = 0.05;
    const double omega0 = 0.5, L = 0.2, w = 0.04, d = L / 2;
    j["bodies"] =
        json::array({{{"shape", "box"},
                      {"min", {0.1, 0.32}},
                      {"max", {0.2, 0.36}},
                      {"motion", {{"type", "prescribed"}, {"velocity", {"0.2", "0"}}}}},
                     {{"shape", "box"},
                      {"min", {0.13, 0.12}},
                      {"max", {0.17, 0.32}},
                      {"motion",
                       {{"type", "free"},
                        {"density", 500},
                        {"hinge", {0.15, 0.32}},
                        {"hinge_body", 0},
                        {"velocity", {0.2 + omega0 * d, 0}},  // the pin moves with the box
                        {"angular_velocity", omega0}}}}});
    ASSERT_EQ(runText("hinge_on_body", j).code, 0);
    const auto rows = csvRows(readFile(outFile("hinge_on_body", "bodies.csv")));
    ASSERT_EQ(rows.size(), 1u + 2 * 16);
    const double W = std::sqrt(9.81 * d / ((L * L + w * w) / 12 + d * d));
    for (std::size_t r = 1; r + 1 < rows.size(); r += 2) {
        const double t = std::stod(rows[r][0]), boxX = std::stod(rows[r][2]),
                     boxY = std::stod(rows[r][3]), rodX = std::stod(rows[r + 1][2]),
                     rodY = std::stod(rows[r + 1][3]), theta = std::stod(rows[r + 1][6]);
        EXPECT_NEAR(theta, omega0 / W * std::sin(W * t), 0.01 * omega0 / W) << "t = " << t;
        const double pinX = rodX - d * std::sin(theta), pinY = rodY + d * std::cos(theta);
        EXPECT_NEAR(std::hypot(pinX - boxX, pinY - (boxY - 0.02)), 0, 1e-6) << "t = " << t;
    }
    j["bodies"][1]["motion"]["hinge_body"] = 1;
    expectOneLine(runText("hinge_on_itself", j), kScene,
                  {"bodies[1].motion.hinge_body", "another"});
    j["bodies"][1]["motion"].erase("hinge");
    expectOneLine(runText("hinge_body_alone", j), kScene,
                  {"bodies[1].motion.hinge_body", "\"hinge\""});
}
