// A box closed by walls on every side and full of fluid stays full: the differentially heated
// cavity at Ra = 1e5 (scenes/validation/natural_convection_ra1e5.json) at spacing 0.05, run to
// t = 10 s. With the density by continuity, particle shifting packed particles below their
// nominal spacing at the walls while the continuity density stayed at rho0, and a void opened
// under the top wall (at t = 10 s 14 of the 20 particles of the top row were left, the centre
// of mass had sunk by 3.6 % of the height, and by t = 36 s the u probe under the top wall saw
// no fluid). docs/physics.md, "Closed boxes".
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "app_runner.hpp"

using namespace apptest;

TEST(ClosedBox, HeatedCavityStaysFullUnderTheTopWall) {
    const double dx = 0.05;
    const int perRow = 20;  // 1 m / dx
    const std::string dir = freshDir("closed_box_ra1e5");
    const Result r = run(FLUID_SIM,
                         "'" + std::string(NUMERICS_SCENES_DIR) +
                             "/validation/natural_convection_ra1e5.json' --out out --threads 1 -q"
                             " --set particles.spacing=0.05 --set time.end=10"
                             " --set output.every=10",
                         dir);
    ASSERT_EQ(r.code, 0) << r.output;
    const std::string out = dir + "/out/";

    // Fluid within one spacing of the top wall (y = 1) across the whole width.
    const Table particles = readCsv(out + "particles_0001.csv");
    const std::vector<double>& x = particles.at("x");
    const std::vector<double>& y = particles.at("y");
    ASSERT_EQ(x.size(), std::size_t(perRow * perRow));
    int top = 0;
    std::set<int> columns;
    for (std::size_t i = 0; i < x.size(); ++i)
        if (y[i] > 1 - dx) ++top, columns.insert(int(std::floor(x[i] / dx)));
    EXPECT_GE(top, perRow * 9 / 10) << "particles within dx of the top wall";
    EXPECT_GE(int(columns.size()), perRow * 9 / 10) << "columns with fluid under the top wall";

    // The fluid has not settled: its centre of mass (potential energy m g y) stays at mid-height.
    const nlohmann::json summary = nlohmann::json::parse(readFile(out + "summary.json"));
    const double pe0 = summary["conservation"]["potential_energy"]["start"];
    const double pe1 = summary["conservation"]["potential_energy"]["end"];
    EXPECT_NEAR(pe1 / pe0, 1.0, 0.01);

    // The probe just under the top wall sees fluid.
    const std::vector<double> u40 = readCsv(out + "probes.csv").at("u40.vx");
    ASSERT_FALSE(u40.empty());
    for (double u : u40) EXPECT_TRUE(std::isfinite(u));
}
