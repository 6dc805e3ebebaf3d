// The weakly-compressible fluid model: options -> equation terms, geometry -> particles.
//
// A fluid case is two descriptions:
//   FluidModel<Dim>     the physics: rest density, equation of state, sound speed, density by
//                       continuity (+ delta-SPH) or summation, laminar and artificial
//                       viscosity, particle shifting, body force (constant or of time), extra
//                       terms (heat, user terms), materials;
//   FluidGeometry<Dim>  (setup/fluid_geometry.hpp) the container box with its walls or
//                       periodic axes, fluid regions and solid bodies, on one lattice dx.
// and two functions:
//   makeFluidEquations(model, geometry)          -> EquationHolder<Dim> for the Solver;
//   makeFluidStorage(model, geometry, settings)  -> Storage<Dim> with every quantity set.
//
// Typical use (2D Poiseuille channel, periodic in x, walls at y = 0 and y = L):
// clang-format off
//     FluidModel<2> model;
//     model.viscosity = 1e-6;
//     model.maxVelocity = 2.5e-5;
//     model.bodyForce = constantForce(Vector<2>{{2e-4, 0}});
//     FluidGeometry<2> geo;
//     geo.domain.min = {{0, 0}};
//     geo.domain.max = {{4 * dx, L}};
//     geo.domain.periodic = {true, false};
//     geo.spacing = dx;
//     geo.fluid.push_back(FluidRegion<2>::filling(BoxOrBall<2>::box(geo.domain.min, geo.domain.max)));
//     Storage<2> storage = makeFluidStorage(model, geo, settings);
//     Solver<2> solver(scheduler, settings, makeFluidEquations(model, geo), geo.domain);
//     LeapfrogKDK<2> integrator;
//     Run<2> run(storage, solver, integrator);
//     run.advanceTo(t);
// clang-format on
//
// Quantities in the storage (types.hpp and terms/fluid_quantities.hpp):
//   POSITION (2nd order: x, v, a), MASS, DENSITY (1st order with continuity), PRESSURE,
//   TEMPERATURE, MATERIAL (int, index into storage.materials()), KIND (int ParticleKind:
//   FLUID, WALL, BODY, INLET, OUTLET), WALL_VELOCITY (boundary particles: prescribed surface
//   velocity; only where a boundary slides, absent means every boundary is held),
//   FluidId::PAIR_VELOCITY, FluidId::WALL_SLIP, FluidId::KINEMATIC_VISCOSITY,
//   heat_ids::BOUNDARY_TEMPERATURE.
// Boundary particles of walls and fixed bodies never move; those of moving bodies
// (model.movingBodies) move rigidly with their body; fluid particles never cross them. Inlet
// and outlet buffers (model.flowBoundaries) move with the flow; the run exchanges particles
// between them and the fluid after each step (FlowBoundaries::exchange).
//
// Order of the terms (each term's constrain, initialize, finalize and postStep run in this
// order; the tension limit's density floor acts in constrain, before every evaluation; particle
// shifting, containment and the heat books act in postStep, once per step after the integrator):
//   neighbour refresh (for the passes below) -> summation density -> equation of state ->
//   tension limit at free surfaces -> wall condition (Adami et al. 2012) -> wall temperature ->
//   outlet condition (inlets and outlets) -> continuity (+ delta-SPH) -> pressure gradient ->
//   laminar viscosity -> artificial viscosity
//   -> body force -> particle shifting -> model.extraTerms (e.g. heat) -> rigid body coupling
//   (moving bodies: their loads, motion and particles) -> boundary hold (zeroes boundary
//   accelerations) -> containment (no particle inside a wall or body).
#pragma once

#include <algorithm>
#include <functional>
#include <memory>
#include <numbers>
#include <vector>

