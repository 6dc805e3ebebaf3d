// Rigid-body kinematics in 2D and 3D: the attitude (an angle in 2D, a unit quaternion in 3D),
// the spin (angular velocity: one component in 2D, three in 3D), r x F and omega x r.
// A body's particle at body-frame offset r sits at X + R r and moves at V + omega x (R r)
// (e.g. Goldstein, Classical Mechanics, ch. 4-5).
#pragma once

#include <array>
#include <cmath>

#include "sph/types.hpp"

namespace num::sph {

/// Angular velocity, torque or angular momentum: the z component in 2D, three in 3D.
template <int Dim>
using Spin = Vec<Float, Dim == 2 ? 1 : 3>;

/// r x F (in 2D the z component).
inline Spin<2> cross(const Vector<2>& r, const Vector<2>& f) {
    return Spin<2>{{r[0] * f[1] - r[1] * f[0]}};
}
inline Spin<3> cross(const Vector<3>& a, const Vector<3>& b) {
    return Spin<3>{
        {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

/// omega x r: the velocity of a point at offset r of a body spinning at omega.
inline Vector<2> spinVelocity(const Spin<2>& w, const Vector<2>& r) {
    return Vector<2>{{-w[0] * r[1], w[0] * r[0]}};
}
inline Vector<3> spinVelocity(const Spin<3>& w, const Vector<3>& r) { return cross(w, r); }

template <int Dim>
struct Attitude;

/// 2D: the angle turned counter-clockwise from the initial pose [rad].
template <>
struct Attitude<2> {
    Float angle = 0;

    Vector<2> rotate(const Vector<2>& r) const {
        const Float c = std::cos(angle), s = std::sin(angle);
        return Vector<2>{{c * r[0] - s * r[1], s * r[0] + c * r[1]}};
    }
    Vector<2> rotateBack(const Vector<2>& r) const {
        const Float c = std::cos(angle), s = std::sin(angle);
        return Vector<2>{{c * r[0] + s * r[1], -s * r[0] + c * r[1]}};
    }
    /// Turns by omega dt.
    void turn(const Spin<2>& w, Float dt) { angle += w[0] * dt; }
    friend bool operator==(const Attitude&, const Attitude&) = default;
};

/// 3D: the unit quaternion q = (q0, q1, q2, q3) of the rotation from the initial pose.
template <>
struct Attitude<3> {
    std::array<Float, 4> q{1, 0, 0, 0};

    /// R r = r + 2 q0 (u x r) + 2 u x (u x r), u = (q1, q2, q3).
    Vector<3> rotate(const Vector<3>& r) const { return rotated(r, q[0]); }
    /// R^T r: the same with the conjugate quaternion.
    Vector<3> rotateBack(const Vector<3>& r) const { return rotated(r, -q[0]); }
    /// Turns by the rotation vector omega dt (q <- exp(omega dt / 2) q, renormalised).
    void turn(const Spin<3>& w, Float dt) {
        const Float angle = norm(w) * dt;
        if (angle == 0) return;
        const Vector<3> axis = w / norm(w);
        const Float c = std::cos(angle / 2), s = std::sin(angle / 2);
        const std::array<Float, 4> d{c, s * axis[0], s * axis[1], s * axis[2]};
        std::array<Float, 4> n{d[0] * q[0] - d[1] * q[1] - d[2] * q[2] - d[3] * q[3],
                               d[0] * q[1] + d[1] * q[0] + d[2] * q[3] - d[3] * q[2],
                               d[0] * q[2] - d[1] * q[3] + d[2] * q[0] + d[3] * q[1],
                               d[0] * q[3] + d[1] * q[2] - d[2] * q[1] + d[3] * q[0]};
        const Float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] + n[3] * n[3]);
        for (Float& c4 : n) c4 /= length;
        q = n;
    }
    friend bool operator==(const Attitude&, const Attitude&) = default;

  private:
    Vector<3> rotated(const Vector<3>& r, Float q0) const {
        const Vector<3> u{{q[1], q[2], q[3]}};
        const Vector<3> t = cross(u, r) * 2.0;
        return r + t * q0 + cross(u, t);
    }
};

}  // namespace num::sph
