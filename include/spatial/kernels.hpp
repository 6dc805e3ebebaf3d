// The SPH kernel family: stateless, templated on dimension (1, 2, 3) and scalar type.
//
// Convention. Every kernel here is written in the smoothing-length form
//     W(r, h) = sigma_Dim / h^Dim * f(q),   q = r / h,
// with compact support r < support * h (`support` is a constexpr member: 2 for the cubic
// spline, Wendland C2/C4 and spiky kernels, 3 for the quintic spline).
// Koschier et al. (2019) write the same kernels in the support-radius form with
// H = support * h and q' = r / H in [0, 1]; the two are the same function:
//     W_Koschier(r, H) = W(r, H / support).
// Use `hFromSupportRadius` / `supportRadius` to convert.
//
// Each kernel offers W, dW/dr (<= 0), the gradient with respect to x_i for the pair
// vector r_ij = x_i - x_j, and dW/dh, callable on host and device (sph/host_device.hpp).
#pragma once

#include <array>
#include <numbers>

#include "spatial/vec.hpp"

namespace num::kernels {

/// Shared machinery: a kernel derives from this and provides the shape f(q), its
/// derivative df/dq, the constant `support` and the normalisations sigma(Dim).
template <class Profile, int Dim, class T>
struct RadialKernel {
    static_assert(Dim >= 1 && Dim <= 3, "kernels are defined for Dim = 1, 2, 3");
    static constexpr int dim = Dim;
    static constexpr T support = Profile::template supportIn<T>();
    static constexpr T sigma = Profile::template sigma<T>(Dim);

    /// Support radius H = support * h.
    NUMERICS_HD static constexpr T supportRadius(T h) { return support * h; }
    /// Smoothing length h of the kernel whose support radius is H (Koschier's form).
    NUMERICS_HD static constexpr T hFromSupportRadius(T H) { return H / support; }

    NUMERICS_HD static constexpr T hPowDim(T h) {
        T p = h;
        for (int k = 1; k < Dim; ++k) p *= h;
        return p;
    }