#include "sph/bodies/body_coupling.hpp"
#include "sph/boundary/boundary_hold.hpp"
#include "sph/boundary/flow_boundaries.hpp"
#include "sph/boundary/generalized_wall.hpp"
#include "sph/boundary/particle_containment.hpp"
#include "sph/boundary/wall_temperature.hpp"
#include "sph/defaults.hpp"
#include "sph/equation_of_state_choice.hpp"
#include "sph/equation_term.hpp"
#include "sph/kernel_choice.hpp"
#include "sph/particle_order.hpp"
#include "sph/setup/fluid_geometry.hpp"
#include "sph/setup/particle_generation.hpp"
#include "sph/terms/artificial_viscosity.hpp"
#include "sph/terms/body_force.hpp"
#include "sph/terms/continuity_density.hpp"
#include "sph/terms/delta_sph.hpp"
#include "sph/terms/equation_of_state.hpp"
#include "sph/terms/free_surface.hpp"
#include "sph/terms/heat_model.hpp"
#include "sph/terms/laminar_viscosity.hpp"
#include "sph/terms/neighbour_gather.hpp"
#include "sph/terms/pair_inputs.hpp"
#include "sph/terms/particle_shifting.hpp"
#include "sph/terms/pressure_gradient.hpp"
#include "sph/terms/summation_density.hpp"

namespace num::sph {

enum class DensityMode { CONTINUITY, SUMMATION };

/// A body force (acceleration) of time.
template <int Dim>
using BodyForce = std::function<Vector<Dim>(Float t)>;

template <int Dim>
BodyForce<Dim> constantForce(const Vector<Dim>& g) {
    return [g](Float) { return g; };
}

/// g (1 - cos(pi t / T)) / 2 for t < T, then g: a smooth ramp that avoids a start-up shock.
template <int Dim>
BodyForce<Dim> rampedForce(const Vector<Dim>& g, Float rampTime) {
    return [g, rampTime](Float t) {
        if (t >= rampTime) return g;
        return g * (0.5 * (1 - std::cos(std::numbers::pi * std::max(t, 0.0) / rampTime)));
    };
}

template <int Dim>
struct FluidModel {
    using Vec = Vector<Dim>;

    // Equation of state.
    Float restDensity = defaults::density;  ///< rho0 [kg/m^3]
    Float soundSpeed = 0;  ///< c0 [m/s]; 0 derives c0 = soundSpeedFactor * maxVelocity
    Float maxVelocity = defaults::flowSpeed;  ///< the largest expected flow speed U [m/s]
    Float soundSpeedFactor = defaults::soundSpeedFactor;  ///< c0 = 10 U: density varies ~1 %
    EosType eos = defaultEos;
    Float taitExponent = defaults::taitExponent;
    Float backgroundPressure = 0;             ///< p_b [Pa], added to the equation of state
    Float maxTension = defaults::maxTension;  ///< [Pa]: p >= p_b - maxTension (cavitation)

    // Density.
    DensityMode density = DensityMode::CONTINUITY;
    Float deltaSph = defaults::densityDiffusion;  ///< delta-SPH's delta (continuity); 0: off
    bool deltaSphHydrostatic = true;  ///< remove the hydrostatic part from the diffusion

    // Viscosity (both may be on).
    Float viscosity = 0;            ///< kinematic nu of the laminar term [m^2/s]; 0: off
    Float artificialViscosity = 0;  ///< Monaghan's alpha; 0: off (defaults::artificialViscosityFor)

    // Particle regularity.
    bool shifting = defaults::shifting;  ///< particle shifting (terms/particle_shifting.hpp)
    Float shiftingCoefficient = defaults::shiftingCoefficient;     ///< A in dr = -A h c0 dt grad C
    bool shiftingNormalToWalls = defaults::shiftingNormalToWalls;  ///< shift towards walls too

    /// A tension limit at free surfaces: the density of a particle whose kernel support is cut
    /// held at or above freeSurfaceDensityFloor rho0 (terms/free_surface.hpp).
    bool freeSurfaceTensionLimit = defaults::freeSurfaceTensionLimit;
    Float freeSurfaceDensityFloor = defaults::freeSurfaceDensityFloor;

    // Forces.
    BodyForce<Dim> bodyForce;  ///< acceleration of time (gravity, a ramp); empty: none

    /// Keep fluid particles out of walls and bodies by reflection (a safety net).
    bool containParticles = true;

    /// The bodies of the geometry with their motions (sph/bodies/); empty: every body fixed.
    std::shared_ptr<MovingBodies<Dim>> movingBodies;

    /// The inlets and outlets (boundary/flow_boundaries.hpp); empty: none. Their sides'
    /// layers (FluidGeometry::walls[k][hi].layers) are INLET or OUTLET buffers.
    std::shared_ptr<FlowBoundaries<Dim>> flowBoundaries;

    /// Terms appended after the fluid terms, before boundaries are held and particles
    /// contained: heat conduction, buoyancy, user terms.
    EquationHolder<Dim> extraTerms;

