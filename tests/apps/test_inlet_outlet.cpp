// Inlets and outlets through the apps (boundaries of type "inlet" and "outlet"): the books of
// summary.json close, runs are bitwise for any thread count and from a restart, bad inlets and
// outlets are refused in one line naming the key, and the CUDA back end runs them.
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

// The CUDA back end (its device step on the host execution) runs them as the CPU back end: the
// same steps, the same mass through the inlet and the outlet, the heat books to round-off.
TEST(InletOutlet, TheCudaBackEndRunsThemAsTheCpuBackEnd) {
    setenv("NUMERICS_TEST_DEVICE_EXECUTION", "host", 1);
    const Result cuda = runText("cuda", sceneJson(2), "--backend cuda");
    unsetenv("NUMERICS_TEST_DEVICE_EXECUTION");
    ASSERT_EQ(cuda.code, 0) << cuda.output;
    ASSERT_EQ(runText("cuda_cpu", sceneJson(2), "--backend cpu").code, 0);
    const json a = summaryOf("cuda"), b = summaryOf("cuda_cpu");
    EXPECT_EQ(a["backend"], "cuda");
    EXPECT_EQ(a["steps"], b["steps"]);
    const json &ma = a["conservation"]["mass"], &mb = b["conservation"]["mass"];
    EXPECT_GT(mb["in"].get<double>(), 0.0);
    for (const char* k : {"in", "out", "end"})
        EXPECT_NEAR(ma[k].get<double>(), mb[k].get<double>(), 1e-12 * mb["end"].get<double>()) << k;
    const json &ea = a["conservation"]["thermal_energy"], &eb = b["conservation"]["thermal_energy"];
    for (const char* k : {"in", "out", "walls", "end"})
        EXPECT_NEAR(ea[k].get<double>(), eb[k].get<double>(), 1e-6 * eb["end"].get<double>()) << k;
}
