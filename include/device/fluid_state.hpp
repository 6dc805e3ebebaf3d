// What the device step of the weakly-compressible fluid needs to know (FluidStepConfig, plain
// data) and the particles it uploads and downloads (ParticleArrays, structure of arrays in the
// storage's order). Built from a FluidModel, its geometry and the run settings by
// device/fluid_run.hpp; read by the device step (device/fluid_step.hpp), which nvcc compiles:
// hence no dependence on Storage or the terms here.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "device/body_state.hpp"
#include "device/containment.hpp"
#include "sph/formulas/equation_of_state.hpp"
#include "sph/formulas/fluid_particles.hpp"
#include "sph/formulas/post_step.hpp"
#include "sph/kernel_choice.hpp"
#include "sph/setup/shapes.hpp"
#include "sph/types.hpp"

namespace num::device {

using sph::Float;
template <int Dim>
using Vector = num::Vec<double, Dim>;

/// A material's parameters the heat passes read (terms/thermal_properties.hpp's
/// ThermalMaterial and the material's viscosity), indexed by the particles' material index.
struct DeviceMaterial {
    Float conductivity = 0, heatCapacity = 1, density = 1, expansion = 0, referenceTemperature = 0,
          viscosity = 0;
};

template <int Dim>
struct FluidStepConfig {
    // Kernel.
    sph::KernelType kernel = sph::defaultKernel;
    Float h = 0, supportRadius = 0;
    Float w0 = 0;                                ///< W(0), for the free-surface test
    Float laplacianEta2 = 0, inverseR2Eta2 = 0;  ///< eta^2 of the two pair factors [m^2]
    // Equation of state, tension limits.
    sph::EquationOfState eos;
    Float pMin = 0;  ///< p_b - T_max
    bool tensionLimit = false;
    Float surfaceRhoMin = 0, surfacePMin = 0;  ///< f rho0 and p(f rho0)
    // Terms.
    bool summation = false;      ///< density by summation (no continuity, no delta-SPH)
    bool walls = false;          ///< the wall condition (any wall or body)
    Float deltaCoefficient = 0;  ///< 2 delta h c0; 0: no delta-SPH
    bool deltaHydrostatic = false;
    Float alphaC0h = 0;  ///< alpha c0 h of the artificial viscosity; 0: off
    bool laminar = false;
    bool shifting = false;
    Float shiftingCoefficient = 0;
    bool shiftingNormalToWalls = false;
    bool contain = false;                         ///< containment in the box's walls
    bool wallLow[Dim] = {}, wallHigh[Dim] = {};   ///< which box sides are walls
    ContainmentSolids<Dim> solids;                ///< the bodies and interior walls (containment)
    std::function<Vector<Dim>(Float)> bodyForce;  ///< empty: none
    // Moving bodies (host side, device/body_run.hpp: null when none moves): the run's bodies,
    // which the host advances, and the particle spacing of their contacts.
    std::shared_ptr<sph::MovingBodies<Dim>> movingBodies;
    Float spacing = 0;
    // Inlets and outlets (boundary/flow_boundaries.hpp): each side's outlet opening, which the
    // containment lets fluid through, and the outlets' pressure p_out(x, t), an expression of
    // the scene evaluated on the host (empty: no outlet).
    sph::formulas::OutletOpening<Dim> outlets[Dim][2] = {};
    std::function<Float(const Vector<Dim>&, Float)> outletPressure;
    // Heat (terms/heat_model.hpp).
    bool conduction = false;  ///< conduction with the thermal conditions of walls and bodies
    bool buoyancy = false;    ///< Boussinesq buoyancy with the body force as g
    bool temperatureViscosity = false;
    sph::ViscosityOfTemperature viscosityLaw{};
    std::vector<DeviceMaterial> materials;  ///< the storage's material table
    Float diffusionFactor = 0;              ///< RunSettings diffusion_factor
    bool heat() const { return conduction || buoyancy || temperatureViscosity; }
    // Domain.
    Vector<Dim> domainMin{}, domainMax{};
    bool periodic[Dim] = {};
    // Time step (RunSettings of the same names).
    Float dtFixed = 0, dtMax = 0, accelerationFactor = 0, cfl = 0, viscousFactor = 0;
};

/// The particles in the storage's order, as structure of arrays.
template <int Dim>
struct ParticleArrays {
    using Vec = Vector<Dim>;
    // The state a step starts from (uploaded).
    std::vector<Vec> x, v, a;
    std::vector<Float> m, rho, drho, p, nu, kernelSum, surfaceNeighbours;
    std::vector<int> kind, slip;
    std::vector<Vec> wallVelocity;  ///< empty: every boundary is held
    // Moving bodies (empty without): BODY_INDEX, BODY_OFFSET, and the particle's rank among the
    // moving particles (-1: not moving), where the device leaves its load (device/body_step.hpp).
    std::vector<int> body, bodySlot;
    std::vector<Vec> bodyOffset;
    // Heat (empty without): temperature and its rate, the temperature shown to conduction
    // (heat_ids::BOUNDARY_TEMPERATURE), heat source [W/kg], material, thermal condition.
    std::vector<Float> T, dT, Tb, heatSource;
    std::vector<int> material, condition;
    // What an evaluation leaves (downloaded with the state).
    std::vector<Float> volume;
    std::vector<Vec> pairVelocity, kernelSumGradient, densityGradient, wallDirection;
    std::array<std::vector<Vec>, Dim> velocityGradient;
    std::size_t size() const { return x.size(); }
};

/// The maxima the time-step criteria need, reduced on the device.
struct StepMaxima {
    Float acceleration2 = 0;  ///< max |a|^2 over every particle
    Float fluidSpeed2 = 0;    ///< max |v|^2 over the fluid
    Float viscosity = 0;      ///< max nu (laminar viscosity on)
    Float diffusivity = 0;    ///< max k / (rho c) of the particles that conduct (conduction on)
};

/// The heat books' powers of an evaluation [W] (boundary/thermal_walls.hpp's WallHeatBooks).
struct HeatPowers {
    Float fixed = 0;   ///< given by fixed-temperature particles to the others
    Float source = 0;  ///< added by heat sources and flux walls
};

}  // namespace num::device

