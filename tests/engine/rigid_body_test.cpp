// The rigid-body equations of motion (sph/bodies/rigid_body.hpp) against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sph/bodies/moving_bodies.hpp"

using namespace num;
using namespace num::sph;

namespace {

constexpr double pi = std::numbers::pi;

/// A free 2D body of this mass and moment of inertia about its centre of mass.
BodyMotion<2> freeBody(double mass, double inertia) {
    BodyMotion<2> m;
    m.type = MotionType::FREE;
    m.mass = mass;
    m.inertia.zz = inertia;
    return m;
}

BodyMotion<2> freeDisc(double mass, double radius) {
    return freeBody(mass, mass * radius * radius / 2);
}

/// The time of the first upward crossing of zero of f after `from` steps (linear interpolation).
template <class Step, class Value>
double period(Step&& step, Value&& value, double dt, int steps) {
    double previous = value(), t = 0, first = -1;
    for (int n = 0; n < steps; ++n) {
        step();
        t += dt;
        const double now = value();
        if (previous < 0 && now >= 0) {
            const double crossing = t - dt * now / (now - previous);
            if (first >= 0) return crossing - first;
            first = crossing;
        }
        previous = now;
    }
    return -1;
}

}  // namespace

TEST(RigidBody, AttitudeTurnsAndTurnsBack) {
    Attitude<2> a2;
    a2.turn(Spin<2>{{pi / 2}}, 1.0);
    const Vector<2> y = a2.rotate(Vector<2>{{1, 0}});
    EXPECT_NEAR(y[0], 0, 1e-15);
    EXPECT_NEAR(y[1], 1, 1e-15);
    Attitude<3> a3;
    a3.turn(Spin<3>{{0, 0, pi / 2}}, 1.0);
    const Vector<3> y3 = a3.rotate(Vector<3>{{1, 0, 0}});
    EXPECT_NEAR(y3[0], 0, 1e-15);
    EXPECT_NEAR(y3[1], 1, 1e-15);
    a3.turn(Spin<3>{{0.3, -0.2, 0.7}}, 0.9);
    const Vector<3> r{{0.1, -2, 0.5}}, back = a3.rotateBack(a3.rotate(r));
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(back[k], r[k], 1e-14);
    EXPECT_NEAR(norm(a3.rotate(r)), norm(r), 1e-14);
}

// Symplectic Euler under a constant g: V_n = n g dt, X_n = g dt^2 n (n + 1) / 2.
TEST(RigidBody, FreeFallIsSymplecticEuler) {
    const BodyMotion<2> m = freeDisc(3, 0.1);
    BodyState<2> s;
    const Vector<2> g{{0, -9.81}};
    const double dt = 1e-3;
    const int n = 500;
    for (int k = 0; k < n; ++k) advanceFree(m, s, Vector<2>{}, Spin<2>{}, g, dt);
    EXPECT_NEAR(s.velocity[1], -9.81 * n * dt, 1e-12);
    EXPECT_NEAR(s.position[1], -9.81 * dt * dt * n * (n + 1) / 2, 1e-12);
    EXPECT_EQ(s.spin[0], 0);
}

TEST(RigidBody, HeldAxesAndSpinStayAtRest) {
    BodyMotion<2> m = freeDisc(1, 0.1);
    m.heldAxes = {false, true};
    m.heldSpins = {true};
    BodyState<2> s;
    for (int k = 0; k < 10; ++k)
        advanceFree(m, s, Vector<2>{{1, 1}}, Spin<2>{{1}}, Vector<2>{{0, -9.81}}, 0.01);
    EXPECT_GT(s.position[0], 0);
    EXPECT_EQ(s.position[1], 0);
    EXPECT_EQ(s.attitude.angle, 0);
}

// A prescribed constant velocity travels exactly V t; a cosine one its integral to O(dt^2).
TEST(RigidBody, PrescribedMotionTravelsItsIntegral) {
    BodyMotion<2> m;
    m.type = MotionType::PRESCRIBED;
    m.velocity = [](Float t) { return Vector<2>{{0.3, 0.05 * std::cos(2 * pi * t)}}; };
    m.spin = [](Float) { return Spin<2>{{2}}; };
    BodyState<2> s;
    const double dt = 1e-3;
    for (int k = 1; k <= 700; ++k) advancePrescribed(m, s, k * dt, dt);
    EXPECT_NEAR(s.position[0], 0.3 * 0.7, 1e-14);
    // The midpoint rule's bound: dt^2 / 24 t max|v''| = 1e-6 / 24 0.7 0.05 (2 pi)^2 = 5.8e-8.
    EXPECT_NEAR(s.position[1], 0.05 * std::sin(2 * pi * 0.7) / (2 * pi), 5.8e-8);
    EXPECT_NEAR(s.attitude.angle, 1.4, 1e-13);
    EXPECT_EQ(s.velocity[0], 0.3);
}

