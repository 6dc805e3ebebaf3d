// Properties every SPH kernel must have (reference_solutions.md section 1; Monaghan 2005, section
// 2), checked once for every kernel of num::kernels in 1D, 2D and 3D.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "kernel_test_support.hpp"

namespace num::test {
namespace {

template <class K>
class KernelFamily : public ::testing::Test {};
TYPED_TEST_SUITE(KernelFamily, AllKernels, KernelName);

// Smoothing lengths at which every property is checked: the properties must hold for any h.
constexpr double kLengths[] = {1.0, 0.05, 3.7};

// reference_solutions.md 1: finite differences with step 1e-6 h agree with the analytic derivative
// to 1e-6 relative. The absolute floor is the rounding error of a central difference, ~ eps_machine
// * W(0) / step = 2.2e-16 / 1e-6 * W(0) = 2.2e-10 W(0); we allow 1e-9 W(0) / h, which matters only
// where the slope itself vanishes (r -> 0 and r -> support).
constexpr double kFdStep = 1e-6;
constexpr double kFdRelative = 1e-6;
constexpr double kFdFloor = 1e-9;

template <class K>
bool nearBreakpoint(double r, double h, double margin) {
    for (double b : KernelFacts<K>::breakpoints)
        if (std::abs(r - b * h) < margin) return true;
    return false;
}

/// Radii covering the support, avoiding the breakpoints by more than 100 finite-difference steps.
template <class K>
std::vector<double> radiiAwayFromKnots(double h, int n = 600) {
    std::vector<double> r;
    const double H = K::supportRadius(h);
    for (int k = 0; k < n; ++k) {
        const double x = (k + 0.5) / n * H;
        if (!nearBreakpoint<K>(x, h, 100 * kFdStep * h)) r.push_back(x);
    }
    return r;
}

template <class K>
Vec<double, K::dim> randomInBall(std::mt19937& rng, double radius) {
    std::uniform_real_distribution<double> u(-radius, radius);
    Vec<double, K::dim> x;
    do {
        for (int k = 0; k < K::dim; ++k) x[k] = u(rng);
    } while (norm(x) > radius);
    return x;
}

// reference_solutions.md 1: the radial integral S_d int W r^(d-1) dr equals 1 to 1e-10 in double.
// The quadrature is Gauss-Legendre with 12 nodes on each polynomial piece (exact to degree 23;
// the integrands here have degree <= 10), so the 1e-10 measures the normalisation alone.
TYPED_TEST(KernelFamily, IntegratesToOne) {
    using K = TypeParam;
    double worst = 0.0;
    for (double h : kLengths) {
        const double integral = radialIntegral<K>([&](double r) { return K::W(r, h); }, h);
        EXPECT_NEAR(integral, 1.0, 1e-10) << "h = " << h;
        worst = std::max(worst, std::abs(integral - 1.0));
    }
    // A 6-node rule (exact to degree 11) gives the same answer: the quadrature is converged.
    const double coarse = radialIntegral<K>([](double r) { return K::W(r, 1.0); }, 1.0, 6);
    EXPECT_NEAR(coarse, 1.0, 1e-10);
    std::printf("[ measured ] %s%dD |integral - 1| = %.2e\n", KernelFacts<K>::name.c_str(), K::dim,
                worst);
}

// reference_solutions.md 1: W and grad W are exactly 0 at and beyond the support radius.
TYPED_TEST(KernelFamily, VanishesExactlyAtAndBeyondSupport) {
    using K = TypeParam;
    for (double h : kLengths) {
        const double H = K::supportRadius(h);
        EXPECT_DOUBLE_EQ(H, KernelFacts<K>::breakpoints.back() * h);
        for (double r : {H, std::nextafter(H, 2 * H), 1.000001 * H, 1.5 * H, 10 * H}) {
            EXPECT_EQ(K::W(r, h), 0.0) << "r = " << r;
            EXPECT_EQ(K::dW_dr(r, h), 0.0) << "r = " << r;
            EXPECT_EQ(K::dW_dh(r, h), 0.0) << "r = " << r;
            Vec<double, K::dim> rij;
            rij[0] = r;
            EXPECT_EQ(norm(K::gradW(rij, h)), 0.0) << "r = " << r;
        }
        // ... and not before it: the support is not shorter than stated.
        EXPECT_GT(K::W(0.999 * H, h), 0.0);
    }
}

// W and dW/dr are continuous at the knots of the spline and at the edge of the support:
// the jump across a knot over 2e-9 h is bounded by the slope times the distance, far below
// 1e-7 W(0) (a wrong coefficient in one piece would jump by 1e-3 W(0) or more).
TYPED_TEST(KernelFamily, ContinuousAtKnotsAndSupport) {
    using K = TypeParam;
    const double h = 1.0, eps = 1e-9;
    const double w0 = K::W(0.0, h);
    double slopeScale = 0.0;
    for (double r : radiiAwayFromKnots<K>(h)) slopeScale = std::max(slopeScale, -K::dW_dr(r, h));
    const auto& b = KernelFacts<K>::breakpoints;
    for (std::size_t k = 1; k < b.size(); ++k) {
        const double knot = b[k] * h;
        const double left = K::W(knot - eps, h), right = K::W(knot + eps, h);
        EXPECT_NEAR(left, right, 1e-7 * w0) << "knot " << knot;
        EXPECT_NEAR(K::dW_dr(knot - eps, h), K::dW_dr(knot + eps, h), 1e-7 * slopeScale)
            << "knot " << knot;
    }
}

// W(r_ij) = W(r_ji) and grad_i W_ij = -grad_j W_ij, bit for bit: the pair loop relies on it
// to conserve momentum exactly.
TYPED_TEST(KernelFamily, SymmetricInThePair) {
    using K = TypeParam;
    std::mt19937 rng(12345);
    for (double h : kLengths) {
        for (int n = 0; n < 200; ++n) {
            const auto xi = randomInBall<K>(rng, 2.0 * h);
            const auto xj = randomInBall<K>(rng, 2.0 * h);
            EXPECT_EQ(K::W(norm(xi - xj), h), K::W(norm(xj - xi), h));
            const auto gi = K::gradW(xi - xj, h), gj = K::gradW(xj - xi, h);
            for (int k = 0; k < K::dim; ++k) EXPECT_EQ(gi[k], -gj[k]);
        }
    }
}

// W is non-increasing in r and dW/dr <= 0; dW/dr(0) = 0 for the smooth kernels, while the
// spiky kernel is steepest at r = 0 on purpose (reference_solutions.md 1).
TYPED_TEST(KernelFamily, DecreasesMonotonically) {
    using K = TypeParam;
    for (double h : kLengths) {
        const double H = K::supportRadius(h);
        const int n = 20000;
        double previous = K::W(0.0, h);
        double steepest = 0.0;
        for (int k = 1; k <= n; ++k) {
            const double r = 1.1 * H * k / n;
            const double w = K::W(r, h), slope = K::dW_dr(r, h);
            ASSERT_LE(w, previous) << "r = " << r;
            ASSERT_LE(slope, 0.0) << "r = " << r;
            previous = w;
            steepest = std::min(steepest, slope);
        }
        if constexpr (KernelFacts<K>::smoothAtOrigin) {
            EXPECT_LE(std::abs(K::dW_dr(0.0, h)), 1e-14 * std::abs(steepest));
        } else {
            EXPECT_LT(K::dW_dr(0.0, h), 0.0);
            EXPECT_LE(K::dW_dr(0.0, h), steepest);
        }
    }
}

TYPED_TEST(KernelFamily, RadialDerivativeMatchesFiniteDifference) {
    using K = TypeParam;
    double worst = 0.0;
    for (double h : kLengths) {
        const double d = kFdStep * h, floor = kFdFloor * K::W(0.0, h) / h;
        for (double r : radiiAwayFromKnots<K>(h)) {
            const double fd = (K::W(r + d, h) - K::W(r - d, h)) / (2 * d);
            const double exact = K::dW_dr(r, h);
            EXPECT_NEAR(fd, exact, kFdRelative * std::abs(exact) + floor) << "r = " << r;
            if (std::abs(exact) > 1e-3 * K::W(0.0, h) / h)
                worst = std::max(worst, std::abs(fd - exact) / std::abs(exact));
        }
    }
    std::printf("[ measured ] %s%dD dW/dr vs FD: worst relative %.1e\n",
                KernelFacts<K>::name.c_str(), K::dim, worst);
}

TYPED_TEST(KernelFamily, SmoothingLengthDerivativeMatchesFiniteDifference) {
    using K = TypeParam;
    for (double h : kLengths) {
        const double d = kFdStep * h, floor = kFdFloor * K::W(0.0, h) / h;
        // At fixed r the knots move with h: keep r / (h +- d) on one polynomial piece.
        for (double r : radiiAwayFromKnots<K>(h)) {
            const double fd = (K::W(r, h + d) - K::W(r, h - d)) / (2 * d);
            EXPECT_NEAR(fd, K::dW_dh(r, h), kFdRelative * std::abs(K::dW_dh(r, h)) + floor)
                << "r = " << r;
        }
        // dW/dh = 0 would also pass where W is flat; check the sign where it is known:
        // at the origin W = sigma f(0) / h^d, so dW/dh = -d W / h.
        EXPECT_NEAR(K::dW_dh(0.0, h), -K::dim * K::W(0.0, h) / h, 1e-12 * K::W(0.0, h) / h);
    }
}

TYPED_TEST(KernelFamily, GradientMatchesFiniteDifferenceOfW) {
    using K = TypeParam;
    std::mt19937 rng(777);
    for (double h : kLengths) {
        const double d = kFdStep * h, floor = kFdFloor * K::W(0.0, h) / h;
        for (int n = 0; n < 300; ++n) {
            const auto rij = randomInBall<K>(rng, K::supportRadius(h));
            if (nearBreakpoint<K>(norm(rij), h, 100 * d)) continue;
            const auto g = K::gradW(rij, h);
            for (int k = 0; k < K::dim; ++k) {
                auto plus = rij, minus = rij;
                plus[k] += d;
                minus[k] -= d;
                const double fd = (K::W(norm(plus), h) - K::W(norm(minus), h)) / (2 * d);
                EXPECT_NEAR(fd, g[k], kFdRelative * norm(g) + floor) << "component " << k;
            }
        }
    }
}

// Values at the origin for h = 1 (reference_solutions.md 1), and the 1/h^d scaling.
TEST(KernelOriginValues, MatchTheReferenceValues) {
    using std::numbers::pi;
    EXPECT_NEAR(CubicSpline<1>::W(0.0, 1.0), 2.0 / 3.0, 1e-15);
    EXPECT_NEAR(CubicSpline<2>::W(0.0, 1.0), 10.0 / (7.0 * pi), 1e-15);
    EXPECT_NEAR(CubicSpline<3>::W(0.0, 1.0), 1.0 / pi, 1e-15);
    EXPECT_NEAR(WendlandC2<2>::W(0.0, 1.0), 7.0 / (4.0 * pi), 1e-15);
    EXPECT_NEAR(WendlandC2<3>::W(0.0, 1.0), 21.0 / (16.0 * pi), 1e-15);
    EXPECT_NEAR(CubicSpline<2>::W(0.0, 0.5), 4.0 * 10.0 / (7.0 * pi), 1e-14);
    EXPECT_NEAR(WendlandC2<3>::W(0.0, 0.5), 8.0 * 21.0 / (16.0 * pi), 1e-14);
}

// Koschier et al. (2019) write kernels with the support radius H; the conversion h = H / support
// gives the same function.
TEST(KernelConventions, SupportRadiusFormIsTheSameKernel) {
    using std::numbers::pi;
    const double H = 0.8;
    const double h = CubicSpline<2>::hFromSupportRadius(H);
    EXPECT_DOUBLE_EQ(CubicSpline<2>::supportRadius(h), H);
    // Koschier's 2D cubic spline: W = 40/(7 pi H^2) (6q^3 - 6q^2 + 1) for q = r/H <= 1/2.
    for (double r : {0.0, 0.1, 0.25, 0.39}) {
        const double q = r / H;
        const double koschier = 40.0 / (7.0 * pi * H * H) * (6 * q * q * q - 6 * q * q + 1);
        EXPECT_NEAR(CubicSpline<2>::W(r, h), koschier, 1e-14 * koschier);
    }
    EXPECT_DOUBLE_EQ(QuinticSpline<3>::supportRadius(1.0), 3.0);
    EXPECT_DOUBLE_EQ(WendlandC4<1>::hFromSupportRadius(3.0), 1.5);
}

}  // namespace
}  // namespace num::test
