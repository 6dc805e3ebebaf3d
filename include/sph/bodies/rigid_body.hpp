// A rigid body's motion: how it moves (fixed, free, prescribed), its mass properties, held
// degrees of freedom, hinge and springs; its state; and one step of its equations of motion
// (hinges between two bodies: body_hinges.hpp).
//
// Free body (Newton-Euler, integrated by symplectic Euler with the fluid's force of the step's
// last evaluation; a hinged body turns about the hinge, whose point is its reference point):
//   M dV/dt = F_fluid + M g + sum F_spring
//   d(I_w omega)/dt = tau  (world frame: I_w domega/dt = tau - omega x I_w omega),
//   tau = sum (x_k - X) x F_k about the reference point X (the centre of mass unless hinged);
//   a hinge about the unit axis a: I_a domega_a/dt = tau . a, I_a = a^T I_w a (2D: a = z).
// Spring or mooring line from the anchor A (a world point, or a point of another body) to the
// body point P (Hooke's law with damping):
//   F = -[k (l - L0) + c ((v_P - v_A) . e)] e,  e = (P - A) / l; a mooring line (slack) pulls
//   only when l > L0; a body that holds the anchor is pulled by -F at A.
// Prescribed body: V(t) and omega(t) given; X and the attitude advance with the mid-step
// velocities, so that a constant velocity travels exactly V t.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "sph/bodies/inertia.hpp"

namespace num::sph {

enum class MotionType { FIXED, FREE, PRESCRIBED };

template <int Dim>
struct BodySpring {
    Vector<Dim> anchor{};  ///< world point; with anchorBody, its body-frame offset on that body
    Vector<Dim> point{};   ///< body-frame offset of the attachment from the reference point
    int anchorBody = -1;   ///< the body that holds the anchor; -1: the world
    Float stiffness = 0, restLength = 0, damping = 0;
    bool slack = false;  ///< a mooring line: no force while shorter than restLength
};

template <int Dim>
struct BodyMotion {
    MotionType type = MotionType::FIXED;
    Float mass = 0;
    Inertia<Dim> inertia;              ///< about the reference point, body frame
    Vector<Dim> centerOfMass{};        ///< body-frame offset from the reference point (hinge)
    std::array<bool, Dim> heldAxes{};  ///< translations held at zero
    std::array<bool, Dim == 2 ? 1 : 3> heldSpins{};  ///< world spin components held
    bool hinged = false;                             ///< turns about the reference point
    Spin<Dim> hingeAxis = unitHingeAxis();           ///< unit axis (2D: z)
    std::function<Vector<Dim>(Float)> velocity;      ///< prescribed V(t)
    std::function<Spin<Dim>(Float)> spin;            ///< prescribed omega(t)
    std::vector<BodySpring<Dim>> springs;
    Float friction = 0.3;  ///< Coulomb coefficient of its contacts (body_coupling.hpp)

    bool moves() const { return type != MotionType::FIXED; }

  private:
    static Spin<Dim> unitHingeAxis() {
        Spin<Dim> a{};
        a[Dim == 2 ? 0 : 2] = 1;
        return a;
    }
};

template <int Dim>
struct BodyState {
    Vector<Dim> position{};  ///< the reference point X
    Vector<Dim> velocity{};
    Attitude<Dim> attitude;
    Spin<Dim> spin{};