namespace {

/// Adds a body with motion m at `position`, as the coupling holds it.
void addBody(MovingBodies<2>& bodies, const BodyMotion<2>& m, const Vector<2>& position) {
    MovingBody<2> body;
    body.motion = m;
    body.state.position = position;
    bodies.bodies.push_back(body);
}

/// One step dt of every free body under its springs alone.
void stepSprings(MovingBodies<2>& bodies, double dt) {
    const auto pulls = bodies.springPulls();
    for (std::size_t b = 0; b < bodies.bodies.size(); ++b)
        advanceFree(bodies.bodies[b].motion, bodies.bodies[b].state, Vector<2>{}, Spin<2>{},
                    Vector<2>{}, dt, std::span(pulls[b]));
}

}  // namespace

// A mass on a spring: T = 2 pi sqrt(M / k) (within 0.1 %).
TEST(RigidBody, SpringOscillatesAtItsPeriod) {
    BodyMotion<2> m = freeDisc(2, 0.05);
    m.springs.push_back({.anchor = Vector<2>{{-1, 0}}, .stiffness = 50, .restLength = 1});
    MovingBodies<2> bodies;
    addBody(bodies, m, Vector<2>{{0.1, 0}});
    const double dt = 1e-4;
    const double T = period([&] { stepSprings(bodies, dt); },
                            [&] { return bodies.bodies[0].state.position[0]; }, dt, 100000);
    EXPECT_NEAR(T, 2 * pi * std::sqrt(2.0 / 50), 1e-3 * T);
}

// Two bodies joined by a spring: the relative motion has T = 2 pi sqrt(mu / k),
// mu = m1 m2 / (m1 + m2) (within 0.1 %); the pulls are equal and opposite, so the centre of mass
// stays where it is (to round-off).
TEST(RigidBody, SpringBetweenTwoBodiesKeepsTheirCentreOfMass) {
    MovingBodies<2> bodies;
    addBody(bodies, freeDisc(2, 0.05), Vector<2>{{0, 0}});
    BodyMotion<2> second = freeDisc(3, 0.05);
    second.springs.push_back(
        {.anchor = Vector<2>{}, .anchorBody = 0, .stiffness = 50, .restLength = 1});
    addBody(bodies, second, Vector<2>{{1.1, 0}});
    const auto centre = [&] {
        return (2 * bodies.bodies[0].state.position[0] + 3 * bodies.bodies[1].state.position[0]) /
               5;
    };
    const double start = centre(), dt = 1e-4;
    const double T = period(
        [&] { stepSprings(bodies, dt); },
        [&] { return bodies.bodies[1].state.position[0] - bodies.bodies[0].state.position[0] - 1; },
        dt, 100000);
    EXPECT_NEAR(T, 2 * pi * std::sqrt(2.0 * 3 / 5 / 50), 1e-3 * T);
    EXPECT_NEAR(centre(), start, 1e-12);
}

// A mooring line is slack when shorter than its rest length.
TEST(RigidBody, MooringLinePullsOnlyWhenTaut) {
    BodyMotion<2> m = freeDisc(1, 0.1);
    const BodySpring<2> line{
        .anchor = Vector<2>{{0, -1}}, .stiffness = 100, .restLength = 1, .slack = true};
    BodyState<2> s;
    s.position = Vector<2>{{0, -0.5}};
    EXPECT_FALSE(springPull(line, s, line.anchor, Vector<2>{}).has_value());
    s.position = Vector<2>{{0, 0.1}};
    const std::optional<Pull<2>> pull = springPull(line, s, line.anchor, Vector<2>{});
    ASSERT_TRUE(pull.has_value());
    EXPECT_NEAR(pull->force[1], -10, 1e-12);
}

// A rod hinged at one end, a compound pendulum: T = 2 pi sqrt(I_P / (M g d)) for small angles,
// I_P = M L^2 / 3, d = L / 2 (within 0.5 %).
TEST(RigidBody, HingedRodSwingsAsACompoundPendulum) {
    const double M = 1.5, L = 0.4;
    BodyMotion<2> m;
    m.type = MotionType::FREE;
    m.mass = M;
    m.hinged = true;
    m.centerOfMass = Vector<2>{{0, -L / 2}};
    m.inertia.zz = M * L * L / 12;
    m.inertia = m.inertia.shifted(M, m.centerOfMass);
    BodyState<2> s;
    s.spin = Spin<2>{{0.05}};
    const double dt = 1e-4;
    const double T = period(
        [&] {
            advanceFree(m, s, Vector<2>{}, Spin<2>{}, Vector<2>{{0, -9.81}}, dt);
        },
        [&] { return s.spin[0]; }, dt, 100000);
    EXPECT_NEAR(T, 2 * pi * std::sqrt(M * L * L / 3 / (M * 9.81 * L / 2)), 5e-3 * T);
    EXPECT_EQ(s.position[0], 0);
    EXPECT_EQ(s.position[1], 0);
}

