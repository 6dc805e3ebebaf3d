// A scene as read from its JSON file (format: docs/scenes.md). Plain data; loadScene() checks
// every key, type and range, and the geometry, so whatever reaches the simulation is valid.
#pragma once

#include <algorithm>
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/errors.hpp"
#include "app/expression.hpp"
#include "geometry/solid.hpp"
#include "spatial/vec.hpp"
#include "sph/bodies/rigid_body.hpp"
#include "sph/boundary/side_boundary.hpp"
#include "sph/boundary/wall_boundary.hpp"
#include "sph/defaults.hpp"

namespace num::app {

/// The largest sound speed a scene may give or derive [m/s] ("auto" is 10 times the velocity
/// scale, so physics.max_speed is at most a tenth of it).
inline constexpr double kMaxSoundSpeed = 1e6;

template <int Dim>
using SceneVec = Vec<double, Dim>;

/// One component per axis, each a number or an expression in x, y, z, t.
template <int Dim>
using VectorField = std::array<Expression, Dim>;

/// One side of the domain box: its boundary type's module with the side's parameters
/// (sph/boundary/side_boundary.hpp; the types: src/scene/boundary_types.cpp).
template <int Dim>
using SideBoundary = std::shared_ptr<const sph::ISideBoundary<Dim>>;

struct MaterialSpec {
    std::string name;
    double density = sph::defaults::density, viscosity = sph::defaults::viscosity;
    std::optional<double> artificialViscosity;  ///< empty: "auto" (sph::defaults)
    std::optional<double> soundSpeed;           ///< empty: "auto"
    double conductivity = sph::defaults::conductivity;
    double heatCapacity = sph::defaults::heatCapacity, thermalExpansion = 0;
    double referenceTemperature = sph::defaults::referenceTemperature;
};

/// A box or ball (min, max; center, radius: the set-up's fast path, which the CUDA back end
/// runs too) or any other shape (SOLID: `solid`, include/geometry/; docs/geometry.md).
enum class ShapeKind { BOX, CIRCLE, SPHERE, SOLID };

/// A shape as a scene gives it (fluid blocks, bodies, walls).
template <int Dim>
struct SceneShape {
    ShapeKind shape = ShapeKind::BOX;
    SceneVec<Dim> min{}, max{}, center{};  ///< a box's corners; a ball's centre
    double radius = 0;
    geometry::SolidPtr<Dim> solid;  ///< the shape when it is SOLID

    /// The engine's shape: the box or ball, or the solid.
    sph::PlacedShape<Dim> placed() const {
        sph::PlacedShape<Dim> p;
        if (shape == ShapeKind::SOLID)
            p.solid = solid, p.solidBounds = solid->bounds();
        else
            p.shape = shape == ShapeKind::BOX ? sph::BoxOrBall<Dim>::box(min, max)
                                              : sph::BoxOrBall<Dim>::ball(center, radius);
        return p;
    }
};

template <int Dim>
struct FluidBlock : SceneShape<Dim> {
    std::string material;
    Expression temperature{sph::defaults::temperature}, pressure{0.0};
    VectorField<Dim> velocity{};
};

/// A spring or mooring line from an anchor, fixed or on another body, to a point of a moving
/// body (bodies[i].motion.springs).
template <int Dim>
struct SpringSpec {
    SceneVec<Dim> anchor{};  ///< at t = 0
    int anchorBody = -1;     ///< the index of the body that holds the anchor; -1: none (fixed)
    std::optional<SceneVec<Dim>> point;  ///< on the body at t = 0; empty: its reference point
    double stiffness = 0, damping = 0;
    std::optional<double> length;  ///< rest length; empty: the distance at t = 0
    bool mooring = false;          ///< pulls only when longer than its rest length
};

/// How a body moves (bodies[i].motion). Free: pushed by the fluid, gravity and springs;
/// prescribed: velocity and angular velocity of t given.
template <int Dim>
struct BodyMotionSpec {
    static constexpr int spinDim = Dim == 2 ? 1 : 3;
    sph::MotionType type = sph::MotionType::FIXED;
    double density = 0, mass = 0;               ///< free: one of the two is given, the other is 0
    std::optional<SceneVec<Dim>> centerOfMass;  ///< free; empty: the shape's centroid
    std::vector<double> inertia;  ///< free; empty: the shape's; 1 number (2D), 3 or 9 (3D)
    VectorField<Dim> velocity{};  ///< free: initial (numbers); prescribed: of t
    std::array<Expression, spinDim> angularVelocity{};  ///< [rad/s], as velocity
    std::optional<SceneVec<Dim>> center;  ///< prescribed: the centre of rotation at t = 0
    std::optional<SceneVec<Dim>> hinge;   ///< free: the hinge's point at t = 0
    int hingeBody = -1;             ///< free: the index of the body it is hinged on; -1: the world
    SceneVec<spinDim> hingeAxis{};  ///< free, 3D: the hinge's axis (default z)
    std::vector<std::string> locked;  ///< free: x, y, (z), rotation (2D) or rx, ry, rz
    std::vector<SpringSpec<Dim>> springs;
    double friction = 0.3;  ///< free: Coulomb coefficient of its contacts
};

template <int Dim>
struct Body : SceneShape<Dim> {
    double temperature = sph::defaults::temperature;
    std::string material;  ///< empty: held at `temperature`; else conducting with this material
    std::string name;      ///< empty: "bodies[i]"
    BodyMotionSpec<Dim> motion;
};

/// A wall inside the domain (scene key "walls"): a shape whose surface layer is made of wall
/// particles, with a box side's wall keys (velocity, slip, thermal: its module).
template <int Dim>
struct Wall : SceneShape<Dim> {
    std::shared_ptr<const sph::WallBoundary<Dim>> boundary;
};

template <int Dim>
struct Emitter {
    std::string name, material;
    SceneVec<Dim> position{}, direction{};
    double speed = sph::defaults::emitterSpeed, radius = sph::defaults::emitterRadius;
    double temperature = sph::defaults::temperature, start = 0, end = 1e300;
};

template <int Dim>
struct Probe {
    std::string name;
    SceneVec<Dim> point{};
    int body = -1;  ///< the body whose force the probe records; -1: none
    int wall = -1;  ///< the interior wall whose force the probe records; -1: none (a point)
    int side = -1;  ///< the box side (2 axis + high) whose flow rate it records; -1: none
    std::vector<std::string> fields;
};

struct OutputSpec {
    std::string directory = "out/scene";
    std::string prefix = "particles";
    double every = 0.05;
    /// Seconds of simulated time between probe samples (output.probes_every); empty: the
    /// default, probeInterval(). Probes sample at the first step that reaches each multiple.
    std::optional<double> probesEvery;
    /// Names of writers (app/writer_registry.hpp), each listed once, in the scene's order.
    std::vector<std::string> formats = {"vtu"};
    bool images = true, video = true;
    int imageWidth = 960;
    std::optional<double> colorMin, colorMax;  ///< colour-bar range; empty: from the scene
    /// Formats of the plots drawn after the run (output.plots): "png", "svg"; empty: none.
    std::vector<std::string> plots = {"png"};

