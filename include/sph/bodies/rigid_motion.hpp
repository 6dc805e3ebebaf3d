// Rigid-body kinematics in 2D and 3D: the attitude (an angle in 2D, a unit quaternion in 3D),
// the spin (angular velocity: one component in 2D, three in 3D), r x F and omega x r.
// A body's particle at body-frame offset r sits at X + R r and moves at V + omega x (R r)
// (e.g. Goldstein, Classical Mechanics, ch. 4-5).
#pragma once

#include <array>
#include <cmath>

#include "sph/host_device.hpp"
#include "sph/types.hpp"

namespace num::sph {

/// Angular velocity, torque or angular momentum: the z component in 2D, three in 3D.
template <int Dim>
using Spin = Vec<Float, Dim == 2 ? 1 : 3>;

/// r x F (in 2D the z component).
NUMERICS_HD_INLINE Spin<2> cross(const Vector<2>& r, const Vector<2>& f) {
    return Spin<2>{{r[0] * f[1] - r[1] * f[0]}};
}
NUMERICS_HD_INLINE Spin<3> cross(const Vector<3>& a, const Vector<3>& b) {
    return Spin<3>{
        {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

/// omega x r: the velocity of a point at offset r of a body spinning at omega.
NUMERICS_HD_INLINE Vector<2> spinVelocity(const Spin<2>& w, const Vector<2>& r) {
    return Vector<2>{{-w[0] * r[1], w[0] * r[0]}};
}
NUMERICS_HD_INLINE Vector<3> spinVelocity(const Spin<3>& w, const Vector<3>& r) {
    return cross(w, r);
}

/// An attitude's rotation ready to apply on host and device (Attitude::orientation): 2D the
/// cosine and sine of the angle, 3D the unit quaternion.
template <int Dim>
struct Orientation;

/// 2D: R r = (c r_x - s r_y, s r_x + c r_y); R^T r = (c r_x + s r_y, -s r_x + c r_y).
template <>
struct Orientation<2> {
    Float c = 1, s = 0;
    NUMERICS_HD Vector<2> rotate(const Vector<2>& r) const {
        return Vector<2>{{c * r[0] - s * r[1], s * r[0] + c * r[1]}};
    }
    NUMERICS_HD Vector<2> rotateBack(const Vector<2>& r) const {
        return Vector<2>{{c * r[0] + s * r[1], -s * r[0] + c * r[1]}};
    }
};

/// 3D: R r = r + 2 q0 (u x r) + 2 u x (u x r), u = (q1, q2, q3); R^T r the same with -q0.
template <>
struct Orientation<3> {
    Float q[4] = {1, 0, 0, 0};
    NUMERICS_HD Vector<3> rotate(const Vector<3>& r) const { return rotated(r, q[0]); }
    NUMERICS_HD Vector<3> rotateBack(const Vector<3>& r) const { return rotated(r, -q[0]); }

  private:
    NUMERICS_HD Vector<3> rotated(const Vector<3>& r, Float q0) const {
        const Vector<3> u{{q[1], q[2], q[3]}};
        const Vector<3> t = cross(u, r) * 2.0;
        return r + t * q0 + cross(u, t);
    }
};

template <int Dim>
struct Attitude;

/// 2D: the angle turned counter-clockwise from the initial pose [rad].
template <>
struct Attitude<2> {
    Float angle = 0;

    Orientation<2> orientation() const { return {std::cos(angle), std::sin(angle)}; }
    Vector<2> rotate(const Vector<2>& r) const { return orientation().rotate(r); }
    Vector<2> rotateBack(const Vector<2>& r) const { return orientation().rotateBack(r); }
    /// Turns by omega dt.
    void turn(const Spin<2>& w, Float dt) { angle += w[0] * dt; }
    friend bool operator==(const Attitude&, const Attitude&) = default;
};

/// 3D: the unit quaternion q = (q0, q1, q2, q3) of the rotation from the initial pose.
template <>
struct Attitude<3> {
    std::array<Float, 4> q{1, 0, 0, 0};

    Orientation<3> orientation() const { return {{q[0], q[1], q[2], q[3]}}; }
    Vector<3> rotate(const Vector<3>& r) const { return orientation().rotate(r); }
    Vector<3> rotateBack(const Vector<3>& r) const { return orientation().rotateBack(r); }
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
};

}  // namespace num::sph
