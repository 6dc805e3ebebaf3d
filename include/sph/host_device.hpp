// Functions callable on the host and on a CUDA device: one source for the physics that the CPU
// engine and the CUDA kernels both run (docs/extending.md, "Formulas on host and device").
//
//   NUMERICS_HD         __host__ __device__ under a CUDA compiler, nothing otherwise
//   NUMERICS_HD_INLINE  NUMERICS_HD inline, for free functions in headers
//
// Code marked NUMERICS_HD calls no std:: function that has no device version: num::hd below
// wraps the C library's (global namespace) functions, which both glibc and CUDA provide, and
// min / max written as std::min / std::max are, so that NaN and signed zeros come out alike.
// Whole powers are written as products (x * x * x), never pow(x, 3). With those, +, -, *, /
// and sqrt round alike on host and device (IEEE, correctly rounded) provided neither side fuses
// multiply-adds: the host build has -ffp-contract=off (cmake/numericsArch.cmake), device code
// needs nvcc -fmad=false. exp and pow are not correctly rounded: the device's may differ from
// glibc's in the last place (the Tait inverse rho(p), the viscosity of temperature, the local
// spacing of particle shifting).
#pragma once

#include <cmath>

#ifdef __CUDACC__
#define NUMERICS_HD __host__ __device__
#else
#define NUMERICS_HD
#endif
#define NUMERICS_HD_INLINE NUMERICS_HD inline

namespace num::hd {

NUMERICS_HD_INLINE double sqrt(double x) { return ::sqrt(x); }
NUMERICS_HD_INLINE double exp(double x) { return ::exp(x); }
NUMERICS_HD_INLINE double pow(double x, double y) { return ::pow(x, y); }
NUMERICS_HD_INLINE double floor(double x) { return ::floor(x); }
NUMERICS_HD_INLINE double fmod(double x, double y) { return ::fmod(x, y); }

/// std::min's definition: b if b < a, else a (the first argument when unordered).
template <class T>
NUMERICS_HD constexpr T min(const T& a, const T& b) {
    return (b < a) ? b : a;
}
/// std::max's definition: b if a < b, else a.
template <class T>
NUMERICS_HD constexpr T max(const T& a, const T& b) {
    return (a < b) ? b : a;
}

}  // namespace num::hd
