// Volume, centroid and second moment of a solid of unit density, as rigid bodies need them: the
// exact values of the simple shapes, and their change when a solid is scaled, rotated and moved.
// Solids offer theirs through Solid::massProperties (solid.hpp).
#pragma once

#include <array>
#include <cmath>
#include <numbers>
#include <type_traits>

#include "spatial/vec.hpp"

namespace num::geometry {

/// A Dim x Dim matrix by rows (a rotation; the 3D inertia). Its size is a std::size_t, so
/// functions taking one deduce Dim from their other arguments.
template <int Dim>
using Rows = std::array<Vec<double, Dim>, Dim>;

/// Per unit density, about the centroid: 2D the polar moment J = integral |r|^2 dA (a number);
/// 3D the inertia tensor integral (|r|^2 1 - r r^T) dV (symmetric, by rows).
template <int Dim>
using SecondMoment = std::conditional_t<Dim == 2, double, Rows<3>>;

template <int Dim>
struct MassProperties {
    double volume = 0;  ///< 2D: the area
    Vec<double, Dim> centroid{};
    SecondMoment<Dim> inertia{};
};

namespace detail {

/// R x
template <int Dim>
Vec<double, Dim> times(const std::type_identity_t<Rows<Dim>>& R, const Vec<double, Dim>& x) {
    Vec<double, Dim> r;
    for (int i = 0; i < Dim; ++i) r[i] = dot(R[i], x);
    return r;
}

/// R I R^T, its lower triangle copied from the upper one so that it stays exactly symmetric.
inline Rows<3> rotatedTensor(const Rows<3>& I, const Rows<3>& R) {
    Rows<3> out{};
    for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j) {
            for (int k = 0; k < 3; ++k) out[i][j] += R[i][k] * dot(I[k], R[j]);
            out[j][i] = out[i][j];
        }
    return out;
}

}  // namespace detail

/// The properties of the image x' = t + R (s x) of a solid: volume s^Dim V, centroid
/// t + R (s c), inertia s^(Dim+2) R I R^T (2D: s^4 J, which a rotation leaves unchanged).
template <int Dim>
MassProperties<Dim> transformed(const MassProperties<Dim>& p, double s,
                                const std::type_identity_t<Rows<Dim>>& R,
                                const Vec<double, Dim>& t) {
    MassProperties<Dim> out;
    out.volume = std::pow(s, Dim) * p.volume;
    out.centroid = t + detail::times(R, p.centroid * s);
    if constexpr (Dim == 2) {
        out.inertia = std::pow(s, 4) * p.inertia;
    } else {
        out.inertia = detail::rotatedTensor(p.inertia, R);
        for (auto& row : out.inertia) row *= std::pow(s, 5);
    }
    return out;
}

/// A box of edges e = hi - lo: I_xx = V (e_y^2 + e_z^2) / 12 and so on (2D: J = A |e|^2 / 12).
template <int Dim>
MassProperties<Dim> boxMassProperties(const Vec<double, Dim>& lo, const Vec<double, Dim>& hi) {
    MassProperties<Dim> m;
    const Vec<double, Dim> e = hi - lo;
    m.volume = 1;
    for (int k = 0; k < Dim; ++k) m.volume *= e[k];
    m.centroid = (lo + hi) * 0.5;
    if constexpr (Dim == 2) {
        m.inertia = m.volume * normSqr(e) / 12;
    } else {
        for (int k = 0; k < 3; ++k) m.inertia[k][k] = m.volume * (normSqr(e) - e[k] * e[k]) / 12;
    }
    return m;
}

/// A disc (J = A r^2 / 2) or a sphere (I = 2/5 V r^2 on the diagonal).
template <int Dim>
MassProperties<Dim> ballMassProperties(const Vec<double, Dim>& center, double r) {
    MassProperties<Dim> m;
    m.centroid = center;
    if constexpr (Dim == 2) {
        m.volume = std::numbers::pi * r * r;
        m.inertia = m.volume * r * r / 2;
    } else {
        m.volume = 4 * std::numbers::pi * r * r * r / 3;
        for (int k = 0; k < 3; ++k) m.inertia[k][k] = 0.4 * m.volume * r * r;
    }
    return m;
}

}  // namespace num::geometry
