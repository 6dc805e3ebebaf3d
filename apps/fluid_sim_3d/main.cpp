// fluid_sim_3d. Until the scene runner lands: prints the seed kernel table the app uses.
#include <cstdio>

#include "kernel3d.hpp"

int main() {
    const float h = 0.02f;
    std::printf("fluid_sim_3d 0.1.0: 3D cubic spline kernel, h = %g\n", h);
    for (int k = 0; k <= 8; ++k) {
        const float r = 0.25f * float(k) * h;
        std::printf("%8.2f %14.6g %14.6g\n", r / h, physics::Kernel3D::W(r, h),
                    physics::Kernel3D::Spiky_dW_dr(r, h));
    }
    return 0;
}
