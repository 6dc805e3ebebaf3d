// The moment of inertia of a rigid body about its reference point: a number in 2D (about z),
// a symmetric 3x3 tensor in 3D given in the body frame, so that in the world frame
// I_w = R I R^T and the angular momentum is L = I_w omega.
#pragma once

#include <array>

#include "sph/bodies/rigid_motion.hpp"

namespace num::sph {

template <int Dim>
struct Inertia;

template <>
struct Inertia<2> {
    Float zz = 0;

    bool positive() const { return zz > 0; }
    /// L = I omega
    Spin<2> momentum(const Spin<2>& w, const Attitude<2>&) const { return w * zz; }
    /// omega = I^-1 L
    Spin<2> spin(const Spin<2>& L, const Attitude<2>&) const { return L / zz; }
    /// I about a point at offset d from the centre of mass: I + M |d|^2 (parallel axes).
    Inertia shifted(Float mass, const Vector<2>& d) const { return {zz + mass * normSqr(d)}; }
};

template <>
struct Inertia<3> {
    std::array<Vector<3>, 3> rows{};  ///< body frame

    static Inertia diagonal(const Vector<3>& d) {
        Inertia I;
        for (int k = 0; k < 3; ++k) I.rows[k][k] = d[k];
        return I;
    }
    /// Symmetric and positive definite (Sylvester's criterion).
    bool positive() const {
        const auto& a = rows;
        const Float m1 = a[0][0], m2 = a[0][0] * a[1][1] - a[0][1] * a[1][0];
        bool symmetric = a[0][1] == a[1][0] && a[0][2] == a[2][0] && a[1][2] == a[2][1];
        return symmetric && m1 > 0 && m2 > 0 && determinant() > 0;
    }
    Spin<3> momentum(const Spin<3>& w, const Attitude<3>& q) const {
        return q.rotate(times(rows, q.rotateBack(w)));
    }
    Spin<3> spin(const Spin<3>& L, const Attitude<3>& q) const {
        return q.rotate(times(inverse(), q.rotateBack(L)));
    }
    /// I + M (|d|^2 1 - d d^T) (parallel axes), d in the body frame.
    Inertia shifted(Float mass, const Vector<3>& d) const {
        Inertia I = *this;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                I.rows[i][j] += mass * ((i == j) * normSqr(d) - d[i] * d[j]);
        return I;
    }

  private:
    static Vector<3> times(const std::array<Vector<3>, 3>& m, const Vector<3>& v) {
        return Vector<3>{{dot(m[0], v), dot(m[1], v), dot(m[2], v)}};
    }
    Float determinant() const { return dot(rows[0], cross(rows[1], rows[2])); }
    /// The inverse from the cofactors: rows of (a1 x a2, a2 x a0, a0 x a1)^T / det.
    std::array<Vector<3>, 3> inverse() const {
        const Float det = determinant();
        const std::array<Vector<3>, 3> c{cross(rows[1], rows[2]), cross(rows[2], rows[0]),
                                         cross(rows[0], rows[1])};
        std::array<Vector<3>, 3> inv{};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) inv[i][j] = c[j][i] / det;
        return inv;
    }
};

}  // namespace num::sph
