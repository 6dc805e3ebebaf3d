// num::SPHKernel<Dim>: the seed kernel API of numerics 0.1.0, in float, exactly as documented.
//
//   W            cubic spline density kernel, support 2h, sigma = 10/(7 pi h^2) (2D), 1/(pi h^3)
//   (3D) dW_dr        its radial derivative (<= 0) Spiky_dW_dr  spiky kernel slope: -15/(16 pi h^5)
//   (2h-r)^2 (2D), -45/(pi (2h)^6) (2h-r)^2 (3D) Spiky_gradW  (dW/dr / r) r_vec, for the pressure
//   gradient
//
// Which derivative the Morris et al. (1997) Laplacian uses: the seed's formula and table say the
// cubic spline's dW_dr, while its usage snippet wrote Spiky_dW_dr. We follow the formula:
//     lap(A)_i = sum_j (m_j / rho_j) 2 (A_i - A_j) r_ij dW_dr(r_ij, h) / (r_ij^2 + eps^2)
// with the smooth kernel's dW_dr. The spiky slope does not vanish at r = 0 and overweights
// close pairs, which makes viscosity and heat conduction too strong.
//
// The double-precision kernel family lives in spatial/kernels.hpp; this header keeps the seed's
// float signatures for the apps' wrappers.
#pragma once

#include <array>
#include <cmath>
#include <numbers>

namespace num {
namespace detail {

/// Normalisation of the cubic spline: W = CubicSigma<Dim>::value(h) * f(q).
template <int Dim>
struct CubicSigma;
template <>
struct CubicSigma<2> {
    static float value(float h) { return 10.0f / (7.0f * std::numbers::pi_v<float> * h * h); }
};
template <>
struct CubicSigma<3> {
    static float value(float h) { return 1.0f / (std::numbers::pi_v<float> * h * h * h); }
};

/// Coefficient of the spiky slope: dW/dr = -SpikyDW<Dim>::coefficient(h) (2h - r)^2.
template <int Dim>
struct SpikyDW;
template <>
struct SpikyDW<2> {
    static float coefficient(float h) {
        return 15.0f / (16.0f * std::numbers::pi_v<float> * h * h * h * h * h);
    }
};
template <>
struct SpikyDW<3> {
    static float coefficient(float h) {
        const float H = 2.0f * h;
        return 45.0f / (std::numbers::pi_v<float> * H * H * H * H * H * H);
    }
};

}  // namespace detail

/// Dimension-generic SPH smoothing kernels, Dim = 2 or 3. All functions are static.
template <int Dim>
struct SPHKernel {
    static_assert(Dim == 2 || Dim == 3, "SPHKernel is defined for Dim = 2 and 3");

    /// Cubic spline density kernel. Support = 2h.
    static float W(float r, float h) {
        const float q = r / h;
        const float sigma = detail::CubicSigma<Dim>::value(h);
        if (q <= 1.0f) return sigma * (1.0f - 1.5f * q * q + 0.75f * q * q * q);
        if (q <= 2.0f) {
            const float s = 2.0f - q;
            return sigma * 0.25f * s * s * s;
        }
        return 0.0f;
    }

    /// Radial derivative dW/dr of the cubic spline (<= 0); used by the Morris Laplacian.
    static float dW_dr(float r, float h) {
        const float q = r / h;
        const float sigma = detail::CubicSigma<Dim>::value(h);
        if (q <= 1.0f) return sigma / h * (-3.0f * q + 2.25f * q * q);
        if (q <= 2.0f) {
            const float s = 2.0f - q;
            return sigma / h * (-0.75f * s * s);
        }
        return 0.0f;
    }

    /// Radial derivative dW/dr of the spiky kernel (<= 0, non-zero at r = 0).
    static float Spiky_dW_dr(float r, float h) {
        const float s = 2.0f * h - r;
        if (s <= 0.0f) return 0.0f;
        return -detail::SpikyDW<Dim>::coefficient(h) * s * s;
    }

    /// Spiky gradient (dW/dr / r) r_vec; zero at r = 0, where the direction is undefined.
    static std::array<float, Dim> Spiky_gradW(std::array<float, Dim> r_vec, float r, float h) {
        std::array<float, Dim> g{};
        if (r <= 0.0f) return g;
        const float f = Spiky_dW_dr(r, h) / r;
        for (int k = 0; k < Dim; ++k) g[k] = f * r_vec[k];
        return g;
    }
};

}  // namespace num