    /// The probes' sampling interval: output.probes_every, else 1 ms, or output.every where
    /// that is shorter (probes never sampled less often than the outputs).
    double probeInterval() const { return probesEvery.value_or(std::min(1e-3, every)); }
};

struct PhysicsSpec {
    bool heat = true, buoyancy = true;
    /// auto, continuity or summation; auto: summation under gravity in a box that is closed by
    /// walls on every side and filled with fluid (no free surface, bodies or emitters), else
    /// continuity
    std::string density = sph::defaults::densityMode;
    double densityDiffusion = sph::defaults::densityDiffusion;  ///< delta-SPH's delta
    bool shifting = sph::defaults::shifting;
    bool shiftingNormalToWalls = sph::defaults::shiftingNormalToWalls;
    bool freeSurfaceTensionLimit = sph::defaults::freeSurfaceTensionLimit;
    double freeSurfaceDensityFloor = sph::defaults::freeSurfaceDensityFloor;  ///< over rho0
    double gravityRamp = 0;                         ///< seconds over which gravity rises from 0
    std::string eos = sph::defaults::eos;           ///< tait or linear
    double backgroundPressure = 0;                  ///< [Pa]
    double maxTension = sph::defaults::maxTension;  ///< [Pa], before the liquid cavitates
    double maxSpeed = 0;  ///< velocity scale for "auto" sound speeds [m/s] (0: estimated)
};

/// The scene's `particles` section.
struct ParticleSpec {
    double spacing = sph::defaults::spacing, hOverSpacing = sph::defaults::hOverSpacing;
    std::string kernel = sph::defaults::kernel;
    std::string evaluation = sph::defaults::evaluation;  ///< the pair loop: asymmetric or symmetric
};

/// The scene's `time` section.
struct TimeSpec {
    double endTime = sph::defaults::endTime, cfl = sph::defaults::cfl, dtMax = 0;
    std::string integrator = sph::defaults::integrator;
};

/// The scene's `numerics` section.
struct NumericsSpec {
    std::string backend = sph::defaults::backend;  ///< cpu or cuda (--backend overrides it)
};

/// A scene as read (docs/scenes.md); the sections of plain values are its bases.
template <int Dim>
struct Scene : ParticleSpec, TimeSpec, NumericsSpec {
    std::string file;  ///< where it was read from (for messages)
    std::string name;
    SceneVec<Dim> domainMin{}, domainMax{};
    std::array<std::array<SideBoundary<Dim>, 2>, Dim> sides{};  ///< [axis][0 = low, 1 = high]
    VectorField<Dim> gravity{};
    std::map<std::string, MaterialSpec> materials;
    std::vector<FluidBlock<Dim>> fluids;
    std::vector<Body<Dim>> bodies;
    std::vector<Wall<Dim>> walls;  ///< walls inside the domain
    std::vector<Emitter<Dim>> emitters;
    OutputSpec output;
    std::vector<Probe<Dim>> probes;
    PhysicsSpec physics;
    std::vector<std::string> warnings;  ///< likely mistakes that are still valid scenes
};

/// Names of the sides of the box: the axis and its low or high end (x_min ... z_max), the same
/// in 2D and 3D whatever the direction of gravity.
inline const char* sideName(int axis, int high) {
    static const char* names[3][2] = {{"x_min", "x_max"}, {"y_min", "y_max"}, {"z_min", "z_max"}};
    return names[axis][high];
}

}  // namespace num::app