namespace num::device {

/// The device step of one execution (device/fluid_step.hpp), behind an interface that needs no
/// CUDA header: the apps drive the CUDA one, the tests the host one (device/fluid_run.hpp).
template <int Dim>
class IDeviceFluid {
  public:
    virtual ~IDeviceFluid() = default;
    /// Copies the particles to the execution's memory (in the storage's order).
    virtual void upload(const ParticleArrays<Dim>& particles) = 0;
    /// Copies them back, in the storage's order.
    virtual void download(ParticleArrays<Dim>& particles) = 0;
    /// Evaluates every rate at time t.
    virtual void evaluate(Float t) = 0;
    /// The maxima of the time-step criteria at the current state.
    virtual StepMaxima maxima() = 0;
    /// The heat books' powers at the last evaluation (zero without conduction).
    virtual HeatPowers heatPowers() = 0;
    /// The box that holds every fluid particle now.
    virtual sph::FluidExtent<Dim> fluidExtent() = 0;
    /// The leapfrog from t to t + dt: kick-drift, evaluate at t + dt, kick.
    virtual void advance(Float t, Float dt) = 0;
    /// The post-step phase of a step of dt: shifting, the moving bodies' particles placed,
    /// containment.
    virtual void postStep(Float dt) = 0;
    /// The moving bodies' frames and contact data (before the first evaluation, after each
    /// advance of the bodies).
    virtual void setBodies(const DeviceBodies<Dim>& bodies) = 0;
    /// The moving particles' loads of the last evaluation (device/body_state.hpp).
    virtual void bodyLoads(BodyLoads<Dim>& loads) = 0;
    virtual std::size_t size() const = 0;
    /// Memory the step holds in its execution [bytes].
    virtual std::size_t bytes() const = 0;
    virtual const char* execution() const = 0;
};

}  // namespace num::device