    NUMERICS_HD static T W(T r, T h) {
        const T q = r / h;
        return q >= support ? T(0) : sigma / hPowDim(h) * Profile::f(q);
    }
    NUMERICS_HD static T dW_dr(T r, T h) {
        const T q = r / h;
        return q >= support ? T(0) : sigma / (hPowDim(h) * h) * Profile::df(q);
    }
    /// dW/dh at fixed r: -(sigma / h^(Dim+1)) (Dim f(q) + q f'(q)).
    NUMERICS_HD static T dW_dh(T r, T h) {
        const T q = r / h;
        if (q >= support) return T(0);
        return -sigma / (hPowDim(h) * h) * (T(Dim) * Profile::f(q) + q * Profile::df(q));
    }
    /// grad_i W(|r_ij|, h) for r_ij = x_i - x_j; zero at r = 0 where the direction is undefined.
    NUMERICS_HD static Vec<T, Dim> gradW(const Vec<T, Dim>& rij, T h) {
        const T r = norm(rij);
        if (r <= T(0)) return Vec<T, Dim>{};
        return rij * (dW_dr(r, h) / r);
    }
    /// (1/r) dW/dr, finite at r = 0 for the smooth kernels; the factor of the gradient.
    NUMERICS_HD static T gradFactor(T r, T h) { return r > T(0) ? dW_dr(r, h) / r : T(0); }
};

/// Cubic B-spline M4 (Monaghan 1992, eq. 2.6; Monaghan & Lattanzio 1985). Support 2h.
struct CubicSplineProfile {
    template <class T>
    static constexpr T supportIn() {
        return T(2);
    }
    template <class T>
    static constexpr T sigma(int dim) {
        using std::numbers::pi_v;
        return dim == 1 ? T(2) / T(3) : dim == 2 ? T(10) / (T(7) * pi_v<T>) : T(1) / pi_v<T>;
    }
    template <class T>
    NUMERICS_HD static constexpr T f(T q) {
        if (q < T(1)) return T(1) - T(1.5) * q * q + T(0.75) * q * q * q;
        const T s = T(2) - q;
        return T(0.25) * s * s * s;
    }
    template <class T>
    NUMERICS_HD static constexpr T df(T q) {
        if (q < T(1)) return -T(3) * q + T(2.25) * q * q;
        const T s = T(2) - q;
        return -T(0.75) * s * s;
    }
    /// Knots where the piecewise form changes (for continuity checks).
    static constexpr std::array<double, 1> knots{1.0};
};

/// Quintic B-spline M6 (Morris, Fox & Zhu 1997, eq. 12). Support 3h.
/// sigma = 1/120, 7/(478 pi), 1/(120 pi) in 1D, 2D, 3D: the exact values of 1 / int f.
/// (The 3D constant 3/(359 pi) found in some texts is 0.28 % too large.)
struct QuinticSplineProfile {
    template <class T>
    static constexpr T supportIn() {
        return T(3);
    }
    template <class T>
    static constexpr T sigma(int dim) {
        using std::numbers::pi_v;
        return dim == 1   ? T(1) / T(120)
               : dim == 2 ? T(7) / (T(478) * pi_v<T>)
                          : T(1) / (T(120) * pi_v<T>);
    }
    template <class T>
    NUMERICS_HD static constexpr T pow5(T x) {
        return x * x * x * x * x;
    }
    template <class T>
    NUMERICS_HD static constexpr T pow4(T x) {
        return x * x * x * x;
    }
    template <class T>
    NUMERICS_HD static constexpr T f(T q) {
        T v = pow5(T(3) - q);
        if (q < T(2)) v -= T(6) * pow5(T(2) - q);
        if (q < T(1)) v += T(15) * pow5(T(1) - q);
        return v;
    }
    template <class T>
    NUMERICS_HD static constexpr T df(T q) {
        T v = -T(5) * pow4(T(3) - q);
        if (q < T(2)) v += T(30) * pow4(T(2) - q);
        if (q < T(1)) v -= T(75) * pow4(T(1) - q);
        return v;
    }
    static constexpr std::array<double, 2> knots{1.0, 2.0};
};

/// Wendland C2 (Wendland 1995; Dehnen & Aly 2012, table 1). Support 2h.
/// 2D/3D: f = (1 - q/2)^4 (2q + 1);  1D: f = (1 - q/2)^3 (1.5q + 1).
struct WendlandC2Profile {
    template <class T>
    static constexpr T supportIn() {
        return T(2);
    }
    template <class T>
    static constexpr T sigma(int dim) {
        using std::numbers::pi_v;
        return dim == 1   ? T(5) / T(8)
               : dim == 2 ? T(7) / (T(4) * pi_v<T>)
                          : T(21) / (T(16) * pi_v<T>);
    }
};

/// Wendland C4 (Dehnen & Aly 2012, table 1). Support 2h.
/// 2D/3D: f = (1 - q/2)^6 (35/12 q^2 + 3q + 1);  1D: f = (1 - q/2)^5 (2q^2 + 2.5q + 1).
struct WendlandC4Profile {
    template <class T>
    static constexpr T supportIn() {
        return T(2);
    }
    template <class T>
    static constexpr T sigma(int dim) {
        using std::numbers::pi_v;
        return dim == 1   ? T(3) / T(4)
               : dim == 2 ? T(9) / (T(4) * pi_v<T>)
                          : T(495) / (T(256) * pi_v<T>);
    }
};

/// Spiky kernel (Desbrun & Gascuel 1996; Mueller et al. 2003): W = C (H - r)^3 with H = 2h,
/// whose slope stays non-zero at r = 0 so that the pressure gradient keeps particles apart.
/// In the h form f = (2 - q)^3, sigma = 1/8, 5/(16 pi), 15/(64 pi) in 1D, 2D, 3D.
struct SpikyProfile {
    template <class T>
    static constexpr T supportIn() {
        return T(2);
    }
    template <class T>
    static constexpr T sigma(int dim) {
        using std::numbers::pi_v;
        return dim == 1   ? T(1) / T(8)
               : dim == 2 ? T(5) / (T(16) * pi_v<T>)
                          : T(15) / (T(64) * pi_v<T>);
    }
    template <class T>
    NUMERICS_HD static constexpr T f(T q) {
        const T s = T(2) - q;
        return s * s * s;
    }
    template <class T>
    NUMERICS_HD static constexpr T df(T q) {
        const T s = T(2) - q;
        return -T(3) * s * s;
    }
    static constexpr std::array<double, 0> knots{};
};

/// Wendland shapes differ between 1D and 2D/3D; this adapter picks the right one for Dim.
template <int Dim>
struct WendlandC2DimProfile : WendlandC2Profile {
    template <class T>
    NUMERICS_HD static constexpr T f(T q) {
        const T s = T(1) - T(0.5) * q;
        if constexpr (Dim == 1)
            return s * s * s * (T(1.5) * q + T(1));
        else
            return s * s * s * s * (T(2) * q + T(1));
    }
    template <class T>
    NUMERICS_HD static constexpr T df(T q) {
        const T s = T(1) - T(0.5) * q;
        // 1D: d/dq[s^3 (1.5q+1)] = -1.5 s^2 (1.5q+1) + 1.5 s^3 = -3 q s^2
        // 2D/3D: d/dq[s^4 (2q+1)] = -2 s^3 (2q+1) + 2 s^4 = -5 q s^3
        if constexpr (Dim == 1)
            return -T(3) * q * s * s;
        else
            return -T(5) * q * s * s * s;
    }
    static constexpr std::array<double, 0> knots{};
};

template <int Dim>
struct WendlandC4DimProfile : WendlandC4Profile {
    template <class T>
    NUMERICS_HD static constexpr T f(T q) {
        const T s = T(1) - T(0.5) * q;
        if constexpr (Dim == 1) {
            return s * s * s * s * s * (T(2) * q * q + T(2.5) * q + T(1));
        } else {
            return s * s * s * s * s * s * (T(35) / T(12) * q * q + T(3) * q + T(1));
        }
    }
    template <class T>
    NUMERICS_HD static constexpr T df(T q) {
        const T s = T(1) - T(0.5) * q;
        // d/dq [s^n P(q)] = s^(n-1) (-(n/2) P(q) + s P'(q)),  s = 1 - q/2.
        if constexpr (Dim == 1) {
            return s * s * s * s *
                   (-T(2.5) * (T(2) * q * q + T(2.5) * q + T(1)) + s * (T(4) * q + T(2.5)));
        } else {
            return s * s * s * s * s *
                   (-T(3) * (T(35) / T(12) * q * q + T(3) * q + T(1)) +
                    s * (T(35) / T(6) * q + T(3)));
        }
    }
    static constexpr std::array<double, 0> knots{};
};

template <int Dim, class T = double>
using CubicSpline = RadialKernel<CubicSplineProfile, Dim, T>;
template <int Dim, class T = double>
using QuinticSpline = RadialKernel<QuinticSplineProfile, Dim, T>;
template <int Dim, class T = double>
using WendlandC2 = RadialKernel<WendlandC2DimProfile<Dim>, Dim, T>;
template <int Dim, class T = double>
using WendlandC4 = RadialKernel<WendlandC4DimProfile<Dim>, Dim, T>;
template <int Dim, class T = double>
using Spiky = RadialKernel<SpikyProfile, Dim, T>;

}  // namespace num::kernels
