// Rotations given by angles in degrees: one angle (counter-clockwise) in 2D; in 3D about x, then
// y, then z, each about the fixed axes (R = Rz Ry Rx).
#pragma once

#include <array>
#include <cmath>
#include <numbers>

#include "geometry/solid.hpp"

namespace num::geometry {

/// The angles of a rotation in degrees: one in 2D, three (about x, y, z) in 3D.
template <int Dim>
using Angles = Vec<double, Dim == 2 ? 1 : 3>;

template <int Dim>
class Rotation {
  public:
    /// The identity.
    Rotation() {
        for (int i = 0; i < Dim; ++i) rows_[i][i] = 1;
    }
    explicit Rotation(const Angles<Dim>& degrees);

    /// R x
    Point<Dim> apply(const Point<Dim>& x) const {
        Point<Dim> r;
        for (int i = 0; i < Dim; ++i) r[i] = dot(rows_[i], x);
        return r;
    }
    /// R^T x (the inverse rotation)
    Point<Dim> applyInverse(const Point<Dim>& x) const {
        Point<Dim> r{};
        for (int i = 0; i < Dim; ++i) r += rows_[i] * x[i];
        return r;
    }
    /// The matrix R by rows.
    const Rows<Dim>& rows() const { return rows_; }
    bool isIdentity() const { return *this == Rotation(); }
    friend bool operator==(const Rotation&, const Rotation&) = default;

  private:
    Rows<Dim> rows_{};
};

namespace detail {
inline double radians(double degrees) { return degrees * std::numbers::pi / 180; }
}  // namespace detail

template <>
inline Rotation<2>::Rotation(const Angles<2>& degrees) {
    const double c = std::cos(detail::radians(degrees[0])),
                 s = std::sin(detail::radians(degrees[0]));
    rows_ = {Point<2>{{c, -s}}, Point<2>{{s, c}}};
}

template <>
inline Rotation<3>::Rotation(const Angles<3>& degrees) {
    double c[3], s[3];
    for (int k = 0; k < 3; ++k)
        c[k] = std::cos(detail::radians(degrees[k])), s[k] = std::sin(detail::radians(degrees[k]));
    // Rz(c2, s2) Ry(c1, s1) Rx(c0, s0)
    rows_ = {
        Point<3>{{c[2] * c[1], c[2] * s[1] * s[0] - s[2] * c[0], c[2] * s[1] * c[0] + s[2] * s[0]}},
        Point<3>{{s[2] * c[1], s[2] * s[1] * s[0] + c[2] * c[0], s[2] * s[1] * c[0] - c[2] * s[0]}},
        Point<3>{{-s[1], c[1] * s[0], c[1] * c[0]}}};
}

}  // namespace num::geometry
