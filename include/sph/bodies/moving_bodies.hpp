// The bodies of a run that move (free or prescribed; sph/bodies/rigid_body.hpp), shared by the
// coupling term that moves them, the containment that keeps fluid out of them and the outputs.
// Indexed as the geometry's bodies (FluidGeometry::bodies); fixed bodies keep their place.
#pragma once

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "sph/bodies/body_hinges.hpp"

namespace num::sph {

template <int Dim>
struct MovingBody {
    std::string name;
    BodyMotion<Dim> motion;
    BodyState<Dim> state;
    Vector<Dim> initialPosition{};  ///< the reference point at t = 0
    Float reach = 0;                ///< no point of its shape is farther from its reference point
    Vector<Dim> fluidForce{};       ///< of the last evaluation [N; 2D: N/m]
    Spin<Dim> fluidTorque{};        ///< about the reference point, of the last evaluation
    Vector<Dim> contactForce{};     ///< of the contacts with other solids, last evaluation
    Spin<Dim> contactTorque{};
};

template <int Dim>
class MovingBodies {
  public:
    std::vector<MovingBody<Dim>> bodies;

    bool moves(int b) const { return b >= 0 && bodies[b].motion.moves(); }
    bool anyMoves() const {
        for (const MovingBody<Dim>& b : bodies)
            if (b.motion.moves()) return true;
        return false;
    }
    /// The point of body b's initial pose that is at x now: X0 + R^T (x - X).
    Vector<Dim> toInitialPose(int b, const Vector<Dim>& x) const {
        const MovingBody<Dim>& m = bodies[b];
        return m.initialPosition + m.state.attitude.rotateBack(x - m.state.position);
    }
    /// A vector of the initial pose turned as body b is now (R u).
    Vector<Dim> turned(int b, const Vector<Dim>& u) const {
        return bodies[b].state.attitude.rotate(u);
    }
    /// The velocity of body b's material point at x.
    Vector<Dim> velocityAt(int b, const Vector<Dim>& x) const {
        const BodyState<Dim>& s = bodies[b].state;
        return s.velocityAt(x - s.position);
    }

    /// The states as numbers, for checkpoints: per body X, V, attitude, spin.
    std::vector<double> save() const {
        std::vector<double> out;
        for (const MovingBody<Dim>& b : bodies) {
            const BodyState<Dim>& s = b.state;
            append(out, s.position), append(out, s.velocity), append(out, s.spin);
            if constexpr (Dim == 2)
                out.push_back(s.attitude.angle);
            else
                out.insert(out.end(), s.attitude.q.begin(), s.attitude.q.end());
        }
        return out;
    }
    /// The states save() gave; throws std::invalid_argument when the count does not match.
    void restore(const std::vector<double>& in) {
        constexpr std::size_t perBody = 2 * Dim + (Dim == 2 ? 2 : 7);
        if (in.size() != perBody * bodies.size())
            throw std::invalid_argument("holds " + std::to_string(in.size() / perBody) +
                                        " body states, the scene has " +
                                        std::to_string(bodies.size()) + " bodies");
        auto at = in.begin();
        for (MovingBody<Dim>& b : bodies) {
            BodyState<Dim>& s = b.state;
            take(at, s.position), take(at, s.velocity), take(at, s.spin);
            if constexpr (Dim == 2)
                s.attitude.angle = *at++;
            else
                for (double& c : s.attitude.q) c = *at++;
        }
    }