// Without torque a spinning 3D body keeps its angular momentum (to 1e-3 over 2,000 steps).
TEST(RigidBody, TorqueFreeSpinKeepsItsMomentum) {
    BodyMotion<3> m;
    m.type = MotionType::FREE;
    m.mass = 1;
    m.inertia = Inertia<3>::diagonal(Vector<3>{{1, 2, 3}});
    BodyState<3> s;
    s.spin = Spin<3>{{0.1, 1, 0.1}};
    const Spin<3> L0 = m.inertia.momentum(s.spin, s.attitude);
    for (int k = 0; k < 2000; ++k) advanceFree(m, s, Vector<3>{}, Spin<3>{}, Vector<3>{}, 1e-3);
    const Spin<3> L = m.inertia.momentum(s.spin, s.attitude);
    EXPECT_NEAR(norm(L - L0), 0, 1e-3 * norm(L0));
}

TEST(RigidBody, InertiaInverseAndParallelAxes) {
    Inertia<3> I = Inertia<3>::diagonal(Vector<3>{{1, 2, 3}});
    I.rows[0][1] = I.rows[1][0] = 0.3;
    EXPECT_TRUE(I.positive());
    const Attitude<3> q;
    const Spin<3> w{{0.2, -1, 0.5}}, back = I.spin(I.momentum(w, q), q);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(back[k], w[k], 1e-14);
    const Inertia<3> P =
        Inertia<3>::diagonal(Vector<3>{{1, 1, 1}}).shifted(2, Vector<3>{{0, 0, 1}});
    EXPECT_DOUBLE_EQ(P.rows[0][0], 3);
    EXPECT_DOUBLE_EQ(P.rows[2][2], 1);
    Inertia<3> notSymmetric = I;
    notSymmetric.rows[0][2] = 0.1;
    EXPECT_FALSE(notSymmetric.positive());
}

TEST(RigidBody, StatesSaveAndRestore) {
    MovingBodies<3> bodies;
    bodies.bodies.resize(2);
    bodies.bodies[1].state.position = Vector<3>{{1, 2, 3}};
    bodies.bodies[1].state.attitude.turn(Spin<3>{{0.1, 0.2, 0.3}}, 1);
    bodies.bodies[0].state.spin = Spin<3>{{4, 5, 6}};
    MovingBodies<3> copy;
    copy.bodies.resize(2);
    copy.restore(bodies.save());
    EXPECT_EQ(copy.bodies[0].state, bodies.bodies[0].state);
    EXPECT_EQ(copy.bodies[1].state, bodies.bodies[1].state);
    copy.bodies.resize(3);
    EXPECT_THROW(copy.restore(bodies.save()), std::invalid_argument);
}

namespace {

/// A rod of mass M and length L, free about its centre of mass (2D).
BodyMotion<2> freeRod(double M, double L) { return freeBody(M, M * L * L / 12); }

/// The distance between the two material points of hinge h.
template <int Dim>
double pinGap(const MovingBodies<Dim>& bodies, const BodyHinge<Dim>& h) {
    const BodyState<Dim>&a = bodies.bodies[h.body].state, &b = bodies.bodies[h.holder].state;
    return norm(a.position + a.offset(h.point) - b.position - b.offset(h.holderPoint));
}

}  // namespace

// A rod hinged at its top end on a body moving at a constant velocity is a compound pendulum
// in the moving frame (Galilean invariance): T = 2 pi sqrt(I_P / (M g d)), I_P = M L^2 / 3,
// d = L / 2 (within 0.5 %, as the hinge on the world); the pin stays joined (1e-6 L).
TEST(RigidBody, RodHingedOnAMovingBodySwingsAsAPendulum) {
    const double M = 1.5, L = 0.4, dt = 1e-4;
    MovingBodies<2> bodies;
    BodyMotion<2> cart;
    cart.type = MotionType::PRESCRIBED;
    cart.velocity = [](Float) { return Vector<2>{{0.7, 0}}; };
    cart.spin = [](Float) { return Spin<2>{}; };
    addBody(bodies, cart, Vector<2>{{0, 0}});
    addBody(bodies, freeRod(M, L), Vector<2>{{0, -L / 2}});
    bodies.bodies[1].state.velocity = Vector<2>{{0.7, 0}};
    bodies.bodies[1].state.spin = Spin<2>{{0.05}};
    bodies.bodies[1].state.velocity[0] -= 0.05 * L / 2;  // the pin moves with the cart
    const BodyHinge<2> h{
        .body = 1, .holder = 0, .point = Vector<2>{{0, L / 2}}, .holderPoint = Vector<2>{}};
    bodies.addHinge(h);
    double t = 0, widest = 0;
    const double T = period(
        [&] {
            t += dt;
            bodies.advance(Vector<2>{{0, -9.81}}, t, dt);
            widest = std::max(widest, pinGap(bodies, h));
        },
        [&] { return bodies.bodies[1].state.spin[0]; }, dt, 100000);
    EXPECT_NEAR(T, 2 * pi * std::sqrt(M * L * L / 3 / (M * 9.81 * L / 2)), 5e-3 * T);
    EXPECT_LT(widest, 1e-6 * L);
    EXPECT_NEAR(bodies.bodies[0].state.position[0], 0.7 * t, 1e-12);
}

