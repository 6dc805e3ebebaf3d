// The seed API num::SPHKernel<Dim> (float, numerics 0.1.0) against the double kernel family,
// against an independent normalisation of the spiky kernel, and the seed's usage snippet.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "kernel_test_support.hpp"
#include "spatial/sph_kernel.hpp"

namespace num::test {
namespace {

using std::numbers::pi;

// The seed API must agree with the double implementation to 1e-6 relative (issue 2). Float
// rounds q = r/h by half an ulp (1.2e-7 near q = 2); near the support edge the cancellation in
// 2 - q turns this into an absolute error of up to |df/dq| * 1.2e-7 ~ 2e-7 of the kernel's
// scale (W(0, h), resp. the steepest slope), however small the value itself. So where h is not
// a power of two the bound is 1e-6 relative to max(|value|, scale); where h is a power of two
// q is exact in float and the bound is 1e-6 relative to the value itself, at every r.
constexpr double kFloatRelative = 1e-6;

/// Radii in float: a fine grid over [0, 2.5h] plus the knots 0, h and 2h exactly.
std::vector<float> seedRadii(float h) {
    std::vector<float> r{0.0f,
                         h,
                         2.0f * h,
                         std::nextafter(h, 0.0f),
                         std::nextafter(h, 2.0f * h),
                         std::nextafter(2.0f * h, 0.0f)};
    for (int k = 0; k <= 500; ++k) r.push_back(2.5f * h * float(k) / 500.0f);
    return r;
}

template <int D>
void expectSeedMatchesFamily(float h, bool exactQuotient) {
    using Seed = SPHKernel<D>;
    using Cubic = kernels::CubicSpline<D>;
    using Spk = kernels::Spiky<D>;
    const double hd = h;
    const double wScale = Cubic::W(0.0, hd);
    const double slopeScale = std::abs(Cubic::dW_dr(2.0 * hd / 3.0, hd));  // steepest: q = 2/3
    const double spikyScale = std::abs(Spk::dW_dr(0.0, hd));
    double worst = 0.0;
    for (float r : seedRadii(h)) {
        const double rd = r;
        const double w = Cubic::W(rd, hd), dw = Cubic::dW_dr(rd, hd), sdw = Spk::dW_dr(rd, hd);
        const double fW = exactQuotient ? 0.0 : wScale, fS = exactQuotient ? 0.0 : slopeScale;
        const double fP = exactQuotient ? 0.0 : spikyScale;
        EXPECT_NEAR(Seed::W(r, h), w, kFloatRelative * std::max(std::abs(w), fW)) << "r=" << r;
        EXPECT_NEAR(Seed::dW_dr(r, h), dw, kFloatRelative * std::max(std::abs(dw), fS))
            << "r=" << r;
        EXPECT_NEAR(Seed::Spiky_dW_dr(r, h), sdw, kFloatRelative * std::max(std::abs(sdw), fP))
            << "r=" << r;
        if (std::max(std::abs(w), fW) > 0.0)
            worst = std::max(worst, std::abs(Seed::W(r, h) - w) / std::max(std::abs(w), fW));
    }
    std::printf(
        "[ measured ] SPHKernel<%d>, h = %g: worst W difference %.1e (relative to max(W, fW))\n", D,
        double(h), worst);
}

TEST(SeedKernelApi, FloatAgreesWithDoubleFamily2D) {
    expectSeedMatchesFamily<2>(1.0f, true);
    expectSeedMatchesFamily<2>(0.25f, true);
    expectSeedMatchesFamily<2>(0.013f, false);
    expectSeedMatchesFamily<2>(3.7f, false);
}
TEST(SeedKernelApi, FloatAgreesWithDoubleFamily3D) {
    expectSeedMatchesFamily<3>(1.0f, true);
    expectSeedMatchesFamily<3>(0.25f, true);
    expectSeedMatchesFamily<3>(0.013f, false);
    expectSeedMatchesFamily<3>(3.7f, false);
}

// Independent normalisation of the spiky kernel W = C (H - r)^3, H = 2h: C = 1 / int (H - r)^3
// dV, integrated here by Gauss-Legendre (exact for this polynomial), then dW/dr = -3 C (H-r)^2
// is compared with the seed's Spiky_dW_dr and the family's Spiky.
template <int D>
void expectSpikyNormalisation(float h) {
    const double H = 2.0 * double(h);
    const GaussLegendre rule(8);
    const double volume =
        unitSphereSurface(D) *
        rule.integrate([&](double r) { return std::pow(H - r, 3) * std::pow(r, D - 1); }, 0.0, H);
    const double C = 1.0 / volume;
    for (int k = 0; k <= 100; ++k) {
        const double r = H * k / 100.0;
        const float rf = float(r);
        const double expected = -3.0 * C * (H - double(rf)) * (H - double(rf));
        const double scale = 3.0 * C * H * H;  // |dW/dr| at r = 0
        EXPECT_NEAR(SPHKernel<D>::Spiky_dW_dr(rf, h), expected,
                    kFloatRelative * (std::abs(expected) + 1e-3 * scale))
            << "r = " << r;
        EXPECT_NEAR(kernels::Spiky<D>::W(r, h), C * std::pow(H - r, 3), 1e-12 * C * H * H * H);
    }
}

TEST(SeedKernelApi, SpikyCoefficientsMatchIndependentNormalisation) {
    for (float h : {1.0f, 0.5f, 0.02f}) {
        expectSpikyNormalisation<2>(h);
        expectSpikyNormalisation<3>(h);
    }
}

TEST(SeedKernelApi, SpikyGradientIsSlopeTimesDirection) {
    const float h = 0.1f;
    const std::array<float, 3> rv{0.03f, -0.05f, 0.07f};
    const float r = std::sqrt(rv[0] * rv[0] + rv[1] * rv[1] + rv[2] * rv[2]);
    const auto g3 = SPHKernel<3>::Spiky_gradW(rv, r, h);
    const auto g2 = SPHKernel<2>::Spiky_gradW({rv[0], rv[1]}, r, h);
    const float s3 = SPHKernel<3>::Spiky_dW_dr(r, h) / r, s2 = SPHKernel<2>::Spiky_dW_dr(r, h) / r;
    for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(g3[k], s3 * rv[k]);
    for (int k = 0; k < 2; ++k) EXPECT_FLOAT_EQ(g2[k], s2 * rv[k]);
    // The gradient points from j towards i with a negative slope: it is antiparallel to r_vec.
    EXPECT_LT(g3[0] * rv[0] + g3[1] * rv[1] + g3[2] * rv[2], 0.0f);
    // At r = 0 the direction is undefined and the gradient is zero, not NaN.
    const auto g0 = SPHKernel<2>::Spiky_gradW({0.0f, 0.0f}, 0.0f, h);
    EXPECT_EQ(g0[0], 0.0f);
    EXPECT_EQ(g0[1], 0.0f);
}

// The seed 000 usage snippet, verbatim, in a scope that declares the names it uses.
TEST(SeedKernelApi, UsageSnippetCompilesAndGivesDocumentedValues) {
    constexpr int Dim = 2;
    const float h = 0.1f, m = 0.01f, rx = 0.06f, ry = 0.08f, rz = 0.0f;
    const float r = std::sqrt(rx * rx + ry * ry + rz * rz), r2 = r * r, eps2 = 0.01f * h * h;

    // --- seed 000 "Usage" (verbatim) ---
    // 2D density update
    const float W0 = num::SPHKernel<2>::W(0.0f, h);
    const float w = m * num::SPHKernel<2>::W(r, h);
    // 2D pressure gradient
    auto g = num::SPHKernel<2>::Spiky_gradW({rx, ry}, r, h);
    float gx = g[0], gy = g[1];
    // 3D pressure gradient
    auto g3 = num::SPHKernel<3>::Spiky_gradW({rx, ry, rz}, r, h);
    // Morris Laplacian (viscosity / heat, same formula for 2D and 3D)
    float lap = 2.0f * num::SPHKernel<Dim>::Spiky_dW_dr(r, h) * r / (r2 + eps2);
    // --- end of snippet ---

    // The documented values, written from the seed's formulas.
    const double hd = h, q = double(r) / hd;
    EXPECT_NEAR(W0, 10.0 / (7.0 * pi * hd * hd), 1e-6 * W0);
    const double cubic = 10.0 / (7.0 * pi * hd * hd) * (1 - 1.5 * q * q + 0.75 * q * q * q);
    EXPECT_NEAR(w, m * cubic, 1e-6 * m * cubic);
    const double spiky2 = -15.0 / (16.0 * pi * std::pow(hd, 5)) * std::pow(2 * hd - r, 2);
    EXPECT_NEAR(gx, spiky2 * rx / r, 1e-6 * std::abs(spiky2));
    EXPECT_NEAR(gy, spiky2 * ry / r, 1e-6 * std::abs(spiky2));
    const double spiky3 = -45.0 / (pi * std::pow(2 * hd, 6)) * std::pow(2 * hd - r, 2);
    EXPECT_NEAR(g3[0], spiky3 * rx / r, 1e-6 * std::abs(spiky3));
    EXPECT_NEAR(g3[1], spiky3 * ry / r, 1e-6 * std::abs(spiky3));
    EXPECT_EQ(g3[2], 0.0f);
    // The snippet's last line uses the spiky slope (a fault of the seed, see
    // sph_kernel.hpp); it computes what it says ...
    const double lapSpiky = 2.0 * spiky2 * r / (double(r2) + double(eps2));
    EXPECT_NEAR(lap, lapSpiky, 1e-6 * std::abs(lapSpiky));
    // ... while the documented Morris Laplacian uses the cubic spline's dW_dr, which differs.
    const double cubicSlope = 10.0 / (7.0 * pi * hd * hd * hd) * (-3 * q + 2.25 * q * q);
    const float lapMorris = 2.0f * num::SPHKernel<Dim>::dW_dr(r, h) * r / (r2 + eps2);
    EXPECT_NEAR(lapMorris, 2.0 * cubicSlope * r / (double(r2) + double(eps2)),
                1e-6 * std::abs(lapMorris));
    EXPECT_GT(std::abs(lapMorris - lap), 0.1 * std::abs(lapMorris));
}

}  // namespace
}  // namespace num::test
