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
void readAnchor(const At& a, SpringSpec<Dim>& k) {
    k.anchor = readVec<Dim>(a, "m");
}

template <int Dim>
void readAnchorBody(const At& a, SpringSpec<Dim>& k) {
    k.anchorBody = int(a.integer(0, 1 << 30));
}

template <int Dim>
void readSpringPoint(const At& a, SpringSpec<Dim>& k) {
    k.point = readVec<Dim>(a, "m");
}

template <int Dim>
void readRestLength(const At& a, SpringSpec<Dim>& k) {
    k.length = a.number(0, 1e6, false, "m");
}

template <int Dim>
const KeyTable<SpringSpec<Dim>> kSpringKeys{
    {.name = "anchor",
     .type = KeyType::CUSTOM,
     .unit = "m",
     .meaning = "the spring's far end at t = 0: fixed, or on `anchor_body`",
     .required = true,
     .read = readAnchor<Dim>},
    {.name = "anchor_body",
     .type = KeyType::CUSTOM,
     .meaning = "the index of another body that holds the anchor (the spring pulls both)",
     .read = readAnchorBody<Dim>,
     .shownDefault = "none (fixed)"},
    {.name = "point",
     .type = KeyType::CUSTOM,
     .unit = "m",
     .meaning = "the end on the body at t = 0",
     .read = readSpringPoint<Dim>,
     .shownDefault = "its centre of mass or hinge"},
    {.name = "stiffness",
     .type = KeyType::NUMBER,
     .field = &SpringSpec<Dim>::stiffness,
     .fallback = 0.0,
     .unit = "N/m",
     .lo = 0,
     .hi = 1e15,
     .loOpen = true,
     .meaning = "in 2D per metre of depth",
     .required = true},
    {.name = "damping",
     .type = KeyType::NUMBER,
     .field = &SpringSpec<Dim>::damping,
     .fallback = 0.0,
     .unit = "N s/m",
     .lo = 0,
     .hi = 1e15},
    {.name = "length",
     .type = KeyType::CUSTOM,
     .unit = "m",
     .meaning = "[0, 1e6]: the rest length",
     .read = readRestLength<Dim>,
     .shownDefault = "the distance at t = 0"},
    {.name = "mooring",
     .type = KeyType::FLAG,
     .field = &SpringSpec<Dim>::mooring,
     .fallback = false,
     .meaning = "true: a mooring line, which pulls only when longer than its rest length"},
};

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

/// A free body's initial velocity (numbers).
template <int Dim>
void readInitialVelocity(const At& a, BodyMotionSpec<Dim>& m) {
    const SceneVec<Dim> v = readVec<Dim>(a, "m/s");
    for (int k = 0; k < Dim; ++k) m.velocity[k] = v[k];
}

template <int Dim>
void readInitialSpin(const At& a, BodyMotionSpec<Dim>& m) {
    m.angularVelocity = readSpin<Dim>(a, "");
}

template <int Dim>
void readCenterOfMass(const At& a, BodyMotionSpec<Dim>& m) {
    m.centerOfMass = readVec<Dim>(a, "m");
}

template <int Dim>
void readInertiaKey(const At& a, BodyMotionSpec<Dim>& m) {
    m.inertia = readInertia<Dim>(a);
}

template <int Dim>
void readHinge(const At& a, BodyMotionSpec<Dim>& m) {
    m.hinge = readVec<Dim>(a, "m");
}

/// Read after the hinge.
template <int Dim>
void readHingeBody(const At& a, BodyMotionSpec<Dim>& m) {
    if (!m.hinge) a.fail("a \"hinge\" point beside it (where the bodies turn)");
    m.hingeBody = int(a.integer(0, 1 << 30));
}

template <int Dim>
void readHingeAxis(const At& a, BodyMotionSpec<Dim>& m) {
    if (Dim == 2) a.fail("no hinge_axis in 2D (a hinge turns about z)");
    m.hingeAxis = readVec<BodyMotionSpec<Dim>::spinDim>(a, "");
    if (!(norm(m.hingeAxis) > 0)) a.fail("a direction that is not zero");
    m.hingeAxis /= norm(m.hingeAxis);
}

