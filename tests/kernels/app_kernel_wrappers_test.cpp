// The apps' kernel APIs (physics::Kernel for fluid_sim, physics::Kernel3D for fluid_sim_3d)
// are thin wrappers: every function must return exactly what num::SPHKernel returns.
#include <gtest/gtest.h>

#include <cmath>

#include "fluid_sim/kernel.hpp"
#include "fluid_sim_3d/kernel3d.hpp"
#include "spatial/sph_kernel.hpp"

namespace {

TEST(AppKernelWrappers, Kernel2DDelegatesToSPHKernel2) {
    using Seed = num::SPHKernel<2>;
    const float h = 0.037f;
    for (int k = 0; k <= 250; ++k) {
        const float r = 2.5f * h * float(k) / 250.0f;
        EXPECT_EQ(physics::Kernel::W(r, h), Seed::W(r, h));
        EXPECT_EQ(physics::Kernel::dW_dr(r, h), Seed::dW_dr(r, h));
        EXPECT_EQ(physics::Kernel::Spiky_dW_dr(r, h), Seed::Spiky_dW_dr(r, h));
        const float rx = 0.6f * r, ry = -0.8f * r;
        float gx = NAN, gy = NAN;
        physics::Kernel::Spiky_gradW(rx, ry, r, h, gx, gy);
        const auto g = Seed::Spiky_gradW({rx, ry}, r, h);
        EXPECT_EQ(gx, g[0]);
        EXPECT_EQ(gy, g[1]);
    }
    // Not vacuous: inside the support the values are non-zero.
    EXPECT_GT(physics::Kernel::W(0.5f * h, h), 0.0f);
    EXPECT_LT(physics::Kernel::Spiky_dW_dr(0.5f * h, h), 0.0f);
}

TEST(AppKernelWrappers, Kernel3DDelegatesToSPHKernel3) {
    using Seed = num::SPHKernel<3>;
    const float h = 0.021f;
    for (int k = 0; k <= 250; ++k) {
        const float r = 2.5f * h * float(k) / 250.0f;
        EXPECT_EQ(physics::Kernel3D::W(r, h), Seed::W(r, h));
        EXPECT_EQ(physics::Kernel3D::dW_dr(r, h), Seed::dW_dr(r, h));
        EXPECT_EQ(physics::Kernel3D::Spiky_dW_dr(r, h), Seed::Spiky_dW_dr(r, h));
        const float rx = 0.48f * r, ry = -0.6f * r, rz = 0.64f * r;
        float gx = NAN, gy = NAN, gz = NAN;
        physics::Kernel3D::Spiky_gradW(rx, ry, rz, r, h, gx, gy, gz);
        const auto g = Seed::Spiky_gradW({rx, ry, rz}, r, h);
        EXPECT_EQ(gx, g[0]);
        EXPECT_EQ(gy, g[1]);
        EXPECT_EQ(gz, g[2]);
    }
    EXPECT_GT(physics::Kernel3D::W(0.5f * h, h), 0.0f);
    EXPECT_LT(physics::Kernel3D::dW_dr(0.5f * h, h), 0.0f);
}

}  // namespace
