// A small fixed-size vector, written once for every dimension; callable on host and device
// (sph/host_device.hpp).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "sph/host_device.hpp"

namespace num {

/// Vec<T, Dim>: an aggregate of Dim components with the arithmetic SPH needs.
template <class T, int Dim>
struct Vec {
    static_assert(Dim >= 1 && Dim <= 3, "Dim must be 1, 2 or 3");
    std::array<T, Dim> c{};

    NUMERICS_HD constexpr T& operator[](int k) { return c[k]; }
    NUMERICS_HD constexpr const T& operator[](int k) const { return c[k]; }
    static constexpr int dim = Dim;

    NUMERICS_HD static constexpr Vec zero() { return Vec{}; }
    NUMERICS_HD static constexpr Vec filled(T v) {
        Vec r;
        for (int k = 0; k < Dim; ++k) r.c[k] = v;
        return r;
    }

    NUMERICS_HD constexpr Vec& operator+=(const Vec& o) {
        for (int k = 0; k < Dim; ++k) c[k] += o.c[k];
        return *this;
    }
    NUMERICS_HD constexpr Vec& operator-=(const Vec& o) {
        for (int k = 0; k < Dim; ++k) c[k] -= o.c[k];
        return *this;
    }
    NUMERICS_HD constexpr Vec& operator*=(T s) {
        for (int k = 0; k < Dim; ++k) c[k] *= s;
        return *this;
    }
    NUMERICS_HD constexpr Vec& operator/=(T s) {
        for (int k = 0; k < Dim; ++k) c[k] /= s;
        return *this;
    }
    friend NUMERICS_HD constexpr Vec operator+(Vec a, const Vec& b) { return a += b; }
    friend NUMERICS_HD constexpr Vec operator-(Vec a, const Vec& b) { return a -= b; }
    friend NUMERICS_HD constexpr Vec operator*(Vec a, T s) { return a *= s; }
    friend NUMERICS_HD constexpr Vec operator*(T s, Vec a) { return a *= s; }
    friend NUMERICS_HD constexpr Vec operator/(Vec a, T s) { return a /= s; }
    friend NUMERICS_HD constexpr Vec operator-(Vec a) {
        for (int k = 0; k < Dim; ++k) a.c[k] = -a.c[k];
        return a;
    }
    friend constexpr bool operator==(const Vec& a, const Vec& b) = default;
};

template <class T, int Dim>
NUMERICS_HD constexpr T dot(const Vec<T, Dim>& a, const Vec<T, Dim>& b) {
    T s = 0;
    for (int k = 0; k < Dim; ++k) s += a.c[k] * b.c[k];
    return s;
}

template <class T, int Dim>
NUMERICS_HD constexpr T normSqr(const Vec<T, Dim>& a) {
    return dot(a, a);
}

template <class T, int Dim>
NUMERICS_HD T norm(const Vec<T, Dim>& a) {
    return hd::sqrt(normSqr(a));
}

}  // namespace num
