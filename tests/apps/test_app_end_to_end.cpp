// End to end: the apps run tiny 2D and 3D scenes with both backends and write every output the
// scene asks for (VTU + PVD series, CSV, PNG, probes.csv, summary.json).
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "app_runner.hpp"
#include "vtu_reader.hpp"

using namespace apptest;

struct Case {
    int dim;
    std::string backend;
};

class EndToEnd : public ::testing::TestWithParam<Case> {};

namespace {

/// Output k (t = 0.01 k), named `name`: the VTU with every field, the CSV and the PNG.
void expectSnapshot(const std::string& out, const std::string& name, int k, int dim) {
    const VtuFile v = readVtu(readFile(out + name + ".vtu"));
    EXPECT_NEAR(v.time, 0.01 * k, 1e-12);
    ASSERT_GT(v.points, 0u);
    for (const char* field :
         {"velocity", "density", "pressure", "temperature", "mass", "material"}) {
        ASSERT_TRUE(v.arrays.count(field)) << field;
        const VtuArray& a = v.arrays.at(field);
        EXPECT_EQ(a.values.size(), v.points * a.components) << field;
    }
    EXPECT_EQ(v.arrays.at("velocity").components, 3);
    // CSV named like the VTU: header, then fluid particles only (fewer rows than points).
    const std::string csv = readFile(out + name + ".csv");
    const std::string header = csv.substr(0, csv.find('\n'));
    EXPECT_EQ(header.rfind(dim == 2 ? "x,y,vx,vy,density,pressure,temperature,mass,material"
                                    : "x,y,z,vx,vy,vz,density,pressure,temperature,mass,material",
                           0),
              0u)
        << header;
    const auto rows = std::count(csv.begin(), csv.end(), '\n') - 1;
    EXPECT_GT(rows, 0);
    EXPECT_LT(std::size_t(rows), v.points);
    const std::string png = readFile(out + name + ".png");
    ASSERT_GT(png.size(), 8u);
    EXPECT_EQ(png.substr(1, 3), "PNG");
}

/// probes.csv: a time column and <probe>.<field> columns, one row per millisecond (the default
/// output.probes_every; the steps are shorter) from t = 0 to the end, 0.02 s.
void expectProbes(const std::string& out, int dim) {
    const std::string probes = readFile(out + "probes.csv");
    EXPECT_EQ(probes.substr(0, probes.find('\n')),
              dim == 2 ? "time,p1.pressure,p1.vx,p1.vy" : "time,p.temperature");
    const std::vector<double> times = readCsv(out + "probes.csv").at("time");
    ASSERT_EQ(times.size(), 21u);
    for (std::size_t k = 0; k < times.size(); ++k)
        EXPECT_EQ(std::floor(times[k] / 1e-3 + 1e-9), double(k)) << times[k];
    EXPECT_DOUBLE_EQ(times.back(), 0.02);
}

/// summary.json: every key, the run's settings, and the conservation of mass.
void expectSummary(const std::string& out, const Case& c) {
    const auto s = nlohmann::json::parse(readFile(out + "summary.json"));
    for (const char* key : {"dimension", "particles", "steps", "final_time", "wall_seconds",
                            "particle_steps_per_second", "threads", "backend", "conservation"})
        EXPECT_TRUE(s.contains(key)) << key;
    EXPECT_EQ(s["dimension"], c.dim);
    EXPECT_EQ(s["backend"], c.backend);
    EXPECT_EQ(s["threads"], c.backend == "seq" ? 1 : 2);
    EXPECT_NEAR(s["final_time"].get<double>(), 0.02, 1e-12);
    EXPECT_GT(s["steps"].get<int>(), 0);
    for (const char* key :
         {"mass", "momentum", "kinetic_energy", "potential_energy", "thermal_energy"})
        EXPECT_TRUE(s["conservation"].contains(key)) << key;
    // No emitter or outflow in the 2D scene: the fluid mass is conserved exactly.
    if (c.dim == 2)
        EXPECT_EQ(s["conservation"]["mass"]["start"], s["conservation"]["mass"]["end"]);
    else
        EXPECT_GT(s["emitted_particles"].get<int>(), 0);  // the 3D scene's emitter ran
}

}  // namespace

