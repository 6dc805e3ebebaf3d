// A moving body's frame as plain data for host and device: its state (rigid_body.hpp), its
// rotation ready to apply (rigid_motion.hpp's Orientation) and its reference point at t = 0.
// The two uses of the frame the CPU engine (body_coupling.hpp, particle_containment.hpp) and the
// device step (device/body_step.hpp) share:
//   placing a body particle of body-frame offset r:  x = X + R r,  v = V + omega x (R r);
//   keeping a point out of the body's solid, given in its initial pose: the point and its
//   velocity relative to the body's taken to that pose, x0 = X0 + R^T (x - X),
//   v0 = R^T (v - v_b(x)), reflected there (formulas::containOutsideBody), and back:
//   x = X + R (x0 - X0), v = v_b(x) + R v0.
#pragma once

#include "sph/bodies/rigid_body.hpp"
#include "sph/host_device.hpp"

namespace num::sph {

template <int Dim>
struct BodyFrame {
    BodyState<Dim> state;
    Orientation<Dim> orientation;
    Vector<Dim> initialPosition{};  ///< X0, the reference point at t = 0

    /// The frame of a body at `state` whose reference point was X0 at t = 0.
    static BodyFrame of(const BodyState<Dim>& state, const Vector<Dim>& X0) {
        return {state, state.attitude.orientation(), X0};
    }
    /// The point of the initial pose that is at x now: X0 + R^T (x - X).
    NUMERICS_HD Vector<Dim> toInitialPose(const Vector<Dim>& x) const {
        return initialPosition + orientation.rotateBack(x - state.position);
    }
    /// The velocity of the body's material point at x.
    NUMERICS_HD Vector<Dim> velocityAt(const Vector<Dim>& x) const {
        return state.velocityAt(x - state.position);
    }
};

/// A body particle of body-frame offset r placed rigidly: x = X + R r, v = V + omega x (R r).
template <int Dim>
NUMERICS_HD void placeBodyParticle(const BodyFrame<Dim>& f, const Vector<Dim>& r, Vector<Dim>& x,
                                   Vector<Dim>& v) {
    const Vector<Dim> d = f.orientation.rotate(r);
    x = f.state.position + d;
    v = f.state.velocityAt(d);
}

/// Keeps x (moving at v) out of a moving body: `solid` is its shape at t = 0, with
/// mayContain(x0) (a bounding box) and contain(x0, v0) (formulas::containOutsideBody).
template <int Dim, class Solid>
NUMERICS_HD void containInBodyFrame(Vector<Dim>& x, Vector<Dim>& v, const BodyFrame<Dim>& f,
                                    const Solid& solid) {
    Vector<Dim> x0 = f.toInitialPose(x);
    if (!solid.mayContain(x0)) return;
    Vector<Dim> v0 = f.orientation.rotateBack(v - f.velocityAt(x));
    solid.contain(x0, v0);
    x = f.state.position + f.orientation.rotate(x0 - f.initialPosition);
    v = f.velocityAt(x) + f.orientation.rotate(v0);
}

}  // namespace num::sph
