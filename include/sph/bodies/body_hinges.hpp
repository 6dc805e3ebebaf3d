// Hinges between two bodies, held by impulses on the bodies' velocities (a velocity-level joint,
// as in sequential-impulse rigid-body solvers: Catto 2005, "Iterative dynamics with temporal
// coherence"). After the free bodies' velocities have been advanced and before the bodies move,
// each hinge gets the impulse P at its pin (+P on the hinged body A, -P on its holder B) that
// makes the pin's two material points move alike:
//   K P = -(u + beta C / dt),  u = v_A(p) - v_B(p),  C = x_A(p) - x_B(p),
// K the change of u per unit impulse, from each body's mass, inertia, own hinge and held degrees
// of freedom (a fixed or prescribed body does not give way). In 3D an angular impulse L
// perpendicular to the axis a_A keeps the two bodies' axes together:
//   (omega_A - omega_B) . e_i = (beta / dt) (a_A x a_B) . e_i,  e_1, e_2 perpendicular to a_A.
// beta = 0.2 (Baumgarte) brings the drift of the explicit step back; the hinges are swept 10
// times in their order (Gauss-Seidel), so that chains of hinged bodies hold.
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "sph/bodies/rigid_body.hpp"

namespace num::sph {

/// Body `body` turns on body `holder` about a pin (3D: and an axis).
template <int Dim>
struct BodyHinge {
    int body = -1, holder = -1;
    Vector<Dim> point{}, holderPoint{};  ///< the pin: body-frame offsets from each reference point
    Spin<Dim> axis{}, holderAxis{};      ///< 3D: the hinge's axis in each body frame
};

/// A body's velocity and spin over the step (what it moves with).
template <int Dim>
struct StepMotion {
    Vector<Dim> velocity{};
    Spin<Dim> spin{};
};

/// The change of a body's step motion from an impulse P at world offset d from its reference
/// point and an angular impulse L; none for a body that is not free.
template <int Dim>
StepMotion<Dim> kick(const BodyMotion<Dim>& m, const BodyState<Dim>& s, const Vector<Dim>& d,
                     const Vector<Dim>& P, const Spin<Dim>& L) {
    if (m.type != MotionType::FREE) return {};
    const Spin<Dim> turn = cross(d, P) + L;
    if (m.hinged) {
        const Spin<Dim>& a = m.hingeAxis;
        return {Vector<Dim>{}, a * (dot(turn, a) / dot(a, m.inertia.momentum(a, s.attitude)))};
    }
    StepMotion<Dim> k{P / m.mass, m.inertia.spin(turn, s.attitude)};
    for (int i = 0; i < Dim; ++i)
        if (m.heldAxes[std::size_t(i)]) k.velocity[i] = 0;
    for (std::size_t i = 0; i < m.heldSpins.size(); ++i)
        if (m.heldSpins[i]) k.spin[int(i)] = 0;
    return k;
}

namespace detail {

/// x with K x = b (N <= 3, partial pivoting); a direction in which neither body can give way
/// (a pivot below 1e-12 of K's largest entry) gets no impulse.
template <int N>
std::array<Float, N> solveSmall(std::array<std::array<Float, N>, N> K, std::array<Float, N> b) {
    Float largest = 0;
    for (const auto& row : K)
        for (Float v : row) largest = std::max(largest, std::abs(v));
    std::array<bool, N> free{};
    for (int c = 0; c < N; ++c) {
        int p = c;
        for (int r = c + 1; r < N; ++r)
            if (std::abs(K[r][c]) > std::abs(K[p][c])) p = r;
        std::swap(K[c], K[p]), std::swap(b[c], b[p]);
        free[c] = std::abs(K[c][c]) > 1e-12 * largest;
        if (!free[c]) continue;
        for (int r = c + 1; r < N; ++r) {
            const Float f = K[r][c] / K[c][c];
            for (int k = c; k < N; ++k) K[r][k] -= f * K[c][k];
            b[r] -= f * b[c];
        }
    }
    std::array<Float, N> x{};
    for (int c = N - 1; c >= 0; --c) {
        if (!free[c]) continue;
        Float sum = b[c];
        for (int k = c + 1; k < N; ++k) sum -= K[c][k] * x[k];
        x[c] = sum / K[c][c];
    }
    return x;
}

constexpr Float kHingeBeta = 0.2;
constexpr int kHingeSweeps = 10;

template <int Dim>
Vector<Dim> pointVelocity(const StepMotion<Dim>& m, const Vector<Dim>& d) {
    return m.velocity + spinVelocity(m.spin, d);
}

template <int Dim>
void add(StepMotion<Dim>& to, const StepMotion<Dim>& k, Float sign) {
    to.velocity += k.velocity * sign, to.spin += k.spin * sign;
}

/// The pin's impulse of hinge h (the file comment).
template <int Dim, class Body>
void holdPin(const BodyHinge<Dim>& h, const Body& A, const Body& B, StepMotion<Dim>& a,
             StepMotion<Dim>& b, Float dt) {
    const Vector<Dim> dA = A.state.offset(h.point), dB = B.state.offset(h.holderPoint);
    const Vector<Dim> gap = A.state.position + dA - B.state.position - dB;
    const Vector<Dim> u = pointVelocity(a, dA) - pointVelocity(b, dB);
    std::array<std::array<Float, Dim>, Dim> K{};
    std::array<Float, Dim> rhs{};
    for (int j = 0; j < Dim; ++j) {
        Vector<Dim> e{};
        e[j] = 1;
        const Vector<Dim> column = pointVelocity(kick(A.motion, A.state, dA, e, Spin<Dim>{}), dA) +
                                   pointVelocity(kick(B.motion, B.state, dB, e, Spin<Dim>{}), dB);
        for (int i = 0; i < Dim; ++i) K[i][j] = column[i];
        rhs[j] = -(u[j] + kHingeBeta * gap[j] / dt);
    }
    const std::array<Float, Dim> x = solveSmall<Dim>(K, rhs);
    Vector<Dim> P;
    for (int k = 0; k < Dim; ++k) P[k] = x[k];
    add(a, kick(A.motion, A.state, dA, P, Spin<Dim>{}), 1);
    add(b, kick(B.motion, B.state, dB, P, Spin<Dim>{}), -1);
}

/// Two unit vectors perpendicular to the unit vector a and to each other.
inline std::array<Vector<3>, 2> perpendiculars(const Vector<3>& a) {
    const Vector<3> other = std::abs(a[0]) < 0.6 ? Vector<3>{{1, 0, 0}} : Vector<3>{{0, 1, 0}};
    const Vector<3> e1 = cross(a, other) / norm(cross(a, other));
    return {e1, cross(a, e1)};
}

/// The angular impulse that keeps hinge h's two axes together (3D; the file comment).
template <class Body>
void holdAxis(const BodyHinge<3>& h, const Body& A, const Body& B, StepMotion<3>& a,
              StepMotion<3>& b, Float dt) {
    const Vector<3> axisA = A.state.attitude.rotate(h.axis);
    const Vector<3> tilt = cross(axisA, B.state.attitude.rotate(h.holderAxis));
    const std::array<Vector<3>, 2> e = perpendiculars(axisA);
    std::array<std::array<Float, 2>, 2> K{};
    std::array<Float, 2> rhs{};
    for (int j = 0; j < 2; ++j) {
        const Spin<3> column = kick(A.motion, A.state, Vector<3>{}, Vector<3>{}, e[j]).spin +
                               kick(B.motion, B.state, Vector<3>{}, Vector<3>{}, e[j]).spin;
        for (int i = 0; i < 2; ++i) K[i][j] = dot(e[i], column);
        rhs[j] = kHingeBeta / dt * dot(tilt, e[j]) - dot(a.spin - b.spin, e[j]);
    }
    const std::array<Float, 2> x = solveSmall<2>(K, rhs);
    const Spin<3> L = e[0] * x[0] + e[1] * x[1];
    add(a, kick(A.motion, A.state, Vector<3>{}, Vector<3>{}, L), 1);
    add(b, kick(B.motion, B.state, Vector<3>{}, Vector<3>{}, L), -1);
}

}  // namespace detail

/// Corrects the step motions of the bodies (indexed as `bodies`, each with .motion and .state at
/// the step's start) so that every hinge holds (the file comment).
template <int Dim, class Bodies>
void holdHinges(const std::vector<BodyHinge<Dim>>& hinges, const Bodies& bodies,
                std::vector<StepMotion<Dim>>& step, Float dt) {
    for (int sweep = 0; sweep < detail::kHingeSweeps; ++sweep)
        for (const BodyHinge<Dim>& h : hinges) {
            const auto &A = bodies[std::size_t(h.body)], &B = bodies[std::size_t(h.holder)];
            StepMotion<Dim>&a = step[std::size_t(h.body)], &b = step[std::size_t(h.holder)];
            detail::holdPin(h, A, B, a, b, dt);
            if constexpr (Dim == 3) detail::holdAxis(h, A, B, a, b, dt);
        }
}

}  // namespace num::sph
