// Inlets and outlets through the apps (boundaries of type "inlet" and "outlet"): the books of
// summary.json close, runs are bitwise for any thread count and from a restart, and bad inlets
// and outlets are refused in one line naming the key.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "app_runner.hpp"

using namespace apptest;
using json = nlohmann::json;

namespace {

constexpr int kScene = 5, kExpression = 6;

json sceneJson(int dim) {
    return json::parse(readFile(scene(dim == 2 ? "inlet_outlet_2d.json" : "inlet_outlet_3d.json")));
}

/// Runs the app of the scene's dimension on the scene text in a fresh folder.
Result runText(const std::string& name, const json& j, const std::string& extra = "") {
    const std::string dir = freshDir("flow_" + name);
    writeFile(dir + "/scene.json", j.dump());
    const std::string app = j["dimension"] == 2 ? FLUID_SIM : FLUID_SIM_3D;
    return run(app, "scene.json --quiet --out out " + extra, dir);
}

json summaryOf(const std::string& name) {
    return json::parse(
        readFile(std::string(APP_TEST_WORK) + "/flow_" + name + "/out/summary.json"));
}

}  // namespace

// Water flows through: mass end = start + in - out to round-off; the heat the inflow brings,
// the outflow takes and the cold wall draws close the thermal books to within 1e-6 of the
// water's heat (a particle that leaves takes half a step's conduction with it).
class FlowBooks : public ::testing::TestWithParam<int> {};

TEST_P(FlowBooks, Close) {
    const std::string name = "books_" + std::to_string(GetParam());
    ASSERT_EQ(runText(name, sceneJson(GetParam())).code, 0);
    const json c = summaryOf(name)["conservation"];
    const json& m = c["mass"];
    const json& e = c["thermal_energy"];
    EXPECT_GT(m["in"].get<double>(), 0.2 * m["start"].get<double>());
    EXPECT_GT(m["out"].get<double>(), 0.2 * m["start"].get<double>());
    const double mass = m["start"].get<double>() + m["in"].get<double>() - m["out"].get<double>();
    EXPECT_NEAR(m["end"].get<double>(), mass, 1e-12 * mass);
    EXPECT_LT(e["walls"].get<double>(), 0.0);  // the wall at 10 degC cools the water
    const double heat = e["start"].get<double>() + e["in"].get<double>() - e["out"].get<double>() +
                        e["walls"].get<double>();
    EXPECT_NEAR(e["end"].get<double>(), heat, 1e-6 * heat);
}

INSTANTIATE_TEST_SUITE_P(Apps, FlowBooks, ::testing::Values(2, 3));

// The same bits with 1 and 2 threads, and from a restart while water flows through.
class FlowRestart : public ::testing::TestWithParam<int> {};

TEST_P(FlowRestart, IsBitwiseForThreadsAndRestarts) {
    const int dim = GetParam();
    const std::string dir = freshDir("flow_restart_" + std::to_string(dim));
    writeFile(dir + "/scene.json", sceneJson(dim).dump());
    const std::string app = dim == 2 ? FLUID_SIM : FLUID_SIM_3D;
    const std::string common = "scene.json --quiet --backend omp ";
    ASSERT_EQ(run(app, common + "--threads 2 --out full", dir).code, 0);
    ASSERT_EQ(run(app, common + "--threads 1 --out one", dir).code, 0);
    const Result first =
        run(app, common + "--threads 2 --out part --end-time 0.05 --checkpoint-every 0.05", dir);
    ASSERT_EQ(first.code, 0) << first.output;
    const std::string end = dim == 2 ? "0.2" : "0.1";
    const Result resumed = run(app,
                               "--quiet --backend omp --threads 2 --out part --end-time " + end +
                                   " --restart part/checkpoint_0001.chk",
                               dir);
    ASSERT_EQ(resumed.code, 0) << resumed.output;
    const std::string last = dim == 2 ? "particles_0004.vtu" : "particles_0002.vtu";
    const std::string a = readFile(dir + "/full/" + last);
    ASSERT_FALSE(a.empty());
    EXPECT_TRUE(a == readFile(dir + "/one/" + last)) << "1 thread differs from 2";
    EXPECT_TRUE(a == readFile(dir + "/part/" + last)) << "the restart differs";
    const json full = json::parse(readFile(dir + "/full/summary.json"))["conservation"];
    const json part = json::parse(readFile(dir + "/part/summary.json"))["conservation"];
    EXPECT_EQ(full["mass"], part["mass"]);
    EXPECT_EQ(full["thermal_energy"], part["thermal_energy"]);
}

INSTANTIATE_TEST_SUITE_P(Apps, FlowRestart, ::testing::Values(2, 3));

TEST(InletOutlet, BadInletsAndOutletsAreRefusedByKey) {
    json j = sceneJson(2);
    j["boundaries"]["x_min"]["velocity"] = {"-0.1", 0};
    expectOneLine(runText("outward", j), kScene,
                  {"boundaries.x_min.velocity", "into the domain", "0.1 m/s out of it"});
    j = sceneJson(2);
    j["boundaries"]["x_min"]["velocity"] = {"0.1*q", 0};
    expectOneLine(runText("variable", j), kExpression, {"boundaries.x_min.velocity[0]", "q"});
    j = sceneJson(2);
    j["boundaries"]["x_max"] = {{"type", "periodic"}};
    expectOneLine(runText("periodic", j), kScene, {"boundaries.x_min.type", "periodic"});
    j = sceneJson(2);
    j["boundaries"]["x_max"]["to"] = {0.04, 0.005};
    expectOneLine(runText("narrow", j), kScene, {"boundaries.x_max.to", "two spacings"});
    j = sceneJson(2);
    j["boundaries"]["x_max"]["from"] = {0.03, 0.004};
    expectOneLine(runText("off_side", j), kScene, {"boundaries.x_max.from", "on the side"});
    j = sceneJson(2);
    j["boundaries"]["x_max"].erase("to");
    expectOneLine(runText("half_opening", j), kScene, {"boundaries.x_max", "\"from\" and \"to\""});
    j = sceneJson(2);
    j["boundaries"]["x_min"]["pressure"] = 3;
    expectOneLine(runText("inlet_pressure", j), kScene, {"boundaries.x_min.pressure", "outlet"});
    j = sceneJson(2);
    j["boundaries"]["x_min"].erase("velocity");
    expectOneLine(runText("no_velocity", j), kScene, {"boundaries.x_min", "velocity"});
}

// The CUDA back end refuses inlets and outlets by name rather than running them as walls.
TEST(InletOutlet, TheCudaBackEndRefusesThem) {
    const Result r = runText("cuda", sceneJson(2), "--backend cuda");
    expectOneLine(r, kScene, {"--backend cuda", "an inlet or outlet"});
}
