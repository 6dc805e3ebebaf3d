// physics::Kernel3D: the 3D app's kernel API, a thin wrapper of num::SPHKernel<3>.
#pragma once

#include "spatial/sph_kernel.hpp"

namespace physics {

struct Kernel3D {
    using K = num::SPHKernel<3>;
    static float W(float r, float h) { return K::W(r, h); }
    static float dW_dr(float r, float h) { return K::dW_dr(r, h); }
    static float Spiky_dW_dr(float r, float h) { return K::Spiky_dW_dr(r, h); }
    static void Spiky_gradW(float rx, float ry, float rz, float r, float h, float& gx, float& gy,
                            float& gz) {
        const auto g = K::Spiky_gradW({rx, ry, rz}, r, h);
        gx = g[0];
        gy = g[1];
        gz = g[2];
    }
};

}  // namespace physics
