// The motions of a scene's bodies (bodies[i].motion) as the engine runs them: mass, centre of
// mass and inertia from the shape and density (exact where the solid knows them: boxes,
// circles, spheres, cylinders and cones, one-loop polygons, meshes, and these scaled, rotated
// and moved, geometry/mass_properties.hpp; else by a lattice quadrature of spacing dx/4 in 2D
// and dx/2 in 3D), the reference point (centre of mass, hinge or centre of rotation), held
// degrees of freedom and springs.
#include "scene/moving_bodies.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/mass_properties.hpp"
#include "sph/setup/particle_generation.hpp"

namespace num::app {

namespace {

using sph::Float;

/// Volume (2D: area), centroid and inertia about the centroid per unit density.
template <int Dim>
struct ShapeMass {
    double volume = 0;
    SceneVec<Dim> centroid{};
    sph::Inertia<Dim> inertia;
};

/// I per unit density of a lattice of cells of volume q^Dim at offsets r from the centroid:
/// sum q^Dim (|r|^2 1 - r r^T) (2D: sum q^2 |r|^2).
template <int Dim>
void addPointInertia(sph::Inertia<Dim>& I, const SceneVec<Dim>& r, double cell) {
    if constexpr (Dim == 2) {
        I.zz += cell * normSqr(r);
    } else {
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                I.rows[i][j] += cell * ((i == j) * normSqr(r) - r[i] * r[j]);
    }
}

template <int Dim>
ShapeMass<Dim> latticeMass(const sph::PlacedShape<Dim>& shape, double dx) {
    const double q = Dim == 2 ? dx / 4 : dx / 2, cell = std::pow(q, Dim);
    const geometry::Bounds<Dim> b = shape.bounds();
    std::vector<SceneVec<Dim>> inside;
    sph::forEachLatticePoint<Dim>(b.min, b.max, q, [&](const SceneVec<Dim>& x) {
        if (shape.contains(x)) inside.push_back(x);
    });
    ShapeMass<Dim> m;
    if (inside.empty()) return m;
    for (const auto& x : inside) m.centroid += x;
    m.centroid /= double(inside.size());
    m.volume = cell * double(inside.size());
    for (const auto& x : inside) addPointInertia<Dim>(m.inertia, x - m.centroid, cell);
    return m;
}

/// The solid's exact properties (geometry/mass_properties.hpp) as the bodies use them.
template <int Dim>
ShapeMass<Dim> fromGeometry(const geometry::MassProperties<Dim>& p) {
    ShapeMass<Dim> m;
    m.volume = p.volume, m.centroid = p.centroid;
    if constexpr (Dim == 2)
        m.inertia.zz = p.inertia;
    else
        m.inertia.rows = p.inertia;
    return m;
}

template <int Dim>
ShapeMass<Dim> shapeMass(const Body<Dim>& b, double dx) {
    switch (b.shape) {
        case ShapeKind::BOX:
            return fromGeometry(geometry::boxMassProperties<Dim>(b.min, b.max));
        case ShapeKind::CIRCLE:
        case ShapeKind::SPHERE:
            return fromGeometry(geometry::ballMassProperties<Dim>(b.center, b.radius));
        default:
            if (const auto exact = b.solid->massProperties()) return fromGeometry(*exact);
            return latticeMass<Dim>(b.placed(), dx);
    }
}

template <int Dim>
sph::Inertia<Dim> scaled(sph::Inertia<Dim> I, double factor) {
    if constexpr (Dim == 2) {
        I.zz *= factor;
    } else {
        for (auto& row : I.rows) row *= factor;
    }
    return I;
}

template <int Dim>
sph::Inertia<Dim> givenInertia(const std::vector<double>& I) {
    sph::Inertia<Dim> out;
    if constexpr (Dim == 2) {
        out.zz = I[0];
    } else if (I.size() == 3) {
        out = sph::Inertia<3>::diagonal(SceneVec<3>{{I[0], I[1], I[2]}});
    } else {
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) out.rows[r][c] = I[3 * r + c];
    }
    return out;
}

template <int Dim>
void holdDegrees(const BodyMotionSpec<Dim>& spec, sph::BodyMotion<Dim>& m) {
    static const char* axes[] = {"x", "y", "z"};
    static const char* spins[] = {"rx", "ry", "rz"};
    for (const std::string& name : spec.locked) {
        for (int k = 0; k < Dim; ++k)
            if (name == axes[k]) m.heldAxes[k] = true;
        if (name == "rotation") m.heldSpins[0] = true;
        for (int k = 0; k < 3 && Dim == 3; ++k)
            if (name == spins[k]) m.heldSpins[std::size_t(k)] = true;
    }
}

/// A free body: mass and inertia, about its centre of mass or its hinge.
template <int Dim>
sph::MovingBody<Dim> freeBody(const Body<Dim>& b, double dx) {
    const BodyMotionSpec<Dim>& spec = b.motion;
    const ShapeMass<Dim> shape = shapeMass(b, dx);
    sph::MovingBody<Dim> body;
    sph::BodyMotion<Dim>& m = body.motion;
    m.type = sph::MotionType::FREE;
    m.mass = spec.mass > 0 ? spec.mass : spec.density * shape.volume;
    const double density = m.mass / shape.volume;
    const SceneVec<Dim> com = spec.centerOfMass.value_or(shape.centroid);
    sph::Inertia<Dim> aboutCom =
        spec.inertia.empty() ? scaled(shape.inertia, density).shifted(m.mass, com - shape.centroid)
                             : givenInertia<Dim>(spec.inertia);
    holdDegrees(spec, m);
    m.friction = spec.friction;
    const bool onTheWorld = spec.hinge && spec.hingeBody < 0;
    body.initialPosition = onTheWorld ? *spec.hinge : com;
    if (onTheWorld) {
        m.hinged = true, m.hingeAxis = spec.hingeAxis;
        m.centerOfMass = com - *spec.hinge;
        aboutCom = aboutCom.shifted(m.mass, m.centerOfMass);
    }
    m.inertia = aboutCom;
    for (int k = 0; k < Dim; ++k) body.state.velocity[k] = spec.velocity[k](0, 0, 0, 0);
    for (int k = 0; k < BodyMotionSpec<Dim>::spinDim; ++k)
        body.state.spin[k] = spec.angularVelocity[std::size_t(k)](0, 0, 0, 0);
    if (m.hinged) body.state.velocity = SceneVec<Dim>{};
    return body;
}

template <int Dim>
sph::MovingBody<Dim> prescribedBody(const Body<Dim>& b, double dx) {
    const BodyMotionSpec<Dim>& spec = b.motion;
    sph::MovingBody<Dim> body;
    sph::BodyMotion<Dim>& m = body.motion;
    m.type = sph::MotionType::PRESCRIBED;
    m.velocity = [v = spec.velocity](Float t) {
        SceneVec<Dim> out;
        for (int k = 0; k < Dim; ++k) out[k] = v[k](0, 0, 0, t);
        return out;
    };
    m.spin = [w = spec.angularVelocity](Float t) {
        sph::Spin<Dim> out;
        for (std::size_t k = 0; k < w.size(); ++k) out[int(k)] = w[k](0, 0, 0, t);
        return out;
    };
    body.initialPosition = spec.center ? *spec.center : shapeMass(b, dx).centroid;
    body.state.velocity = m.velocity(0), body.state.spin = m.spin(0);
    return body;
}

/// Body b's springs; an anchor on another body is kept as its offset from that body's reference
/// point at t = 0.
template <int Dim>
void addSprings(const BodyMotionSpec<Dim>& spec, std::size_t b, sph::MovingBodies<Dim>& all) {
    sph::MovingBody<Dim>& body = all.bodies[b];
    for (const SpringSpec<Dim>& s : spec.springs) {
        sph::BodySpring<Dim> k;
        k.anchor = s.anchor, k.anchorBody = s.anchorBody;
        if (s.anchorBody >= 0)
            k.anchor = s.anchor - all.bodies[std::size_t(s.anchorBody)].initialPosition;
        const SceneVec<Dim> point = s.point.value_or(body.initialPosition);
        k.point = point - body.initialPosition;
        k.stiffness = s.stiffness, k.damping = s.damping, k.slack = s.mooring;
        k.restLength = s.length.value_or(norm(point - s.anchor));
        body.motion.springs.push_back(k);
    }
}

/// Body b's hinge on another body: the pin and (3D) the axis in both bodies' frames at t = 0.
template <int Dim>
void addHinge(const BodyMotionSpec<Dim>& spec, std::size_t b, sph::MovingBodies<Dim>& all) {
    if (spec.hingeBody < 0) return;
    const SceneVec<Dim>& pin = *spec.hinge;
    sph::BodyHinge<Dim> h{.body = int(b), .holder = spec.hingeBody};
    h.point = pin - all.bodies[b].initialPosition;
    h.holderPoint = pin - all.bodies[std::size_t(spec.hingeBody)].initialPosition;
    h.axis = h.holderAxis = spec.hingeAxis;
    all.addHinge(h);
}

/// The farthest corner of the shape's bounding box from p.
template <int Dim>
double reachFrom(const Body<Dim>& b, const SceneVec<Dim>& p) {
    const geometry::Bounds<Dim> box = b.placed().bounds();
    double reach = 0;
    for (int corner = 0; corner < (1 << Dim); ++corner) {
        SceneVec<Dim> c;
        for (int k = 0; k < Dim; ++k) c[k] = (corner >> k & 1) ? box.max[k] : box.min[k];
        reach = std::max(reach, norm(c - p));
    }
    return reach;
}

}  // namespace