    /// Heat: conduction, thermal walls and bodies, buoyancy, temperature-dependent viscosity
    /// (terms/heat_model.hpp). Everything off by default.
    HeatModel<Dim> heat;

    /// The storage's material table (MATERIAL indexes it); empty: one "water" made from the
    /// fields above.
    std::vector<std::shared_ptr<IMaterial>> materials;

    Float c0() const { return soundSpeed > 0 ? soundSpeed : soundSpeedFactor * maxVelocity; }

    EquationOfState equationOfState() const {
        return EquationOfState{eos, restDensity, c0(), taitExponent, backgroundPressure};
    }
    Vec bodyForceAt(Float t) const { return bodyForce ? bodyForce(t) : Vec{}; }
};

/// The built-in pair sums in one pass over the pairs (DerivativeHolder::fuse).
template <int Dim>
using BuiltInPairSums =
    FuseDerivatives<Dim, ContinuityDensityPart<Dim>, DeltaSphPart<Dim>, PressureGradientPart<Dim>,
                    ArtificialViscosityPart<Dim>, LaminarViscosityPart<Dim>,
                    HeatConductionDerivative<Dim>, KernelSumPart<Dim>, ParticleShiftingPart<Dim>>;

/// The fluid's equation terms, in the order described at the top of this file.
template <int Dim>
EquationHolder<Dim> makeFluidEquations(const FluidModel<Dim>& model,
                                       const FluidGeometry<Dim>& geometry);

/// The material table of a model's particles: its materials, or water of its rest density,
/// sound speed and viscosities when it names none.
template <int Dim>
std::vector<std::shared_ptr<IMaterial>> fluidMaterials(const FluidModel<Dim>& model) {
    if (!model.materials.empty()) return model.materials;
    auto water = std::make_shared<Material>("water");
    water->params()
        .set("density", model.restDensity)
        .set("sound_speed", model.c0())
        .set("viscosity", model.viscosity)
        .set("artificial_viscosity", model.artificialViscosity);
    return {water};
}

/// The particles of a geometry with every quantity the fluid terms use. Masses are
/// rho0 dx^Dim, densities rho0, pressures p(rho0), velocities from the fluid regions.
template <int Dim>
Storage<Dim> makeFluidStorage(const FluidModel<Dim>& model, const FluidGeometry<Dim>& geometry,
                              const RunSettings& settings) {
    using Vec = Vector<Dim>;
    const Float dx = geometry.spacing;
    const int layers = geometry.wallLayers > 0
                           ? geometry.wallLayers
                           : wallLayersFor(RunKernel<Dim>(settings).supportRadius(), dx);
    const auto particles = generateParticles(geometry, layers);
    const std::size_t n = particles.size();
    std::vector<Vec> x(n), v(n), wallVelocity(n);
    std::vector<Float> temperature(n);
    std::vector<int> material(n), kind(n), slip(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto& p = particles[i];
        x[i] = p.x, v[i] = p.v, wallVelocity[i] = p.wallVelocity;
        temperature[i] = p.temperature, material[i] = p.material;
        kind[i] = int(p.kind), slip[i] = int(p.slip);
    }
    const Float volume = std::pow(dx, Dim);
    const OrderEnum densityOrder =
        model.density == DensityMode::CONTINUITY ? OrderEnum::FIRST : OrderEnum::ZERO;

    Storage<Dim> s;
    s.template insert<Vec>(QuantityId::POSITION, OrderEnum::SECOND, std::move(x));
    std::copy(v.begin(), v.end(), s.template getDt<Vec>(QuantityId::POSITION).begin());
    s.template insert<Float>(QuantityId::MASS, OrderEnum::ZERO, model.restDensity * volume);
    s.template insert<Float>(QuantityId::DENSITY, densityOrder, model.restDensity);
    s.template insert<Float>(QuantityId::PRESSURE, OrderEnum::ZERO,
                             model.equationOfState().pressure(model.restDensity));
    // Until the wall condition mirrors it, every particle shows conduction its own temperature.
    s.template insert<Float>(heat_ids::BOUNDARY_TEMPERATURE, OrderEnum::ZERO, temperature);
    s.template insert<Float>(QuantityId::TEMPERATURE, OrderEnum::ZERO, std::move(temperature));
    s.template insert<int>(QuantityId::MATERIAL, OrderEnum::ZERO, std::move(material));
    s.template insert<int>(QuantityId::KIND, OrderEnum::ZERO, std::move(kind));
    // Only where a wall or body slides (a lid): held ones need no array (16 B a particle in 2D).
    if (std::any_of(wallVelocity.begin(), wallVelocity.end(),
                    [](const Vec& w) { return normSqr(w) != 0; }))
        s.template insert<Vec>(QuantityId::WALL_VELOCITY, OrderEnum::ZERO, wallVelocity);
    // Until the wall condition extrapolates it, a boundary particle shows its wall's velocity.
    s.template insert<Vec>(FluidId::PAIR_VELOCITY, OrderEnum::ZERO, std::move(wallVelocity));
    s.template insert<int>(FluidId::WALL_SLIP, OrderEnum::ZERO, std::move(slip));
    s.template insert<Float>(FluidId::KINEMATIC_VISCOSITY, OrderEnum::ZERO, model.viscosity);
    ensureParticleIds(s);
    s.materials() = fluidMaterials(model);
    // Quantities of optional and extra terms (shifting, heat...), with their defaults.
    makeFluidEquations(model, geometry).create(s, *s.materials().front());
    return s;
}

template <int Dim>
EquationHolder<Dim> makeFluidEquations(const FluidModel<Dim>& model,
                                       const FluidGeometry<Dim>& geometry) {
    const EquationOfState eos = model.equationOfState();
    const bool boundaries = geometry.hasBoundaries();
    const bool summation = model.density == DensityMode::SUMMATION;

    EquationHolder<Dim> eq = makeHeatPreEquations(model.heat);
    auto gather = std::make_shared<NeighbourGather<Dim>>();
    if (summation || boundaries) eq += makeTerm<NeighbourRefresh<Dim>>(gather);
    if (summation) eq += makeTerm<SummationDensity<Dim>>(gather);
    eq += makeTerm<EquationOfStateTerm<Dim>>(eos, model.maxTension);
    if (model.freeSurfaceTensionLimit)
        eq += makeTerm<FreeSurfaceTensionLimit<Dim>>(eos, model.freeSurfaceDensityFloor);
    if (boundaries) {
        auto nearFluid = std::make_shared<BoundaryNearFluid<Dim>>();
        eq += makeTerm<GeneralizedWall<Dim>>(gather, eos, model.bodyForce, nearFluid);
        eq += makeTerm<WallTemperature<Dim>>(gather, nearFluid);
        if (model.flowBoundaries)
            eq += makeTerm<OutletCondition<Dim>>(model.flowBoundaries, gather, eos);
    }
    eq += makeTerm<PairInputs<Dim>>();  // volumes and velocities the pair terms read
    if (!summation) {
        eq += makeTerm<ContinuityDensity<Dim>>();
        if (model.deltaSph > 0)
            eq += makeTerm<DeltaSph<Dim>>(
                model.deltaSph, model.restDensity, eos.c0,
                model.deltaSphHydrostatic ? model.bodyForce : BodyForce<Dim>{});
    }
    eq += makeTerm<PressureGradient<Dim>>();
    if (model.viscosity > 0) eq += makeTerm<LaminarViscosity<Dim>>(model.viscosity);
    if (model.artificialViscosity > 0)
        eq += makeTerm<ArtificialViscosity<Dim>>(model.artificialViscosity, eos.c0);
    if (model.bodyForce) eq += makeTerm<BodyForceTerm<Dim>>(model.bodyForce);
    if (model.shifting)
        eq += makeTerm<ParticleShifting<Dim>>(model.shiftingCoefficient, eos.c0,
                                              model.shiftingNormalToWalls);
    eq += makeHeatEquations(model.heat, model.bodyForce);
    eq += model.extraTerms;
    if (model.movingBodies)
        eq += makeTerm<RigidBodyCoupling<Dim>>(model.movingBodies, geometry.bodies, model.bodyForce,
                                               model.artificialViscosity, eos.c0, geometry.spacing);
    eq += makeTerm<BoundaryHold<Dim>>();
    if (model.containParticles && boundaries)
        eq += makeTerm<ParticleContainment<Dim>>(geometry, model.movingBodies);
    eq += makeTerm<BuiltInPairSums<Dim>>();
    return eq;
}

}  // namespace num::sph
