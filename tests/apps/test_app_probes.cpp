// Probes at their own rate (output.probes_every) and their plot by scripts/plot_series.py: rows
// at the first step that reaches each multiple, steps untouched by the probes, the plot as PNG
// and SVG, and a run that goes on with one line when Python or matplotlib is missing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app_runner.hpp"

namespace {

using namespace apptest;
namespace fs = std::filesystem;

/// The tiny 2D scene (outputs every 10 ms to t = 0.02 s) with `output` keys changed, in `dir`.
std::string tinyScene(const std::string& dir, const nlohmann::json& output) {
    nlohmann::json j = nlohmann::json::parse(readFile(scene("tiny_2d.json")));
    j["output"].update(output);
    writeFile(dir + "/scene.json", j.dump());
    return "scene.json --out out --threads 2";
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream s(text);
    for (std::string l; std::getline(s, l);) out.push_back(l);
    return out;
}

/// The interval of `every` seconds each row's time falls in (a row per interval expected).
std::vector<long> slots(const std::vector<double>& times, double every) {
    std::vector<long> out;
    for (double t : times) out.push_back(std::lround(std::floor(t / every + 1e-9)));
    return out;
}

std::vector<long> upTo(long n) {
    std::vector<long> out;
    for (long k = 0; k <= n; ++k) out.push_back(k);
    return out;
}

TEST(AppProbes, SampledAtTheirOwnRateWithoutChangingTheSteps) {
    const std::string a = freshDir("probes_default"), b = freshDir("probes_5ms");
    ASSERT_EQ(run(FLUID_SIM, tinyScene(a, {{"video", false}}), a).code, 0);
    ASSERT_EQ(run(FLUID_SIM, tinyScene(b, {{"video", false}, {"probes_every", 0.005}}), b).code, 0);
    // Default: every 1 ms (the steps are shorter), not at the outputs' 10 ms.
    const std::vector<double> t1 = readCsv(a + "/out/probes.csv").at("time");
    EXPECT_EQ(slots(t1, 1e-3), upTo(20));
    const std::vector<double> t5 = readCsv(b + "/out/probes.csv").at("time");
    EXPECT_EQ(slots(t5, 5e-3), upTo(4));
    EXPECT_DOUBLE_EQ(t5.back(), 0.02);
    // The probes do not shorten the steps: the same particles, and the 5 ms rows are 1 ms rows.
    EXPECT_EQ(readFile(a + "/out/particles_0002.vtu"), readFile(b + "/out/particles_0002.vtu"));
    const std::vector<std::string> all = lines(readFile(a + "/out/probes.csv"));
    for (const std::string& row : lines(readFile(b + "/out/probes.csv")))
        EXPECT_NE(std::find(all.begin(), all.end(), row), all.end()) << row;
}

TEST(AppProbes, PlotAsPngAndSvg) {
    const std::string dir = freshDir("probes_svg");
    const Result r =
        run(FLUID_SIM, tinyScene(dir, {{"video", false}, {"plots", {"png", "svg"}}}), dir);
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_EQ(readFile(dir + "/out/probes.png").substr(1, 3), "PNG");
    EXPECT_TRUE(contains(readFile(dir + "/out/probes.svg"), "<svg"));
    const auto summary = nlohmann::json::parse(readFile(dir + "/out/summary.json"));
    EXPECT_EQ(summary.at("probe_plot"), "out/probes.png");
    EXPECT_EQ(summary.at("probe_plot_note"), "");
    EXPECT_TRUE(contains(r.output, "probes.png, probes.svg")) << r.output;
}

/// Runs the tiny scene with the environment variable `name` set to `value`.
Result runWith(const std::string& dir, const char* name, const std::string& value) {
    ::setenv(name, value.c_str(), 1);
    Result r = run(FLUID_SIM, tinyScene(dir, {{"video", false}}), dir);
    ::unsetenv(name);
    return r;
}

/// The run completes with its probes.csv and says in one line why there is no plot.
void expectNoPlot(const std::string& dir, const Result& r, const std::string& why) {
    ASSERT_EQ(r.code, 0) << r.output;
    const std::string last = lines(r.output).back();
    EXPECT_EQ(last.rfind("fluid_sim: no probe plot: ", 0), 0u) << r.output;
    EXPECT_TRUE(contains(last, why)) << r.output;
    EXPECT_FALSE(fs::exists(dir + "/out/probes.png"));
    EXPECT_EQ(readCsv(dir + "/out/probes.csv").at("time").size(), 21u);
    const auto summary = nlohmann::json::parse(readFile(dir + "/out/summary.json"));
    EXPECT_EQ(summary.at("status"), "completed");
    EXPECT_EQ(summary.at("probe_plot"), "");
    EXPECT_TRUE(contains(summary.at("probe_plot_note").get<std::string>(), why));
}

TEST(AppProbes, NoPythonIsOneLine) {
    const std::string dir = freshDir("probes_no_python");
    expectNoPlot(dir, runWith(dir, "NUMERICS_PYTHON", "/nonexistent/python3"),
                 "python3 is not installed");
}

TEST(AppProbes, NoMatplotlibIsOneLine) {
    // A matplotlib that cannot be imported, first on Python's path.
    const std::string dir = freshDir("probes_no_matplotlib");
    fs::create_directories(dir + "/fake/matplotlib");
    writeFile(dir + "/fake/matplotlib/__init__.py", "raise ImportError('not here')\n");
    expectNoPlot(dir, runWith(dir, "PYTHONPATH", dir + "/fake"), "matplotlib is not installed");
}

}  // namespace