template <int Dim>
void readSprings(const At& s, BodyMotionSpec<Dim>& m) {
    if (!s.v.is_array()) s.fail("an array of springs");
    for (std::size_t i = 0; i < s.v.size(); ++i) {
        SpringSpec<Dim> spring;
        readKeys(s[i], kSpringKeys<Dim>, spring);
        m.springs.push_back(spring);
    }
}

template <int Dim>
const KeyTable<BodyMotionSpec<Dim>> kFreeKeys{
    {.name = "type",
     .type = KeyType::CUSTOM,
     .meaning = "`\"free\"`",
     .required = true,
     .read = readBefore<BodyMotionSpec<Dim>>},
    {.name = "density",
     .type = KeyType::NUMBER,
     .field = &BodyMotionSpec<Dim>::density,
     .fallback = 0.0,
     .unit = "kg/m^3",
     .lo = 0,
     .hi = 1e6,
     .loOpen = true,
     .meaning = "the mass is the density times the shape's volume (area in 2D)",
     .shownDefault = "this or `mass`"},
    {.name = "mass",
     .type = KeyType::NUMBER,
     .field = &BodyMotionSpec<Dim>::mass,
     .fallback = 0.0,
     .unit = Dim == 2 ? "kg/m" : "kg",
     .lo = 0,
     .loOpen = true,
     .meaning = "the mass (2D: kg/m, per metre of depth)",
     .shownDefault = "this or `density`"},
    {.name = "velocity",
     .type = KeyType::CUSTOM,
     .unit = "m/s",
     .meaning = "initial velocity (numbers)",
     .read = readInitialVelocity<Dim>,
     .shownDefault = "zero"},
    {.name = "angular_velocity",
     .type = KeyType::CUSTOM,
     .unit = "rad/s",
     .meaning = "initial: a number in 2D (about z), `[wx, wy, wz]` in 3D",
     .read = readInitialSpin<Dim>,
     .shownDefault = "zero"},
    {.name = "center_of_mass",
     .type = KeyType::CUSTOM,
     .unit = "m",
     .meaning = "a point",
     .read = readCenterOfMass<Dim>,
     .shownDefault = "the shape's centroid"},
    {.name = "inertia",
     .type = KeyType::CUSTOM,
     .unit = "kg m^2",
     .meaning = "about the centre of mass: a number in 2D (kg m²/m); in 3D three principal "
                "moments (body axes along x, y, z at t = 0) or a symmetric positive definite 3x3 "
                "array. Default: exact for boxes, circles, spheres, cylinders, cones, polygons "
                "(one outline) and meshes, also scaled, rotated or moved; else (unions, "
                "differences, intersections, polygons with holes, polylines) by quadrature on a "
                "lattice of dx/4 (2D) or dx/2 (3D); uniform density",
     .read = readInertiaKey<Dim>,
     .shownDefault = "the shape's"},
    {.name = "locked",
     .type = KeyType::CUSTOM,
     .meaning = "degrees of freedom held at rest: `\"x\"`, `\"y\"` (`\"z\"`), and `\"rotation\"` "
                "in 2D or `\"rx\"`, `\"ry\"`, `\"rz\"` (world axes) in 3D",
     .read = readLocked<Dim>,
     .shownDefault = "none"},
    {.name = "hinge",
     .type = KeyType::CUSTOM,
     .unit = "m",
     .meaning = "a point (at t = 0) the body turns about and nothing else (a flap)",
     .read = readHinge<Dim>,
     .shownDefault = "none"},
    {.name = "hinge_body",
     .type = KeyType::CUSTOM,
     .meaning = "the index of the body that holds the hinge (another body, which it moves with; "
                "the two do not touch each other)",
     .read = readHingeBody<Dim>,
     .shownDefault = "none (the world)"},
    {.name = "hinge_axis",
     .type = KeyType::CUSTOM,
     .meaning = "3D: the hinge's axis",
     .read = readHingeAxis<Dim>,
     .shownDefault = "`[0, 0, 1]`"},
    {.name = "springs",
     .type = KeyType::CUSTOM,
     .meaning = "springs or mooring lines from an anchor to the body, each with the keys of a "
                "spring (below)",
     .read = readSprings<Dim>,
     .shownDefault = "none"},
    {.name = "friction",
     .type = KeyType::NUMBER,
     .field = &BodyMotionSpec<Dim>::friction,
     .fallback = 0.3,
     .lo = 0,
     .hi = 10,
     .meaning = "Coulomb coefficient of contacts with walls and other bodies"},
};