// ASSERT_NO_FATAL_FAILURE: a failed ASSERT in a helper ends the test, as it did inline.
TEST_P(EndToEnd, WritesEveryOutput) {
    const Case c = GetParam();
    const std::string app = c.dim == 2 ? FLUID_SIM : FLUID_SIM_3D;
    const std::string dir = freshDir("e2e_" + std::to_string(c.dim) + "d_" + c.backend);
    const Result r = run(app,
                         "'" + scene(c.dim == 2 ? "tiny_2d.json" : "tiny_3d.json") +
                             "' --out out --backend " + c.backend + " --threads 2",
                         dir);
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_TRUE(contains(r.output, "particles.pvd")) << r.output;  // tells what to open
    const std::string out = dir + "/out/";

    // Outputs at t = 0, 0.01, 0.02: three VTU files listed in the series with their times.
    const std::string pvd = readFile(out + "particles.pvd");
    for (int k = 0; k < 3; ++k) {
        const std::string name = "particles_000" + std::to_string(k);
        EXPECT_TRUE(contains(pvd, "file=\"" + name + ".vtu\"")) << pvd;
        ASSERT_NO_FATAL_FAILURE(expectSnapshot(out, name, k, c.dim));
    }
    ASSERT_NO_FATAL_FAILURE(expectProbes(out, c.dim));
    expectSummary(out, c);
}

INSTANTIATE_TEST_SUITE_P(Apps, EndToEnd,
                         ::testing::Values(Case{2, "seq"}, Case{2, "omp"}, Case{2, "threads"},
                                           Case{3, "seq"}, Case{3, "omp"}, Case{3, "threads"}),
                         [](const auto& info) {
                             return std::to_string(info.param.dim) + "D_" + info.param.backend;
                         });

/// particles.evaluation selects the symmetric pair loop (each pair once): bitwise the same for 1
/// and 2 threads, and the same flow as the default asymmetric loop up to round-off growth.
TEST(Apps, SymmetricEvaluationFromTheScene) {
    const std::string dir = freshDir("symmetric");
    const std::string common = "--quiet '" + scene("tiny_2d.json") + "' ";
    const std::string sym = common + "--set particles.evaluation=symmetric ";
    ASSERT_EQ(run(FLUID_SIM, sym + "--threads 1 --out s1", dir).code, 0);
    ASSERT_EQ(run(FLUID_SIM, sym + "--threads 2 --out s2", dir).code, 0);
    ASSERT_EQ(run(FLUID_SIM, common + "--threads 2 --out a2", dir).code, 0);
    const std::string last = "/particles_0002.vtu";
    EXPECT_EQ(readFile(dir + "/s1" + last), readFile(dir + "/s2" + last));
    const VtuFile s = readVtu(readFile(dir + "/s2" + last));
    const VtuFile a = readVtu(readFile(dir + "/a2" + last));
    const auto& ps = s.arrays.at("pressure").values;
    const auto& pa = a.arrays.at("pressure").values;
    ASSERT_EQ(ps.size(), pa.size());
    EXPECT_NE(ps, pa);  // another order of the additions
    // After 0.02 s the two loops differ by round-off only: pressures (0 to 710 Pa) agree to
    // 1e-3 Pa (measured: below 1e-6 Pa, equal in 10 digits).
    for (std::size_t i = 0; i < ps.size(); ++i) EXPECT_NEAR(ps[i], pa[i], 1e-3) << i;
    const Result bad = run(FLUID_SIM, common + "--set particles.evaluation=both --out b", dir);
    EXPECT_NE(bad.code, 0);
    EXPECT_TRUE(contains(bad.output, "particles.evaluation")) << bad.output;
}

