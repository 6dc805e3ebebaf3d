// Cavitation through fluid_sim: water stretched beyond physics.max_tension (default 98,986 Pa,
// one atmosphere less water's vapour pressure) is held at that tension, never below it.
// A closed box of water, started with u = 60 (x - 0.1) m/s: its middle stretches by 6 % in
// 1 ms, and with c0 = 56 m/s (B = rho0 c0^2 / 7 = 448 kPa) the equation of state alone gives
// -149 kPa there.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <vector>

#include "app_runner.hpp"

using namespace apptest;

namespace {

const char* kStretchedBox = R"json({
  "dimension": 2,
  "name": "stretched water",
  "domain": { "min": [0, 0], "max": [0.2, 0.1] },
  "boundaries": {
    "x_min": { "type": "wall" }, "x_max": { "type": "wall" },
    "y_min": { "type": "wall" }, "y_max": { "type": "wall" }
  },
  "particles": { "spacing": 0.005 },
  "time": { "end": 0.001 },
  "gravity": [0, 0],
  "materials": { "water": { "density": 1000, "sound_speed": 56 } },
  "fluids": [ { "material": "water", "shape": "box", "min": [0, 0], "max": [0.2, 0.1],
                "velocity": ["60*(x-0.1)", 0] } ],
  "physics": { "heat": false },
  "output": { "directory": "out", "every": 0.001, "formats": ["csv"], "images": false,
              "video": false }
})json";

/// The fluid particles' pressures in the run's output at t = 1 ms.
std::vector<double> pressuresAfterStretching(const std::string& name, const std::string& extra) {
    const std::string dir = freshDir("cavitation_" + name);
    writeFile(dir + "/scene.json", kStretchedBox);
    const Result r = run(FLUID_SIM, "scene.json --quiet --threads 1 --out out " + extra, dir);
    EXPECT_EQ(r.code, 0) << r.output;
    const Table out = readCsv(dir + "/out/particles_0001.csv");
    const std::vector<double>& pressure = out.at("pressure");
    const std::vector<double>& kind = out.at("kind");
    std::vector<double> p;
    for (std::size_t i = 0; i < pressure.size(); ++i)
        if (kind[i] == 0) p.push_back(pressure[i]);
    EXPECT_EQ(p.size(), 800u);
    return p;
}

double lowest(const std::vector<double>& p) {
    return p.empty() ? std::numeric_limits<double>::quiet_NaN()
                     : *std::min_element(p.begin(), p.end());
}

}  // namespace

TEST(Cavitation, StretchedWaterIsHeldAtTheDefaultTension) {
    const auto p = pressuresAfterStretching("default", "");
    EXPECT_DOUBLE_EQ(lowest(p), -98986);  // held there: 360 of the 800 particles
    EXPECT_GT(std::count(p.begin(), p.end(), -98986.0), 100);
}

TEST(Cavitation, TheSceneSetsTheTension) {
    EXPECT_DOUBLE_EQ(lowest(pressuresAfterStretching("50kPa", "--set physics.max_tension=5e4")),
                     -5e4);
    // With a limit no water reaches, the equation of state alone: about -149 kPa.
    EXPECT_LT(lowest(pressuresAfterStretching("none", "--set physics.max_tension=1e12")), -1.2e5);
}
