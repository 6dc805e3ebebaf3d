// The cell grid against a brute-force oracle: random particles in 1D, 2D and 3D, every subset of
// periodic axes, particles exactly on cell borders, at the domain edges and at the periodic end.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "spatial/cell_grid.hpp"

namespace {

template <int Dim>
using V = num::Vec<double, Dim>;

template <int Dim>
V<Dim> oracleImage(const num::Domain<Dim>& d, V<Dim> dx) {
    for (int k = 0; k < Dim; ++k)
        if (d.periodic[k]) dx[k] -= d.length(k) * std::round(dx[k] / d.length(k));
    return dx;
}

/// Random positions, positions on multiples of the radius (cell borders of non-periodic axes,
/// the lattice of the cells on periodic ones) and at both ends of every axis.
template <int Dim>
std::vector<V<Dim>> makePositions(const num::Domain<Dim>& d, double radius, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::vector<V<Dim>> x;
    for (int n = 0; n < 400; ++n) {
        V<Dim> p;
        for (int k = 0; k < Dim; ++k)
            p[k] = std::uniform_real_distribution<double>(d.min[k], d.max[k])(rng);
        x.push_back(p);
    }
    for (int n = 0; n < 150; ++n) {
        V<Dim> p;
        for (int k = 0; k < Dim; ++k) {
            const int cellsAlong = int(d.length(k) / radius);
            const int m = std::uniform_int_distribution<int>(0, cellsAlong)(rng);
            const int kind = std::uniform_int_distribution<int>(0, 3)(rng);
            // On a border of the radius lattice, on a border of the periodic cell lattice, at the
            // lower end, or at the upper end (the upper end of a periodic axis is its lower end).
            const double cellSize = d.length(k) / std::max(1, cellsAlong);
            p[k] = kind == 0   ? d.min[k] + m * radius
                   : kind == 1 ? d.min[k] + m * cellSize
                   : kind == 2 ? d.min[k]
                               : d.max[k];
            p[k] = std::min(p[k], d.max[k]);
        }
        x.push_back(p);
    }
    return x;
}

/// The flat lists of the pair loop: collect() gives exactly forEachNeighbourOf's neighbours, in
/// its order and bit for bit; collectAfter() finds every pair from exactly one of its particles.
template <int Dim>
void checkFlatLists(const num::CellGrid<Dim>& grid, const std::vector<V<Dim>>& x) {
    typename num::CellGrid<Dim>::Neighbours list;
    const std::uint32_t n = std::uint32_t(x.size());
    std::vector<int> seen(std::size_t(n) * n, 0);
    for (std::uint32_t i = 0; i < n; ++i) {
        std::vector<std::uint32_t> js;
        std::vector<V<Dim>> dxs;
        grid.forEachNeighbourOf(i, [&](std::uint32_t j, const V<Dim>& dx, double) {
            if (j != i) js.push_back(j), dxs.push_back(dx);
        });
        const std::uint32_t m = grid.collect(
            i, [i](std::uint32_t j) { return j != i; }, list);
        ASSERT_EQ(m, js.size());
        for (std::uint32_t k = 0; k < m; ++k) {
            EXPECT_EQ(list.j[k], js[k]);
            EXPECT_TRUE(list.dx[k] == dxs[k]);
            EXPECT_EQ(list.r2[k], num::normSqr(dxs[k]));
        }
        const std::uint32_t after = grid.collectAfter(i, list);
        for (std::uint32_t k = 0; k < after; ++k) {
            const std::uint32_t j = list.j[k];
            ASSERT_NE(j, i);
            ++seen[std::size_t(std::min(i, j)) * n + std::max(i, j)];
            EXPECT_TRUE(std::find(js.begin(), js.end(), j) != js.end());
        }
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        std::size_t count = 0;
        grid.forEachNeighbourOf(i, [&](std::uint32_t j, const V<Dim>&, double) {
            if (j == i) return;
            ++count;
            EXPECT_EQ(seen[std::size_t(std::min(i, j)) * n + std::max(i, j)], 1)
                << "pair " << i << "," << j << " not found exactly once by collectAfter";
        });
    }
}

template <int Dim>
void checkAgainstOracle(const num::Domain<Dim>& domain, double radius, unsigned seed) {
    const std::vector<V<Dim>> x = makePositions(domain, radius, seed);
    num::CellGrid<Dim> grid;
    grid.build(x, radius, domain);
    checkFlatLists(grid, x);
    const double r2max = radius * radius;
    // Pairs within a relative 1e-12 of the radius may go either way (the distance is rounded
    // differently); every other pair must match the oracle exactly.
    const double band = 1e-12 * r2max;
    std::size_t pairs = 0;
    for (std::uint32_t i = 0; i < x.size(); ++i) {
        std::vector<int> found(x.size(), 0);
        std::vector<V<Dim>> foundDx(x.size());
        grid.forEachNeighbourOf(i, [&](std::uint32_t j, const V<Dim>& dx, double r2) {
            ++found[j];
            foundDx[j] = dx;
            EXPECT_LT(r2, r2max);
            EXPECT_DOUBLE_EQ(r2, num::normSqr(dx));
        });
        for (std::uint32_t j = 0; j < x.size(); ++j) {
            const V<Dim> dx = oracleImage(domain, x[i] - x[j]);
            const double r2 = num::normSqr(dx);
            ASSERT_LE(found[j], 1) << "pair " << i << "," << j << " reported twice";
            if (r2 < r2max - band) {
                ASSERT_EQ(found[j], 1)
                    << "missed pair " << i << "," << j << " r = " << std::sqrt(r2);
                for (int k = 0; k < Dim; ++k) EXPECT_NEAR(foundDx[j][k], dx[k], 1e-12);
                ++pairs;
            } else if (r2 >= r2max + band) {
                ASSERT_EQ(found[j], 0) << "spurious pair " << i << "," << j;
            }
        }
    }
    EXPECT_GT(pairs, x.size());  // every particle finds itself, most find others
}

template <int Dim>
void checkAllPeriodicSubsets(double radius, unsigned seed) {
    for (int mask = 0; mask < (1 << Dim); ++mask) {
        num::Domain<Dim> d;
        for (int k = 0; k < Dim; ++k) {
            d.min[k] = -0.3 * (k + 1);
            d.max[k] = d.min[k] + 1.0 + 0.25 * k;  // unequal lengths per axis
            d.periodic[k] = (mask >> k) & 1;
        }
        SCOPED_TRACE("periodic mask " + std::to_string(mask) + ", radius " +
                     std::to_string(radius));
        checkAgainstOracle(d, radius, seed + mask);
    }
}

TEST(NeighbourSearch, MatchesBruteForce1D) {
    for (double radius : {0.07, 0.2, 0.45}) checkAllPeriodicSubsets<1>(radius, 11);
}

TEST(NeighbourSearch, MatchesBruteForce2D) {
    // 0.45: fewer than three cells on the periodic axes (images found per pair).
    for (double radius : {0.1, 0.25, 0.45}) checkAllPeriodicSubsets<2>(radius, 23);
}

TEST(NeighbourSearch, MatchesBruteForce3D) {
    for (double radius : {0.15, 0.3, 0.45}) checkAllPeriodicSubsets<3>(radius, 37);
}

TEST(NeighbourSearch, PairVectorsAreExactlyAntisymmetric) {
    num::Domain<3> d;
    d.max = V<3>::filled(1.0);
    d.periodic = {true, false, true};
    const auto x = makePositions(d, 0.2, 5);
    num::CellGrid<3> grid;
    grid.build(x, 0.2, d);
    std::size_t checked = 0;
    for (std::uint32_t i = 0; i < x.size(); ++i)
        grid.forEachNeighbourOf(i, [&](std::uint32_t j, const V<3>& dij, double) {
            grid.forEachNeighbourOf(j, [&](std::uint32_t k, const V<3>& dji, double) {
                if (k != i) return;
                for (int a = 0; a < 3; ++a) EXPECT_EQ(dij[a], -dji[a]);
                ++checked;
            });
        });
    EXPECT_GT(checked, x.size());
}

TEST(NeighbourSearch, QueryByPositionMatchesQueryByIndex) {
    num::Domain<2> d;
    d.max = V<2>::filled(1.0);
    d.periodic = {true, true};
    const auto x = makePositions(d, 0.15, 3);
    num::CellGrid<2> grid;
    grid.build(x, 0.15, d);
    for (std::uint32_t i = 0; i < x.size(); ++i) {
        std::vector<std::uint32_t> a, b;
        // Pairs at the radius to round-off may go either way (the image is rounded).
        const double inner = 0.15 * 0.15 * (1 - 1e-12);
        grid.forEachNeighbourOf(i, [&](std::uint32_t j, const V<2>&, double r2) {
            if (r2 < inner) a.push_back(j);
        });
        // An image of the position one period away finds the same neighbours.
        V<2> shifted = x[i];
        shifted[0] += 1.0;
        grid.forEachNeighbour(shifted, [&](std::uint32_t j, const V<2>&, double r2) {
            if (r2 < inner) b.push_back(j);
        });
        EXPECT_FALSE(a.empty());
        std::sort(a.begin(), a.end());
        std::sort(b.begin(), b.end());
        EXPECT_EQ(a, b);
    }
}

TEST(NeighbourSearch, SortedOrderIsAPermutationByCell) {
    num::Domain<3> d;
    d.max = V<3>::filled(1.0);
    const auto x = makePositions(d, 0.2, 9);
    num::CellGrid<3> grid;
    grid.build(x, 0.2, d);
    std::vector<std::uint32_t> order = grid.sortedOrder();
    ASSERT_EQ(order.size(), x.size());
    std::sort(order.begin(), order.end());
    for (std::uint32_t i = 0; i < order.size(); ++i) EXPECT_EQ(order[i], i);
}

TEST(NeighbourSearch, RejectsBadInput) {
    num::Domain<2> d;
    d.max = V<2>::filled(1.0);
    d.periodic = {true, false};
    num::CellGrid<2> grid;
    std::vector<V<2>> x(3);
    EXPECT_THROW(grid.build(x, 0.6, d), std::invalid_argument);  // period below 2 radius
    EXPECT_THROW(grid.build(x, 0.0, d), std::invalid_argument);
    x[1][1] = std::nan("");
    EXPECT_THROW(grid.build(x, 0.1, d), std::invalid_argument);
}

}  // namespace