/// The keys a free motion's reader read first, before its table: the friction before the centre
/// of mass.
const std::vector<std::string> kFreeReadFirst{"density", "mass", "velocity", "angular_velocity",
                                              "friction"};

template <int Dim>
void readFree(const At& a, BodyMotionSpec<Dim>& m) {
    a.object(keyNames(kFreeKeys<Dim>), keyNames(kFreeKeys<Dim>, true));
    if (a.has("density") == a.has("mass"))
        a.fail("an object with one of \"density\" or \"mass\"",
               "a free body's mass: give its density [kg/m^3] or its mass [kg]");
    m.hingeAxis[BodyMotionSpec<Dim>::spinDim - 1] = 1;
    readKeyValues(a, kFreeKeys<Dim>, m, kFreeReadFirst);
}

template <int Dim>
void readPrescribedVelocity(const At& a, BodyMotionSpec<Dim>& m) {
    m.velocity = readMotionVelocity<Dim>(a, "t");
}

template <int Dim>
void readPrescribedSpin(const At& a, BodyMotionSpec<Dim>& m) {
    m.angularVelocity = readSpin<Dim>(a, "t");
}

template <int Dim>
void readCenter(const At& a, BodyMotionSpec<Dim>& m) {
    m.center = readVec<Dim>(a, "m");
}

template <int Dim>
const KeyTable<BodyMotionSpec<Dim>> kPrescribedKeys{
    {.name = "type",
     .type = KeyType::CUSTOM,
     .meaning = "`\"prescribed\"`",
     .required = true,
     .read = readBefore<BodyMotionSpec<Dim>>},
    {.name = "velocity",
     .type = KeyType::CUSTOM,
     .unit = "m/s",
     .meaning = "vector of numbers or expressions in `t`, e.g. `[\"0.05*cos(2*_pi*t)\", 0]`",
     .read = readPrescribedVelocity<Dim>,
     .shownDefault = "zero"},
    {.name = "angular_velocity",
     .type = KeyType::CUSTOM,
     .unit = "rad/s",
     .meaning = "number or expression in `t` (2D), array of three (3D)",
     .read = readPrescribedSpin<Dim>,
     .shownDefault = "zero"},
    {.name = "center",
     .type = KeyType::CUSTOM,
     .unit = "m",
     .meaning = "the point it turns about at t = 0 (a hinge)",
     .read = readCenter<Dim>,
     .shownDefault = "the shape's centroid"},
};

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
        readKeys(m, kPrescribedKeys<Dim>, spec);
    }
    return spec;
}

template <int Dim>
const KeyTable<BodyMotionSpec<Dim>>& freeMotionKeys() {
    return kFreeKeys<Dim>;
}

template <int Dim>
const KeyTable<BodyMotionSpec<Dim>>& prescribedMotionKeys() {
    return kPrescribedKeys<Dim>;
}

template <int Dim>
const KeyTable<SpringSpec<Dim>>& springKeys() {
    return kSpringKeys<Dim>;
}

template BodyMotionSpec<2> readBodyMotion<2>(const At&);
template BodyMotionSpec<3> readBodyMotion<3>(const At&);
template const KeyTable<BodyMotionSpec<2>>& freeMotionKeys<2>();
template const KeyTable<BodyMotionSpec<3>>& freeMotionKeys<3>();
template const KeyTable<BodyMotionSpec<2>>& prescribedMotionKeys<2>();
template const KeyTable<BodyMotionSpec<3>>& prescribedMotionKeys<3>();
template const KeyTable<SpringSpec<2>>& springKeys<2>();
template const KeyTable<SpringSpec<3>>& springKeys<3>();

}  // namespace num::app
