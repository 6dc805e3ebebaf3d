// physics::Kernel: the 2D app's kernel API, a thin wrapper of num::SPHKernel<2>.
#pragma once

#include "spatial/sph_kernel.hpp"

namespace physics {

struct Kernel {
    using K = num::SPHKernel<2>;
    static float W(float r, float h) { return K::W(r, h); }
    static float dW_dr(float r, float h) { return K::dW_dr(r, h); }
    static float Spiky_dW_dr(float r, float h) { return K::Spiky_dW_dr(r, h); }
    static void Spiky_gradW(float rx, float ry, float r, float h, float& gx, float& gy) {
        const auto g = K::Spiky_gradW({rx, ry}, r, h);
        gx = g[0];
        gy = g[1];
    }
};

}  // namespace physics