    /// The springs' pulls on every body at the bodies' present states: a spring of body b pulls
    /// b at its point and, when its anchor is on body a, pulls a back at the anchor
    /// (rigid_body.hpp).
    std::vector<std::vector<Pull<Dim>>> springPulls() const {
        std::vector<std::vector<Pull<Dim>>> pulls(bodies.size());
        for (std::size_t b = 0; b < bodies.size(); ++b)
            for (const BodySpring<Dim>& k : bodies[b].motion.springs) {
                Vector<Dim> anchor = k.anchor, anchorVelocity{}, anchorArm{};
                if (k.anchorBody >= 0) {
                    const BodyState<Dim>& holder = bodies[std::size_t(k.anchorBody)].state;
                    anchorArm = holder.offset(k.anchor);
                    anchor = holder.position + anchorArm;
                    anchorVelocity = holder.velocityAt(anchorArm);
                }
                const std::optional<Pull<Dim>> pull =
                    springPull(k, bodies[b].state, anchor, anchorVelocity);
                if (!pull) continue;
                pulls[b].push_back(*pull);
                if (k.anchorBody >= 0)
                    pulls[std::size_t(k.anchorBody)].push_back({anchorArm, -pull->force});
            }
        return pulls;
    }

    /// Hinges body h.body on body h.holder (body_hinges.hpp).
    void addHinge(const BodyHinge<Dim>& h) {
        hinges_.push_back(h);
        partners_.resize(bodies.size());
        partners_[std::size_t(h.body)].push_back(h.holder);
        partners_[std::size_t(h.holder)].push_back(h.body);
    }
    /// Whether bodies a and b are hinged together (their particles do not push each other).
    bool hingedTogether(int a, int b) const {
        if (a < 0 || b < 0 || std::size_t(a) >= partners_.size()) return false;
        const std::vector<int>& p = partners_[std::size_t(a)];
        return std::find(p.begin(), p.end(), b) != p.end();
    }

    /// One step from t - dt to t of every body under the last evaluation's loads, gravity g, the
    /// springs (from the states before the step) and the hinges.
    void advance(const Vector<Dim>& g, Float t, Float dt) {
        const std::vector<std::vector<Pull<Dim>>> pulls = springPulls();
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            MovingBody<Dim>& b = bodies[i];
            if (b.motion.type == MotionType::FREE)
                accelerateFree(b.motion, b.state, b.fluidForce + b.contactForce,
                               b.fluidTorque + b.contactTorque, g, dt, std::span(pulls[i]));
        }
        if (!hinges_.empty()) holdAllHinges(t, dt);
        for (MovingBody<Dim>& b : bodies) {
            if (b.motion.type == MotionType::FREE) moveFree(b.state, dt);
            if (b.motion.type == MotionType::PRESCRIBED)
                advancePrescribed(b.motion, b.state, t, dt);
        }
    }

  private:
    /// The hinges' impulses on the free bodies' new velocities; a prescribed body moves with
    /// its mid-step velocity (advancePrescribed).
    void holdAllHinges(Float t, Float dt) {
        std::vector<StepMotion<Dim>> step(bodies.size());
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            const MovingBody<Dim>& b = bodies[i];
            if (b.motion.type == MotionType::FREE) step[i] = {b.state.velocity, b.state.spin};
            if (b.motion.type == MotionType::PRESCRIBED)
                step[i] = {b.motion.velocity(t - dt / 2), b.motion.spin(t - dt / 2)};
        }
        holdHinges(hinges_, bodies, step, dt);
        for (std::size_t i = 0; i < bodies.size(); ++i)
            if (bodies[i].motion.type == MotionType::FREE)
                bodies[i].state.velocity = step[i].velocity, bodies[i].state.spin = step[i].spin;
    }

    std::vector<BodyHinge<Dim>> hinges_;      ///< between two bodies (body_hinges.hpp)
    std::vector<std::vector<int>> partners_;  ///< per body, the bodies hinged to it

    template <int N>
    static void append(std::vector<double>& out, const Vec<Float, N>& v) {
        out.insert(out.end(), v.c.begin(), v.c.end());
    }
    template <int N>
    static void take(std::vector<double>::const_iterator& at, Vec<Float, N>& v) {
        for (int k = 0; k < N; ++k) v[k] = *at++;
    }
};

}  // namespace num::sph