    /// World offset of a body-frame offset r.
    Vector<Dim> offset(const Vector<Dim>& r) const { return attitude.rotate(r); }
    /// Velocity of the body's material point at world offset d from X.
    NUMERICS_HD Vector<Dim> velocityAt(const Vector<Dim>& d) const {
        return velocity + spinVelocity(spin, d);
    }
    friend bool operator==(const BodyState&, const BodyState&) = default;
};

/// omega x L (zero in 2D, where both are along z).
inline Spin<2> crossSpin(const Spin<2>&, const Spin<2>&) { return Spin<2>{}; }
inline Spin<3> crossSpin(const Spin<3>& a, const Spin<3>& b) { return cross(a, b); }

/// A force on a body and the offset from its reference point X of the point where it acts.
template <int Dim>
struct Pull {
    Vector<Dim> arm{}, force{};
};

/// The pull of spring k on its body (state s) from the anchor at A moving at vA (the file
/// comment); none while a mooring line is slack.
template <int Dim>
std::optional<Pull<Dim>> springPull(const BodySpring<Dim>& k, const BodyState<Dim>& s,
                                    const Vector<Dim>& A, const Vector<Dim>& vA) {
    const Vector<Dim> d = s.offset(k.point), stretch = s.position + d - A;
    const Float length = norm(stretch);
    if (length == 0 || (k.slack && length <= k.restLength)) return std::nullopt;
    const Vector<Dim> e = stretch / length;
    const Float tension =
        k.stiffness * (length - k.restLength) + k.damping * dot(s.velocityAt(d) - vA, e);
    return Pull<Dim>{d, -(e * tension)};
}

/// omega after dt under torque tau, for a free body (held components zero) or a hinged one.
template <int Dim>
Spin<Dim> nextSpin(const BodyMotion<Dim>& m, const BodyState<Dim>& s, const Spin<Dim>& torque,
                   Float dt) {
    if (m.hinged) {
        const Spin<Dim>& a = m.hingeAxis;
        const Float Ia = dot(a, m.inertia.momentum(a, s.attitude));
        return a * (dot(s.spin, a) + dt * dot(torque, a) / Ia);
    }
    const Spin<Dim> L = m.inertia.momentum(s.spin, s.attitude);
    Spin<Dim> w = s.spin + m.inertia.spin(torque - crossSpin(s.spin, L), s.attitude) * dt;
    for (std::size_t k = 0; k < m.heldSpins.size(); ++k)
        if (m.heldSpins[k]) w[int(k)] = 0;
    return w;
}

/// The velocity and spin of a free body after dt under the fluid's force and torque (about X),
/// gravity g and the springs' pulls (the first half of a symplectic Euler step).
template <int Dim>
void accelerateFree(const BodyMotion<Dim>& m, BodyState<Dim>& s, Vector<Dim> force,
                    Spin<Dim> torque, const Vector<Dim>& g, Float dt,
                    std::span<const Pull<Dim>> pulls = {}) {
    force += g * m.mass;
    torque += cross(s.offset(m.centerOfMass), g * m.mass);
    for (const Pull<Dim>& p : pulls) force += p.force, torque += cross(p.arm, p.force);
    if (m.hinged) {
        s.velocity = Vector<Dim>{};
    } else {
        s.velocity += force * (dt / m.mass);
        for (int k = 0; k < Dim; ++k)
            if (m.heldAxes[k]) s.velocity[k] = 0;
    }
    s.spin = nextSpin(m, s, torque, dt);
}

/// Moves a free body by its (new) velocity and spin over dt (the second half).
template <int Dim>
void moveFree(BodyState<Dim>& s, Float dt) {
    s.position += s.velocity * dt;
    s.attitude.turn(s.spin, dt);
}

/// One step dt of a free body on its own: accelerateFree, then moveFree.
template <int Dim>
void advanceFree(const BodyMotion<Dim>& m, BodyState<Dim>& s, const Vector<Dim>& force,
                 const Spin<Dim>& torque, const Vector<Dim>& g, Float dt,
                 std::span<const Pull<Dim>> pulls = {}) {
    accelerateFree(m, s, force, torque, g, dt, pulls);
    moveFree(s, dt);
}

/// One step from t - dt to t of a prescribed body.
template <int Dim>
void advancePrescribed(const BodyMotion<Dim>& m, BodyState<Dim>& s, Float t, Float dt) {
    const Float middle = t - dt / 2;
    s.position += m.velocity(middle) * dt;
    s.attitude.turn(m.spin(middle), dt);
    s.velocity = m.velocity(t), s.spin = m.spin(t);
}

}  // namespace num::sph