template <int Dim>
std::shared_ptr<sph::MovingBodies<Dim>> makeMovingBodies(const Scene<Dim>& scene) {
    auto out = std::make_shared<sph::MovingBodies<Dim>>();
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const Body<Dim>& b = scene.bodies[i];
        sph::MovingBody<Dim> body;
        if (b.motion.type == sph::MotionType::FREE) body = freeBody(b, scene.spacing);
        if (b.motion.type == sph::MotionType::PRESCRIBED) body = prescribedBody(b, scene.spacing);
        body.name = bodyName(scene, i);
        body.state.position = body.initialPosition;
        body.reach = reachFrom(b, body.initialPosition);
        out->bodies.push_back(std::move(body));
    }
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
        addSprings(scene.bodies[i].motion, i, *out), addHinge(scene.bodies[i].motion, i, *out);
    if (!out->anyMoves()) return nullptr;
    return out;
}

template <int Dim>
std::string bodyName(const Scene<Dim>& scene, std::size_t i) {
    const std::string& name = scene.bodies[i].name;
    return name.empty() ? "bodies[" + std::to_string(i) + "]" : name;
}

template <int Dim>
double bodyVolume(const Body<Dim>& body, double dx) {
    return shapeMass(body, dx).volume;
}

template std::shared_ptr<sph::MovingBodies<2>> makeMovingBodies<2>(const Scene<2>&);
template std::shared_ptr<sph::MovingBodies<3>> makeMovingBodies<3>(const Scene<3>&);
template std::string bodyName<2>(const Scene<2>&, std::size_t);
template std::string bodyName<3>(const Scene<3>&, std::size_t);
template double bodyVolume<2>(const Body<2>&, double);
template double bodyVolume<3>(const Body<3>&, double);

}  // namespace num::app
