// Lattice sums on an infinite Cartesian lattice (reference_solutions.md section 1, table "Lattice
// sums"): partition of unity sum_j W_ij dx^d, the gradient of a linear field and the Brookshaw
// (1985) Laplacian of |x|^2, for the particle at a lattice node.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "kernel_test_support.hpp"

namespace num::test {
namespace {

constexpr double kRatios[] = {1.0, 1.2, 1.3, 1.5};

/// One row of the validation table: the four values at h/dx = 1.0, 1.2, 1.3, 1.5.
struct TableRow {
    double values[4];
};

// The table gives partition sums to 6 decimals, gradients to 4 and Laplacians to 3: we must
// reproduce each to the digits given, i.e. within half a unit of the last digit.
constexpr double kPartitionDigits = 0.5e-6;
constexpr double kGradientDigits = 0.5e-4;
constexpr double kLaplacianDigits = 0.5e-3;

template <class K>
void expectTable(const TableRow* partition, const TableRow* gradient, const TableRow* laplacian) {
    for (int c = 0; c < 4; ++c) {
        const LatticeSums s = latticeSums<K>(kRatios[c]);
        const std::string where = KernelFacts<K>::name + std::to_string(K::dim) +
                                  "D, h/dx = " + std::to_string(kRatios[c]);
        std::printf("[ measured ] %s: partition %.6f  gradient %.4f  laplacian %.3f\n",
                    where.c_str(), s.partition, s.gradientX, s.laplacian);
        if (partition) {
            EXPECT_NEAR(s.partition, partition->values[c], kPartitionDigits) << where;
        }
        if (gradient) {
            EXPECT_NEAR(s.gradientX, gradient->values[c], kGradientDigits) << where;
        }
        if (laplacian) {
            EXPECT_NEAR(s.laplacian, laplacian->values[c], kLaplacianDigits) << where;
        }
    }
}

// Reference values: reference_solutions.md section 1.
TEST(KernelLatticeTable, CubicSpline1D) {
    const TableRow partition{{1.000000, 1.001800, 1.003466, 1.004115}};
    expectTable<CubicSpline<1>>(&partition, nullptr, nullptr);
}
TEST(KernelLatticeTable, CubicSpline2D) {
    const TableRow partition{{1.000862, 0.999757, 0.999947, 1.003440}};
    const TableRow gradient{{1.0131, 0.9908, 1.0105, 1.0067}};
    const TableRow laplacian{{1.005, 0.981, 1.000, 0.995}};
    expectTable<CubicSpline<2>>(&partition, &gradient, &laplacian);
}
TEST(KernelLatticeTable, CubicSpline3D) {
    const TableRow partition{{0.999972, 1.000810, 0.997262, 1.001795}};
    const TableRow gradient{{1.0200, 0.9817, 0.9935, 1.0101}};
    const TableRow laplacian{{1.013, 0.973, 0.985, 1.001}};
    expectTable<CubicSpline<3>>(&partition, &gradient, &laplacian);
}
TEST(KernelLatticeTable, WendlandC2_2D) {
    const TableRow partition{{1.037602, 1.017952, 1.010473, 1.005142}};
    expectTable<WendlandC2<2>>(&partition, nullptr, nullptr);
}
TEST(KernelLatticeTable, WendlandC2_3D) {
    const TableRow partition{{1.033843, 1.017457, 1.009501, 1.003141}};
    expectTable<WendlandC2<3>>(&partition, nullptr, nullptr);
}

// Kernels and dimensions the table does not list, at the usual ratios h/dx = 1.3 and 1.5.
// The lattice error is the kernel's Fourier transform sampled at the reciprocal lattice
// vectors (Poisson summation), so it depends on the kernel's smoothness and width:
//  - quintic spline (C4, support 3h): its transform decays fastest; 5e-4 on the partition
//    and 0.5 % on the gradient (ten times tighter than the table's cubic spline rows);
//  - Wendland C2/C4 and the remaining C2 kernels (support 2h): the table's worst deviations
//    at h/dx >= 1.3 are 1.05 % (partition, Wendland C2 2D) and 1.05 % (gradient, cubic 2D);
//    Wendland kernels are known to need more neighbours than the cubic spline for the same
//    accuracy (Dehnen & Aly 2012, section 5), so we allow 1.5 % and 3 %, and 5 % for the
//    Brookshaw Laplacian (table worst 2.7 %, of which ~1-2 % is the eta^2 bias).
struct LooseBounds {
    double partition, gradient, laplacian;
};
constexpr LooseBounds kQuinticBounds{5e-4, 5e-3, 0.02};
constexpr LooseBounds kCompactC2Bounds{0.015, 0.03, 0.05};

template <class K>
void expectLoose(const LooseBounds& b) {
    for (double ratio : {1.3, 1.5}) {
        const LatticeSums s = latticeSums<K>(ratio);
        const std::string where =
            KernelFacts<K>::name + std::to_string(K::dim) + "D, h/dx = " + std::to_string(ratio);
        std::printf("[ measured ] %s: partition %.6f  gradient %.4f  laplacian %.3f\n",
                    where.c_str(), s.partition, s.gradientX, s.laplacian);
        EXPECT_NEAR(s.partition, 1.0, b.partition) << where;
        EXPECT_NEAR(s.gradientX, 1.0, b.gradient) << where;
        EXPECT_NEAR(s.laplacian, 1.0, b.laplacian) << where;
    }
}

TEST(KernelLatticeLoose, QuinticSpline) {
    expectLoose<QuinticSpline<1>>(kQuinticBounds);
    expectLoose<QuinticSpline<2>>(kQuinticBounds);
    expectLoose<QuinticSpline<3>>(kQuinticBounds);
}
TEST(KernelLatticeLoose, WendlandC2) {
    expectLoose<WendlandC2<1>>(kCompactC2Bounds);
    // 2D and 3D partition sums are in the table; their gradients and Laplacians are not.
    expectLoose<WendlandC2<2>>(kCompactC2Bounds);
    expectLoose<WendlandC2<3>>(kCompactC2Bounds);
}
TEST(KernelLatticeLoose, WendlandC4) {
    expectLoose<WendlandC4<1>>(kCompactC2Bounds);
    expectLoose<WendlandC4<2>>(kCompactC2Bounds);
    expectLoose<WendlandC4<3>>(kCompactC2Bounds);
}
TEST(KernelLatticeLoose, CubicSpline1D) { expectLoose<CubicSpline<1>>(kCompactC2Bounds); }

// The spiky kernel is for the pressure gradient, not for density: its cusp at r = 0 makes the
// transform decay only like k^-(d+1), so its lattice sums are poor at h/dx ~ 1 (1D: 1.15 at
// 1.3) but must converge as h/dx grows, at least like (dx/h)^2 (the 1D rate). We require an
// observed order >= 1.5 between h/dx = 2 and 4 and errors below 2 % at h/dx = 4.
template <class K>
void expectSpikyConverges() {
    const LatticeSums coarse = latticeSums<K>(2.0), fine = latticeSums<K>(4.0);
    const double orderPartition =
        std::log2(std::abs(coarse.partition - 1.0) / std::abs(fine.partition - 1.0));
    const double orderGradient =
        std::log2(std::abs(coarse.gradientX - 1.0) / std::abs(fine.gradientX - 1.0));
    std::printf(
        "[ measured ] Spiky%dD: partition %.6f -> %.6f (order %.2f), gradient %.4f -> "
        "%.4f (order %.2f)\n",
        K::dim, coarse.partition, fine.partition, orderPartition, coarse.gradientX, fine.gradientX,
        orderGradient);
    EXPECT_GE(orderPartition, 1.5);
    EXPECT_GE(orderGradient, 1.5);
    EXPECT_NEAR(fine.partition, 1.0, 0.02);
    EXPECT_NEAR(fine.gradientX, 1.0, 0.02);
}

TEST(KernelLatticeLoose, SpikyConvergesWithResolution) {
    expectSpikyConverges<Spiky<1>>();
    expectSpikyConverges<Spiky<2>>();
    expectSpikyConverges<Spiky<3>>();
}

}  // namespace
}  // namespace num::test
