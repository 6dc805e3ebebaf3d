// The device step's neighbour grid, run by the host execution (the code the CUDA kernels run),
// against brute force over every pair: the same neighbours with the same pair vectors (bitwise),
// without periodic axes and with them, with few cells on a periodic axis, and in the order the
// grid promises (increasing sorted index where no axis wraps).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <tuple>
#include <vector>

#include "device/neighbour_grid.hpp"
#include "spatial/cell_grid.hpp"

namespace {

using num::device::HostExecution;
using num::device::Index;

template <int Dim>
void checkAgainstBruteForce(std::array<bool, Dim> periodic, double radius, unsigned seed,
                            Index n = 600) {
    using V = num::Vec<double, Dim>;
    num::Domain<Dim> domain;
    for (int k = 0; k < Dim; ++k) domain.min[k] = -0.5, domain.max[k] = 0.5 + 0.25 * k;
    domain.periodic = periodic;
    std::mt19937 rng(seed);
    std::vector<V> x(n);
    for (V& p : x)
        for (int k = 0; k < Dim; ++k)
            p[k] = std::uniform_real_distribution<double>(domain.min[k], domain.max[k])(rng);
    // Some particles outside the box on axes that do not wrap (wall layers lie there).
    for (Index i = 0; i < n / 10; ++i)
        for (int k = 0; k < Dim; ++k)
            if (!periodic[k]) x[i][k] += (i % 2 ? 1 : -1) * 0.05;

    HostExecution exec;
    bool flags[Dim];
    for (int k = 0; k < Dim; ++k) flags[k] = periodic[k];
    num::device::NeighbourGrid<Dim, HostExecution> grid(exec, radius, domain.min, domain.max,
                                                        flags);
    grid.build(x.data(), n);
    // The permutation is one: every particle exactly once.
    std::vector<Index> order(grid.order(), grid.order() + n), sortedCheck = order;
    std::sort(sortedCheck.begin(), sortedCheck.end());
    for (Index k = 0; k < n; ++k) ASSERT_EQ(sortedCheck[k], k);
    std::vector<V> sorted(n);
    for (Index k = 0; k < n; ++k) sorted[k] = x[order[k]];

    bool anyPeriodic = false;
    for (bool p : periodic) anyPeriodic |= p;
    std::size_t pairs = 0;
    for (Index i = 0; i < n; ++i) {
        std::vector<std::tuple<Index, V, double>> found, expected;
        num::device::forEachNeighbour<Dim>(
            grid.grid(), sorted.data(), grid.start(), grid.end(), i,
            [&](Index j, const V& dx, double r2) { found.emplace_back(j, dx, r2); });
        for (Index j = 0; j < n; ++j) {
            if (j == i) continue;
            V dx;
            for (int k = 0; k < Dim; ++k) dx[k] = sorted[i][k] - sorted[j][k];
            dx = domain.minimumImage(dx);
            if (normSqr(dx) < radius * radius) expected.emplace_back(j, dx, normSqr(dx));
        }
        if (!anyPeriodic) {  // the promised order: increasing index
            for (std::size_t k = 1; k < found.size(); ++k)
                ASSERT_LT(std::get<0>(found[k - 1]), std::get<0>(found[k]));
        }
        std::sort(found.begin(), found.end(),
                  [](const auto& a, const auto& b) { return std::get<0>(a) < std::get<0>(b); });
        ASSERT_EQ(found.size(), expected.size()) << "particle " << i;
        for (std::size_t k = 0; k < found.size(); ++k) {
            EXPECT_EQ(std::get<0>(found[k]), std::get<0>(expected[k]));
            EXPECT_EQ(std::get<1>(found[k]), std::get<1>(expected[k]));  // bitwise
            EXPECT_EQ(std::get<2>(found[k]), std::get<2>(expected[k]));
        }
        pairs += found.size();
    }
    EXPECT_GT(pairs, std::size_t(n));  // the case has neighbours to find
}

TEST(DeviceNeighbourGrid, MatchesBruteForceWithoutPeriodicAxes2D) {
    checkAgainstBruteForce<2>({false, false}, 0.09, 1);
}
TEST(DeviceNeighbourGrid, MatchesBruteForceWithoutPeriodicAxes3D) {
    checkAgainstBruteForce<3>({false, false, false}, 0.17, 2);
}
TEST(DeviceNeighbourGrid, MatchesBruteForceWithPeriodicAxes) {
    checkAgainstBruteForce<2>({true, false}, 0.09, 3);
    checkAgainstBruteForce<2>({true, true}, 0.09, 4);
    checkAgainstBruteForce<3>({true, false, true}, 0.17, 5);
}
TEST(DeviceNeighbourGrid, MatchesBruteForceWithOneOrTwoCellsOnAPeriodicAxis) {
    checkAgainstBruteForce<2>({true, false}, 0.6, 6, 200);   // 1 cell across x
    checkAgainstBruteForce<2>({true, false}, 0.45, 7, 200);  // 2 cells across x
}

}  // namespace
