// The VTU files read back with a reader of our own (vtu_reader.hpp, written from the format
// description, independent of the writer): the initial state matches the scene exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "app_runner.hpp"
#include "vtu_reader.hpp"

using namespace apptest;

TEST(VtuReadBack, InitialStateMatchesTheScene) {
    const std::string dir = freshDir("readback");
    const Result r =
        run(FLUID_SIM, "'" + scene("tiny_2d.json") + "' --quiet --out out --end-time 0.001", dir);
    ASSERT_EQ(r.code, 0) << r.output;
    const VtuFile v = readVtu(readFile(dir + "/out/particles_0000.vtu"));
    EXPECT_EQ(v.time, 0.0);
    const auto& x = v.arrays.at("Points").values;
    const auto& vel = v.arrays.at("velocity").values;
    const auto& T = v.arrays.at("temperature").values;
    const auto& rho = v.arrays.at("density").values;
    const auto& m = v.arrays.at("mass").values;
    const auto& kind = v.arrays.at("kind").values;
    const auto& mat = v.arrays.at("material").values;
    ASSERT_EQ(x.size(), 3 * v.points);
    const double dx = 0.02;  // tiny_2d.json: particles.spacing
    int fluid = 0, hotBody = 0, coldWall = 0;
    for (std::size_t i = 0; i < v.points; ++i) {
        const double px = x[3 * i], py = x[3 * i + 1];
        EXPECT_EQ(x[3 * i + 2], 0.0);  // 2D points lie in z = 0
        // Lattice of cell centres: (i + 1/2) dx from the domain corner (0, 0).
        EXPECT_NEAR(std::fmod(px / dx + 100.5, 1.0), 0.0, 1e-9);
        if (kind[i] == 0) {
            ++fluid;
            // The scene's fluid block: [0, 0.1] x [0, 0.12], T = 20 + 100 x, v = (0.5 y, 0).
            EXPECT_TRUE(px > 0 && px < 0.1 && py > 0 && py < 0.12);
            EXPECT_NEAR(T[i], 20 + 100 * px, 1e-12);
            EXPECT_NEAR(vel[3 * i], 0.5 * py, 1e-15);
            EXPECT_EQ(vel[3 * i + 1], 0.0);
            EXPECT_EQ(rho[i], 1000.0);  // rest density, no initial pressure
            EXPECT_NEAR(m[i], 1000.0 * dx * dx, 1e-15);
            EXPECT_EQ(mat[i], 0.0);
        } else if (kind[i] == 2) {
            ++hotBody;
            EXPECT_EQ(T[i], 60.0);                    // bodies[0].temperature
        } else if (px > 0.2 && py > 0 && py < 0.2) {  // beside the right wall, not a corner
            ++coldWall;
            EXPECT_EQ(T[i], 10.0);  // boundaries.right.thermal.temperature
        }
    }
    EXPECT_EQ(fluid, 5 * 6);  // 0.1 / dx by 0.12 / dx
    EXPECT_GT(hotBody, 0);
    EXPECT_GT(coldWall, 0);
}
