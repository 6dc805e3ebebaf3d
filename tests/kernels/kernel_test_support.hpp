// Shared tools of the kernel tests: the list of kernels x dimensions, their piecewise-polynomial
// breakpoints (written here from the formulas, independently of the header), Gauss-Legendre
// quadrature and lattice sums.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "spatial/kernels.hpp"

namespace num::test {

using kernels::CubicSpline;
using kernels::QuinticSpline;
using kernels::Spiky;
using kernels::WendlandC2;
using kernels::WendlandC4;

/// Facts about a kernel that the tests know from its formula: its name, the breakpoints (in
/// units of h) between which it is one polynomial, and whether its slope vanishes at r = 0.
template <class K>
struct KernelFacts;

template <int D>
struct KernelFacts<CubicSpline<D>> {
    static inline const std::string name = "CubicSpline";
    static inline const std::vector<double> breakpoints{0.0, 1.0, 2.0};
    static constexpr bool smoothAtOrigin = true;
};
template <int D>
struct KernelFacts<QuinticSpline<D>> {
    static inline const std::string name = "QuinticSpline";
    static inline const std::vector<double> breakpoints{0.0, 1.0, 2.0, 3.0};
    static constexpr bool smoothAtOrigin = true;
};
template <int D>
struct KernelFacts<WendlandC2<D>> {
    static inline const std::string name = "WendlandC2";
    static inline const std::vector<double> breakpoints{0.0, 2.0};
    static constexpr bool smoothAtOrigin = true;
};
template <int D>
struct KernelFacts<WendlandC4<D>> {
    static inline const std::string name = "WendlandC4";
    static inline const std::vector<double> breakpoints{0.0, 2.0};
    static constexpr bool smoothAtOrigin = true;
};
template <int D>
struct KernelFacts<Spiky<D>> {
    static inline const std::string name = "Spiky";
    static inline const std::vector<double> breakpoints{0.0, 2.0};
    // The spiky kernel keeps a non-zero slope at r = 0 on purpose (Mueller et al. 2003).
    static constexpr bool smoothAtOrigin = false;
};

/// Every kernel of the family in 1D, 2D and 3D (double precision).
using AllKernels = ::testing::Types<CubicSpline<1>, CubicSpline<2>, CubicSpline<3>,
                                    QuinticSpline<1>, QuinticSpline<2>, QuinticSpline<3>,
                                    WendlandC2<1>, WendlandC2<2>, WendlandC2<3>, WendlandC4<1>,
                                    WendlandC4<2>, WendlandC4<3>, Spiky<1>, Spiky<2>, Spiky<3>>;

struct KernelName {
    template <class K>
    static std::string GetName(int) {
        return KernelFacts<K>::name + std::to_string(K::dim) + "D";
    }
};

/// Gauss-Legendre rule with n nodes on [-1, 1]; nodes found by Newton's method on P_n.
/// Exact for polynomials of degree <= 2n - 1.
struct GaussLegendre {
    std::vector<double> x, w;
    explicit GaussLegendre(int n) : x(n), w(n) {
        for (int i = 0; i < n; ++i) {
            double t = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
            double dp = 0.0;
            for (int it = 0; it < 100; ++it) {
                // Three-term recurrence (k+1) P_{k+1} = (2k+1) t P_k - k P_{k-1}.
                double p0 = 1.0, p1 = t;
                for (int k = 1; k < n; ++k) {
                    const double p2 = ((2.0 * k + 1.0) * t * p1 - k * p0) / (k + 1.0);
                    p0 = p1;
                    p1 = p2;
                }
                dp = n * (t * p1 - p0) / (t * t - 1.0);
                const double step = p1 / dp;
                t -= step;
                if (std::abs(step) < 1e-16) break;
            }
            x[i] = t;
            w[i] = 2.0 / ((1.0 - t * t) * dp * dp);
        }
    }
    /// Integral of f over [a, b].
    template <class F>
    double integrate(F&& f, double a, double b) const {
        const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
        double s = 0.0;
        for (std::size_t i = 0; i < x.size(); ++i) s += w[i] * f(mid + half * x[i]);
        return s * half;
    }
};

/// Surface of the unit sphere in `dim` dimensions: 2, 2 pi, 4 pi.
inline double unitSphereSurface(int dim) {
    return dim == 1 ? 2.0 : dim == 2 ? 2.0 * std::numbers::pi : 4.0 * std::numbers::pi;
}

/// Radial integral S_d int_0^H g(r) r^(d-1) dr, one Gauss-Legendre rule per polynomial piece of
/// the kernel (breakpoints in units of h), so that polynomial integrands are integrated exactly.
template <class K, class G>
double radialIntegral(G&& g, double h, int nodes = 12) {
    const GaussLegendre rule(nodes);
    const auto& b = KernelFacts<K>::breakpoints;
    double sum = 0.0;
    for (std::size_t s = 0; s + 1 < b.size(); ++s) {
        sum += rule.integrate([&](double r) { return g(r) * std::pow(r, K::dim - 1); }, b[s] * h,
                              b[s + 1] * h);
    }
    return unitSphereSurface(K::dim) * sum;
}

/// Sums over a Cartesian lattice of spacing dx = 1 around the particle at the origin:
///   partition   sum_j W_ij dx^d                                      (exact: 1)
///   gradientX   x-component of sum_j V_j (x_j - x_i) grad_i W_ij      (exact: 1)
///   laplacian   Brookshaw (1985): sum_j V_j 2 (A_i - A_j) (r_ij . grad_i W_ij) / (r_ij^2 + eta^2)
///               for A = |x|^2, divided by the exact value 2d; eta^2 = 0.01 h^2
struct LatticeSums {
    double partition = 0.0, gradientX = 0.0, laplacian = 0.0;
};

template <class K>
LatticeSums latticeSums(double hOverDx) {
    constexpr int D = K::dim;
    const double h = hOverDx;  // dx = 1, so V_j = 1
    const int reach = int(std::ceil(K::supportRadius(h))) + 1;
    const double eta2 = 0.01 * h * h;
    LatticeSums s;
    int idx[3] = {0, 0, 0};
    const int count = int(std::pow(2 * reach + 1, D));
    for (int n = 0; n < count; ++n) {
        int rest = n;
        Vec<double, D> xj;
        for (int k = 0; k < D; ++k) {
            idx[k] = rest % (2 * reach + 1) - reach;
            rest /= 2 * reach + 1;
            xj[k] = double(idx[k]);
        }
        const Vec<double, D> rij = -xj;  // x_i - x_j with x_i = 0
        const double r = norm(rij);
        s.partition += K::W(r, h);
        if (r == 0.0) continue;
        const Vec<double, D> grad = K::gradW(rij, h);
        s.gradientX += xj[0] * grad[0];
        const double aDiff = 0.0 - normSqr(xj);
        s.laplacian += 2.0 * aDiff * dot(rij, grad) / (r * r + eta2);
    }
    s.laplacian /= 2.0 * D;
    return s;
}

}  // namespace num::test