// Two free rods hinged end to end, no gravity: the impulses are equal and opposite, so the
// momentum stays (to round-off) and the pin stays joined while they tumble.
TEST(RigidBody, TwoHingedFreeRodsKeepTheirMomentum) {
    const double L = 0.4, dt = 1e-4;
    MovingBodies<2> bodies;
    addBody(bodies, freeRod(1, L), Vector<2>{{-L / 2, 0}});
    addBody(bodies, freeRod(2, L), Vector<2>{{L / 2, 0}});
    bodies.bodies[0].state.spin = Spin<2>{{3}};
    bodies.bodies[0].state.velocity = Vector<2>{{0.1, -3 * L / 2}};
    bodies.bodies[1].state.velocity = Vector<2>{{0.1, 0}};
    const BodyHinge<2> h{.body = 1,
                         .holder = 0,
                         .point = Vector<2>{{-L / 2, 0}},
                         .holderPoint = Vector<2>{{L / 2, 0}}};
    bodies.addHinge(h);
    const auto momentum = [&] {
        return bodies.bodies[0].state.velocity * 1.0 + bodies.bodies[1].state.velocity * 2.0;
    };
    const Vector<2> p0 = momentum();
    double widest = 0;
    for (int n = 1; n <= 20000; ++n) {
        bodies.advance(Vector<2>{}, n * dt, dt);
        widest = std::max(widest, pinGap(bodies, h));
    }
    EXPECT_LT(norm(momentum() - p0), 1e-12);
    EXPECT_LT(widest, 1e-5 * L);
    EXPECT_GT(std::abs(bodies.bodies[1].state.attitude.angle), 0.1);  // the second rod turned
}

// 3D: a rod hinged about x on a body at rest, pushed off the axis: it swings about x only (the
// axis holds the other spin components near zero) at the compound pendulum's period.
TEST(RigidBody, HingeAxisHoldsIn3D) {
    const double M = 1.5, L = 0.4, dt = 1e-4;
    MovingBodies<3> bodies;
    MovingBody<3> holder;
    holder.motion.type = MotionType::PRESCRIBED;
    holder.motion.velocity = [](Float) { return Vector<3>{}; };
    holder.motion.spin = [](Float) { return Spin<3>{}; };
    bodies.bodies.push_back(holder);
    MovingBody<3> rod;
    rod.motion.type = MotionType::FREE;
    rod.motion.mass = M;
    rod.motion.inertia = Inertia<3>::diagonal(Vector<3>{{M * L * L / 12, 1e-3, M * L * L / 12}});
    rod.state.position = Vector<3>{{0, -L / 2, 0}};
    rod.state.spin = Spin<3>{{0.05, 0.02, 0.03}};
    bodies.bodies.push_back(rod);
    const BodyHinge<3> h{.body = 1,
                         .holder = 0,
                         .point = Vector<3>{{0, L / 2, 0}},
                         .holderPoint = Vector<3>{},
                         .axis = Spin<3>{{1, 0, 0}},
                         .holderAxis = Spin<3>{{1, 0, 0}}};
    bodies.addHinge(h);
    double t = 0, offAxis = 0;
    const double T = period(
        [&] {
            t += dt;
            bodies.advance(Vector<3>{{0, -9.81, 0}}, t, dt);
            const Spin<3>& w = bodies.bodies[1].state.spin;
            if (t > 0.01) offAxis = std::max(offAxis, std::hypot(w[1], w[2]));
        },
        [&] { return bodies.bodies[1].state.spin[0]; }, dt, 100000);
    EXPECT_NEAR(T, 2 * pi * std::sqrt(M * L * L / 3 / (M * 9.81 * L / 2)), 5e-3 * T);
    EXPECT_LT(offAxis, 1e-3 * 0.05);
    EXPECT_LT(pinGap(bodies, h), 1e-6 * L);
}
