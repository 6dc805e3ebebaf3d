// The probe plot (probes.png): one panel per quantity, a line per probe in its own colour, gaps
// where a probe had no fluid near (nan), and no failure on an empty table.
#include <gtest/gtest.h>

#include "io/probe_plot.hpp"

namespace {

using num::io::Image;
using num::io::plotProbes;
using num::io::Rgb;

int countColour(const Image& img, Rgb c) {
    int n = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const Rgb p = img.at(x, y);
            n += p.r == c.r && p.g == c.g && p.b == c.b;
        }
    return n;
}

const Rgb kFirst{31, 119, 180}, kSecond{214, 39, 40};  // the plot's first two line colours

TEST(ProbePlot, OnePanelPerQuantityAndALinePerProbe) {
    const std::string csv =
        "time,a.temperature,b.temperature\n0,10,20\n0.5,12,nan\n1,14,nan\n1.5,16,26\n";
    const Image one = plotProbes(csv, "t", 800);
    EXPECT_EQ(one.width(), 800);
    EXPECT_GT(countColour(one, kFirst), 200);  // probe a: a line across the panel
    EXPECT_GT(countColour(one, kSecond), 20);  // probe b: its legend and the segment after nan
    const Image two = plotProbes("time,a.temperature,a.vx,a.vy\n0,10,0,1\n1,12,1,0\n", "t", 800);
    EXPECT_GT(two.height(), one.height());  // temperature and velocity: two panels
}

TEST(ProbePlot, AnEmptyTableGivesAPictureNotAFailure) {
    EXPECT_GT(plotProbes("", "t").height(), 0);
    EXPECT_GT(plotProbes("time,a.pressure\n", "t").height(), 0);
}

}  // namespace
