// The geometry of a pair (i, j), written once for the CPU pair loop and the CUDA kernels.
//   dx = x_i - x_j (nearest periodic image), r = |dx|, w = W(r, h), grad_i W = dx (1/r) dW/dr,
//   laplacian = dx . grad_i W / (r^2 + eta^2),  eta^2 = defaults::laplacianEta2 h^2:
//               the second-derivative factor of viscosity and conduction (Morris, Fox & Zhu
//               1997, eq. 8; Brookshaw 1985);
//   inverseR2 = 1 / (r^2 + eta^2),  eta^2 = defaults::inverseR2Eta2 h^2: of the artificial
//               viscosity (Monaghan 1992, eq. 4.2) and delta-SPH (Antuono et al. 2010).
#pragma once

#include <limits>

#include "spatial/kernels.hpp"
#include "sph/host_device.hpp"
#include "sph/types.hpp"

namespace num::sph {

/// Geometry of one pair (i, j): dx = x_i - x_j, r = |dx|, the kernel value w = W(r, h) (0
/// unless a derivative asked for kernel values), and the two shared factors above, computed once
/// per pair (a division each).
template <int Dim>
struct PairGeometry {
    Vector<Dim> dx;
    Float r;
    Float w;
    Float laplacian;
    Float inverseR2;
};

namespace formulas {

/// dx . grad_i W / (r^2 + eta2): the Laplacian factor of the pair (Morris et al. 1997, eq. 8).
template <int Dim>
NUMERICS_HD Float pairLaplacian(const Vector<Dim>& dx, const Vector<Dim>& grad, Float r,
                                Float eta2) {
    return dot(dx, grad) / (r * r + eta2);
}

/// 1 / (r^2 + eta2) (Monaghan 1992, eq. 4.2).
NUMERICS_HD_INLINE Float pairInverseR2(Float r, Float eta2) { return 1.0 / (r * r + eta2); }

}  // namespace formulas

namespace detail {
template <class Kernel>
struct KernelProfile {};
template <class Profile, int Dim, class T>
struct KernelProfile<kernels::RadialKernel<Profile, Dim, T>> {
    using type = Profile;
};
}  // namespace detail

/// (1/r) dW/dr of a radial kernel for the pair loop, without branches or divisions other than
/// by r, so that the loop over a particle's neighbours vectorises. Equals Kernel::gradFactor
/// to round-off for 0 < r < support radius (every found neighbour), and gives 0 at r = 0 (where
/// the smooth kernels' dW/dr vanishes).
/// The clamp of q is a member, not the constant: the compiler turns a clamp to a constant into
/// a branch around the constant-folded f(support), and a loop with a branch does not vectorise
/// (hence also the copies the pair loop makes inside each thread's function).
template <class Kernel>
struct GradientFactor {
    using Profile = typename detail::KernelProfile<Kernel>::type;
    Float invH, scale, support = Kernel::support;
    explicit GradientFactor(Float h)
        : invH(1 / h), scale(Kernel::sigma / (Kernel::hPowDim(h) * h)) {}
    NUMERICS_HD Float factor(Float r) const {
        const Float q = hd::min(r * invH, support);
        return scale * Profile::df(q) / hd::max(r, std::numeric_limits<Float>::min());
    }
};

/// W(r) of a radial kernel for the pair loop, without branches, so that the loop over a
/// particle's neighbours vectorises (as GradientFactor). Bitwise Kernel::W for r below the
/// support radius (every found neighbour): the same q = r / h and sigma / h^Dim * f(q); 0 from
/// the support radius on.
template <class Kernel>
struct KernelValue {
    using Profile = typename detail::KernelProfile<Kernel>::type;
    Float h, scale, support = Kernel::support;
    explicit KernelValue(Float h) : h(h), scale(Kernel::sigma / Kernel::hPowDim(h)) {}
    NUMERICS_HD Float value(Float r) const { return scale * Profile::f(hd::min(r / h, support)); }
};

}  // namespace num::sph
