#include "scene/body_motion_reader.hpp"

#include <algorithm>

namespace num::app {

using detail::At;

namespace {

using detail::readVec;

template <int Dim>
const std::vector<std::string>& lockNames() {
    static const std::vector<std::string> names =
        Dim == 2 ? std::vector<std::string>{"x", "y", "rotation"}
                 : std::vector<std::string>{"x", "y", "z", "rx", "ry", "rz"};
    return names;
}

/// The angular velocity: a number or expression in 2D, an array of three in 3D.
template <int Dim>
std::array<Expression, BodyMotionSpec<Dim>::spinDim> readSpin(const At& a, const char* vars) {
    std::array<Expression, BodyMotionSpec<Dim>::spinDim> w{};
    const std::string meaning = "a body's motion is a function of the time t only";
    if constexpr (Dim == 2) {
        w[0] = a.expression(vars, meaning);
    } else {
        a.array(3, "three numbers or expressions [rad/s] (about x, y and z)");
        for (int k = 0; k < 3; ++k) w[k] = a[std::size_t(k)].expression(vars, meaning);
    }
    return w;
}

template <int Dim>
VectorField<Dim> readMotionVelocity(const At& a, const char* vars) {
    a.array(Dim, "numbers or expressions [m/s] (one per axis of the " + std::to_string(Dim) +
                     "D scene)");
    VectorField<Dim> v;
    for (int k = 0; k < Dim; ++k)
        v[k] =
            a[std::size_t(k)].expression(vars, "a body's motion is a function of the time t only");
    return v;
}

template <int Dim>
SpringSpec<Dim> readSpring(const At& a) {
    a.object({"anchor", "anchor_body", "point", "stiffness", "damping", "length", "mooring"},
             {"anchor", "stiffness"});
    SpringSpec<Dim> k;
    k.anchor = readVec<Dim>(a["anchor"], "m");
    if (a.has("anchor_body")) k.anchorBody = int(a["anchor_body"].integer(0, 1 << 30));
    if (a.has("point")) k.point = readVec<Dim>(a["point"], "m");
    k.stiffness = a["stiffness"].number(0, 1e15, true, "N/m");
    k.damping = a.number("damping", 0, 0, 1e15, false, "N s/m");
    if (a.has("length")) k.length = a["length"].number(0, 1e6, false, "m");
    k.mooring = a.boolean("mooring", false);
    return k;
}

template <int Dim>
std::vector<double> readInertia(const At& a) {
    if (a.v.is_number()) {
        if (Dim != 2) a.fail("three numbers (principal moments) or a 3x3 array [kg m^2]");
        return {a.number(0, 1e300, true, "kg m^2")};
    }
    if (Dim == 2) a.fail("a number above 0 [kg m^2/m] (about the centre of mass)");
    if (!a.v.is_array() || (a.v.size() != 3))
        a.fail("three numbers (principal moments) or a 3x3 array [kg m^2]");
    std::vector<double> I;
    for (std::size_t r = 0; r < 3; ++r) {
        if (!a[r].v.is_array()) {
            I.push_back(a[r].number(0, 1e300, true, "kg m^2"));
            continue;
        }
        a[r].array(3, "a row of three numbers [kg m^2]");
        for (std::size_t c = 0; c < 3; ++c) I.push_back(a[r][c].number(-1e300, 1e300));
    }
    if (I.size() != 3 && I.size() != 9)
        a.fail("three numbers (principal moments) or a 3x3 array [kg m^2]");
    return I;
}

template <int Dim>
void readLocked(const At& a, BodyMotionSpec<Dim>& m) {
    if (!a.v.is_array()) a.fail("an array of names of held degrees of freedom");
    for (std::size_t i = 0; i < a.v.size(); ++i) m.locked.push_back(a[i].choice(lockNames<Dim>()));
}

template <int Dim>
void readFree(const At& a, BodyMotionSpec<Dim>& m) {
    a.object({"type", "density", "mass", "velocity", "angular_velocity", "center_of_mass",
              "inertia", "locked", "hinge", "hinge_body", "hinge_axis", "springs", "friction"});
    if (a.has("density") == a.has("mass"))
        a.fail("an object with one of \"density\" or \"mass\"",
               "a free body's mass: give its density [kg/m^3] or its mass [kg]");
    m.density = a.number("density", 0, 0, 1e6, true, "kg/m^3");
    m.mass = a.number("mass", 0, 0, 1e300, true, Dim == 2 ? "kg/m" : "kg");
    if (a.has("velocity")) {
        const SceneVec<Dim> v = readVec<Dim>(a["velocity"], "m/s");
        for (int k = 0; k < Dim; ++k) m.velocity[k] = v[k];
    }
    if (a.has("angular_velocity")) m.angularVelocity = readSpin<Dim>(a["angular_velocity"], "");
    m.friction = a.number("friction", m.friction, 0, 10);
    if (a.has("center_of_mass")) m.centerOfMass = readVec<Dim>(a["center_of_mass"], "m");
    if (a.has("inertia")) m.inertia = readInertia<Dim>(a["inertia"]);
    if (a.has("locked")) readLocked(a["locked"], m);
    if (a.has("hinge")) m.hinge = readVec<Dim>(a["hinge"], "m");
    if (a.has("hinge_body")) {
        if (!m.hinge) a["hinge_body"].fail("a \"hinge\" point beside it (where the bodies turn)");
        m.hingeBody = int(a["hinge_body"].integer(0, 1 << 30));
    }
    m.hingeAxis[BodyMotionSpec<Dim>::spinDim - 1] = 1;
    if (a.has("hinge_axis")) {
        if (Dim == 2) a["hinge_axis"].fail("no hinge_axis in 2D (a hinge turns about z)");
        m.hingeAxis = readVec<BodyMotionSpec<Dim>::spinDim>(a["hinge_axis"], "");
        if (!(norm(m.hingeAxis) > 0)) a["hinge_axis"].fail("a direction that is not zero");
        m.hingeAxis /= norm(m.hingeAxis);
    }
    if (a.has("springs")) {
        const At s = a["springs"];
        if (!s.v.is_array()) s.fail("an array of springs");
        for (std::size_t i = 0; i < s.v.size(); ++i) m.springs.push_back(readSpring<Dim>(s[i]));
    }
}

template <int Dim>
void readPrescribed(const At& a, BodyMotionSpec<Dim>& m) {
    a.object({"type", "velocity", "angular_velocity", "center"});
    if (a.has("velocity")) m.velocity = readMotionVelocity<Dim>(a["velocity"], "t");
    if (a.has("angular_velocity")) m.angularVelocity = readSpin<Dim>(a["angular_velocity"], "t");
    if (a.has("center")) m.center = readVec<Dim>(a["center"], "m");
}

}  // namespace

template <int Dim>
BodyMotionSpec<Dim> readBodyMotion(const At& m) {
    BodyMotionSpec<Dim> spec;
    if (m.v.is_string()) {
        m.choice({"fixed"});
        return spec;
    }
    if (!m.v.is_object()) m.fail("\"fixed\" or an object with a \"type\"");
    const std::string type = m.required("type").choice({"fixed", "free", "prescribed"});
    if (type == "fixed") {
        m.object({"type"});
    } else if (type == "free") {
        spec.type = sph::MotionType::FREE;
        readFree(m, spec);
    } else {
        spec.type = sph::MotionType::PRESCRIBED;
        readPrescribed(m, spec);
    }
    return spec;
}

template BodyMotionSpec<2> readBodyMotion<2>(const At&);
template BodyMotionSpec<3> readBodyMotion<3>(const At&);

}  // namespace num::app
