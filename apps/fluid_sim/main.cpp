// fluid_sim (2D). Until the scene runner lands: prints the seed kernel table the app uses.
#include <cstdio>

#include "kernel.hpp"

int main() {
    const float h = 0.013f;
    std::printf("fluid_sim 0.1.0: 2D cubic spline kernel, h = %g\n", h);
    std::printf("%8s %14s %14s %14s\n", "r/h", "W", "dW_dr", "Spiky_dW_dr");
    for (int k = 0; k <= 8; ++k) {
        const float r = 0.25f * float(k) * h;
        std::printf("%8.2f %14.6g %14.6g %14.6g\n", r / h, physics::Kernel::W(r, h),
                    physics::Kernel::dW_dr(r, h), physics::Kernel::Spiky_dW_dr(r, h));
    }
    return 0;
}