TEST(Apps, HelpShowsExamplesAndVersionPrints) {
    const std::string dir = freshDir("help");
    const Result help = run(FLUID_SIM, "--help", dir);
    EXPECT_EQ(help.code, 0);
    for (const char* option :
         {"--out", "--threads", "--backend", "--end-time", "--set", "--restart",
          "--checkpoint-every", "--quiet", "--version", "--list-scenes", "Examples:"})
        EXPECT_TRUE(contains(help.output, option)) << option;
    const Result version = run(FLUID_SIM_3D, "--version", dir);
    EXPECT_EQ(version.code, 0);
    EXPECT_TRUE(contains(version.output, "0.1.0"));
    // With anything else, the version is a bad command line, and so are two options of which
    // one would be ignored.
    for (const char* args :
         {"--version --bogus", "--version --list-scenes", "--print-scene --list-scenes"}) {
        const Result r = run(FLUID_SIM, args, dir);
        EXPECT_EQ(r.code, 2) << args << ": " << r.output;
        EXPECT_TRUE(contains(r.output, "error:")) << args << ": " << r.output;
    }
}

TEST(Apps, QuietPrintsNothing) {
    const std::string dir = freshDir("quiet");
    const Result r =
        run(FLUID_SIM, "'" + scene("tiny_2d.json") + "' --quiet --end-time 0.005", dir);
    EXPECT_EQ(r.code, 0);
    EXPECT_EQ(r.output, "");
}

TEST(Apps, SetOverridesSceneValues) {
    const std::string dir = freshDir("set");
    const Result r =
        run(FLUID_SIM,
            "'" + scene("tiny_2d.json") +
                "' --print-scene --set particles.spacing=0.01 --set fluids.0.temperature=30",
            dir);
    ASSERT_EQ(r.code, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    EXPECT_EQ(j["particles"]["spacing"], 0.01);
    EXPECT_EQ(j["fluids"][0]["temperature"], 30);
}

TEST(Apps, DefaultScenesAreBuiltIn) {
    const std::string dir = freshDir("defaults");
    const Result r2 = run(FLUID_SIM, "--print-scene", dir);
    ASSERT_EQ(r2.code, 0);
    EXPECT_EQ(nlohmann::json::parse(r2.output),
              nlohmann::json::parse(readFile(scene("../../../scenes/dam_break_hot_cold_2d.json"))));
    const Result r3 = run(FLUID_SIM_3D, "--print-scene", dir);
    ASSERT_EQ(r3.code, 0);
    EXPECT_EQ(nlohmann::json::parse(r3.output),
              nlohmann::json::parse(readFile(scene("../../../scenes/hot_cold_exchange_3d.json"))));
}

// Every shipped example scene (scenes/*.json) starts with the app its dimension names: its
// set-up (sound speed, particles, outputs at t = 0) and a first step succeed.
TEST(Apps, EveryShippedSceneStarts) {
    const std::filesystem::path shipped = scene("../../../scenes");
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(shipped)) {
        if (entry.path().extension() != ".json") continue;
        const auto j = nlohmann::json::parse(readFile(entry.path().string()));
        const std::string app = j.at("dimension") == 2 ? FLUID_SIM : FLUID_SIM_3D;
        const std::string dir = freshDir("shipped_" + entry.path().stem().string());
        const Result r = run(app,
                             "'" + entry.path().string() +
                                 "' --out out --end-time 1e-5 --threads 2 --set output.video=false",
                             dir);
        EXPECT_EQ(r.code, 0) << entry.path() << ":\n" << r.output;
        ++count;
    }
    EXPECT_GE(count, 5);
}

TEST(Apps, HeldWallTemperaturesAreInTheColourRange) {
    // The tiny scene's water is 20 to 30 C, its body 60 C and its x_max side held at 10 C; an
    // interior wall held at 90 C widens the default colour range of the pictures and of the
    // ParaView script to [10, 90].
    nlohmann::json j = nlohmann::json::parse(readFile(scene("tiny_2d.json")));
    j["walls"] = nlohmann::json::parse(R"([{"shape": "polygon",
        "points": [[0.12, 0.14], [0.18, 0.14], [0.18, 0.18]], "thermal": {"temperature": 90}}])");
    const std::string dir = freshDir("wall_colour_range");
    writeFile(dir + "/scene.json", j.dump());
    ASSERT_EQ(run(FLUID_SIM, "scene.json --quiet --out out --end-time 0.002", dir).code, 0);
    const std::string script = readFile(dir + "/out/particles_paraview.py");
    EXPECT_TRUE(contains(script, "temperature_range = [10, 90]")) << script.substr(0, 600);
}
