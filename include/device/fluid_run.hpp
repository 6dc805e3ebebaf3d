// The host side of the device step (plain C++; the apps and the tests use it): what a fluid
// model must leave out to run on the device, its FluidStepConfig, the copies between a Storage
// and the device step, and DeviceRun, sph::Run's step (timestepping.hpp) over a device step:
// the adaptive step from the same criteria (sph/formulas/time_step.hpp, from maxima reduced on
// the device, offered in the CPU solver's order, the diffusion limit of conduction last), the
// leapfrog (sph/formulas/leapfrog.hpp), the post-step phase with the moving bodies advanced on
// the host (device/body_run.hpp). The apps' step loop is Simulation's
// (src/run/engine.hpp: the device engine). The heat books of thermal_walls.hpp (heat delivered by
// fixed temperatures and sources) are not kept on the device.
#pragma once

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "device/body_run.hpp"
#include "device/containment_setup.hpp"
#include "device/device_terms.hpp"
#include "device/fluid_step_on.hpp"
#include "sph/defaults.hpp"
#include "sph/fluid_model.hpp"
#include "sph/formulas/time_step.hpp"
#include "sph/scheduler.hpp"
#include "sph/timestepping.hpp"

namespace num::device {

/// What of a fluid model the device step does not run yet, as "what (why)", or "" when it runs
/// all of it. Checked before anything is uploaded. The terms come from the model's own CPU
/// equations (device_terms.hpp); the geometry and the settings the device step reads are checked
/// here.
template <int Dim>
std::string unsupported(const sph::FluidModel<Dim>& model, const sph::FluidGeometry<Dim>& geometry,
                        const sph::RunSettings& settings) {
    if (const std::string term = firstTermNotOnDevice(sph::makeFluidEquations(model, geometry));
        !term.empty())
        // A plugin's term is named `term "spring" (plugins.0.terms.0, libx.so)` already.
        return term.starts_with("term \"") ? term : "the equation term \"" + term + "\"";
    if (const std::string solid = firstSolidNotOnDevice(geometry); !solid.empty())
        return "the shape of " + solid + " (a mesh, or a solid flatten() does not take)";
    if (sph::evaluationFromName(settings.get<std::string>("evaluation")) ==
        sph::Evaluation::SYMMETRIC)
        return "symmetric evaluation";
    return "";
}

/// The outlets' openings and pressure (inlets need nothing: the host sets their particles'
/// velocity and temperature after every step, FlowBoundaries::exchange).
template <int Dim>
void setFlowSides(FluidStepConfig<Dim>& c, const sph::FluidModel<Dim>& model,
                  const sph::FluidGeometry<Dim>& geometry) {
    const std::shared_ptr<const sph::FlowBoundaries<Dim>> flow = model.flowBoundaries;
    if (!flow) return;
    bool outlets = false;
    for (int k = 0; k < Dim; ++k)
        for (int hi = 0; hi < 2; ++hi) {
            const sph::WallSide<Dim>& side = geometry.walls[k][hi];
            if (!geometry.hasWall(k, hi) || side.layers != sph::ParticleKind::OUTLET) continue;
            c.outlets[k][hi] = {true, side.openFrom, side.openTo};
            outlets = true;
        }
    if (outlets)
        c.outletPressure = [flow](const Vector<Dim>& x, Float t) {
            return flow->sides[flow->sideOf(x, sph::ParticleKind::OUTLET)].pressure(x, t);
        };
}

template <int Dim>
FluidStepConfig<Dim> makeFluidStepConfig(const sph::FluidModel<Dim>& model,
                                         const sph::FluidGeometry<Dim>& geometry,
                                         const sph::RunSettings& settings) {
    FluidStepConfig<Dim> c;
    const sph::RunKernel<Dim> kernel(settings);
    c.kernel = kernel.type, c.h = kernel.h, c.supportRadius = kernel.supportRadius();
    c.w0 = kernel.W(0);
    c.laplacianEta2 = sph::defaults::laplacianEta2 * c.h * c.h;
    c.inverseR2Eta2 = sph::defaults::inverseR2Eta2 * c.h * c.h;
    c.eos = model.equationOfState();
    c.pMin = c.eos.backgroundPressure - model.maxTension;
    c.tensionLimit = model.freeSurfaceTensionLimit;
    c.surfaceRhoMin = model.freeSurfaceDensityFloor * c.eos.rho0;
    c.surfacePMin = c.eos.pressure(c.surfaceRhoMin);
    bool boundaries = !geometry.bodies.empty() || !geometry.interiorWalls.empty();
    for (int k = 0; k < Dim; ++k) {
        c.wallLow[k] = geometry.hasWall(k, 0), c.wallHigh[k] = geometry.hasWall(k, 1);
        boundaries |= c.wallLow[k] || c.wallHigh[k];
        c.domainMin[k] = geometry.domain.min[k], c.domainMax[k] = geometry.domain.max[k];
        c.periodic[k] = geometry.domain.periodic[k];
    }
    c.walls = boundaries;
    c.summation = model.density == sph::DensityMode::SUMMATION;
    c.deltaCoefficient = model.deltaSph > 0 && !c.summation
                             ? sph::formulas::deltaSphCoefficient(model.deltaSph, c.eos.c0, c.h)
                             : 0.0;
    c.deltaHydrostatic = model.deltaSphHydrostatic;
    c.alphaC0h = model.artificialViscosity > 0 ? model.artificialViscosity * c.eos.c0 * c.h : 0;
    c.laminar = model.viscosity > 0;
    c.shifting = model.shifting;
    c.shiftingCoefficient = model.shiftingCoefficient;
    c.shiftingNormalToWalls = model.shiftingNormalToWalls;
    c.contain = model.containParticles && boundaries;
    if (model.movingBodies && model.movingBodies->anyMoves())
        c.movingBodies = model.movingBodies, c.spacing = geometry.spacing;
    c.solids = containmentSolids(geometry, c.movingBodies.get());
    setFlowSides(c, model, geometry);
    c.bodyForce = model.bodyForce;
    c.conduction = model.heat.conduction;
    c.buoyancy = model.heat.buoyancy && bool(model.bodyForce);  // as makeHeatEquations
    c.temperatureViscosity = model.heat.temperatureViscosity;
    c.viscosityLaw = model.heat.viscosityLaw;
    if (c.heat()) {  // the storage's table: the model's materials (makeFluidStorage)
        const auto materials = sph::fluidMaterials(model);
        const std::vector<sph::ThermalMaterial> table = sph::thermalMaterials(materials);
        for (std::size_t k = 0; k < table.size(); ++k) {
            const sph::ThermalMaterial& t = table[k];
            c.materials.push_back(DeviceMaterial{
                t.conductivity, t.heatCapacity, t.density, t.expansion, t.referenceTemperature,
                c.temperatureViscosity ? materials[k]->params().template get<double>("viscosity")
                                       : 0.0});
        }
    }
    c.diffusionFactor = settings.get<double>("diffusion_factor");
    c.dtFixed = settings.get<double>("dt_fixed"), c.dtMax = settings.get<double>("dt_max");
    c.accelerationFactor = settings.get<double>("acceleration_factor");
    c.cfl = settings.get<double>("cfl"), c.viscousFactor = settings.get<double>("viscous_factor");
    return c;
}

namespace detail {
template <class T, int Dim>
std::vector<T> valuesOr(const sph::Storage<Dim>& s, sph::QuantityId id, T otherwise) {
    if (!s.has(id)) return std::vector<T>(s.size(), otherwise);
    const auto v = s.template getValue<T>(id);
    return std::vector<T>(v.begin(), v.end());
}
template <class T, int Dim>
void store(sph::Storage<Dim>& s, sph::QuantityId id, const std::vector<T>& from) {
    if (!s.has(id)) return;
    auto to = s.template getValue<T>(id);
    std::copy(from.begin(), from.end(), to.begin());
}
}  // namespace detail

/// The particles of a storage the device step starts from.
template <int Dim>
ParticleArrays<Dim> particleArrays(const sph::Storage<Dim>& s) {
    namespace FluidId = sph::FluidId;
    using sph::QuantityId;
    using Vec = Vector<Dim>;
    ParticleArrays<Dim> p;
    const auto x = s.template getValue<Vec>(QuantityId::POSITION);
    const auto v = s.template getDt<Vec>(QuantityId::POSITION);
    const auto a = s.template getD2t<Vec>(QuantityId::POSITION);
    p.x.assign(x.begin(), x.end()), p.v.assign(v.begin(), v.end()), p.a.assign(a.begin(), a.end());
    p.m = detail::valuesOr<Float>(s, QuantityId::MASS, 0.0);
    p.rho = detail::valuesOr<Float>(s, QuantityId::DENSITY, 0.0);
    if (s.order(QuantityId::DENSITY) >= sph::OrderEnum::FIRST) {
        const auto drho = s.template getDt<Float>(QuantityId::DENSITY);
        p.drho.assign(drho.begin(), drho.end());
    } else {  // density by summation: no rate
        p.drho.assign(s.size(), 0.0);
    }
    p.p = detail::valuesOr<Float>(s, QuantityId::PRESSURE, 0.0);
    p.nu = detail::valuesOr<Float>(s, FluidId::KINEMATIC_VISCOSITY, 0.0);
    p.kernelSum = detail::valuesOr<Float>(s, FluidId::KERNEL_SUM, 1.0);
    p.surfaceNeighbours = detail::valuesOr<Float>(s, FluidId::SURFACE_NEIGHBOURS, 0.0);
    p.kind = detail::valuesOr<int>(s, QuantityId::KIND, int(sph::ParticleKind::FLUID));
    p.slip = detail::valuesOr<int>(s, FluidId::WALL_SLIP, int(sph::WallSlip::NO_SLIP));
    if (s.has(QuantityId::WALL_VELOCITY))
        p.wallVelocity = detail::valuesOr<Vec>(s, QuantityId::WALL_VELOCITY, Vec{});
    p.pairVelocity = detail::valuesOr<Vec>(s, FluidId::PAIR_VELOCITY, Vec{});
    if (s.has(QuantityId::TEMPERATURE) &&
        s.order(QuantityId::TEMPERATURE) >= sph::OrderEnum::FIRST) {
        p.T = detail::valuesOr<Float>(s, QuantityId::TEMPERATURE, 0.0);
        const auto dT = s.template getDt<Float>(QuantityId::TEMPERATURE);
        p.dT.assign(dT.begin(), dT.end());
        p.Tb = s.has(sph::heat_ids::BOUNDARY_TEMPERATURE)
                   ? detail::valuesOr<Float>(s, sph::heat_ids::BOUNDARY_TEMPERATURE, 0.0)
                   : p.T;
        p.heatSource = detail::valuesOr<Float>(s, sph::heat_ids::HEAT_SOURCE, 0.0);
        p.material = detail::valuesOr<int>(s, QuantityId::MATERIAL, 0);
        p.condition = detail::valuesOr<int>(s, sph::heat_ids::THERMAL_CONDITION,
                                            int(sph::ThermalCondition::CONDUCTING));
    }
    return p;
}

/// Writes what the device step changes back into the storage it started from.
template <int Dim>
void copyBack(const ParticleArrays<Dim>& p, sph::Storage<Dim>& s) {
    namespace FluidId = sph::FluidId;
    using sph::QuantityId;
    using Vec = Vector<Dim>;
    auto copy = [](const auto& from, auto to) { std::copy(from.begin(), from.end(), to.begin()); };
    copy(p.x, s.template getValue<Vec>(QuantityId::POSITION));
    copy(p.v, s.template getDt<Vec>(QuantityId::POSITION));
    copy(p.a, s.template getD2t<Vec>(QuantityId::POSITION));
    copy(p.rho, s.template getValue<Float>(QuantityId::DENSITY));
    if (s.order(QuantityId::DENSITY) >= sph::OrderEnum::FIRST)
        copy(p.drho, s.template getDt<Float>(QuantityId::DENSITY));
    detail::store(s, QuantityId::PRESSURE, p.p);
    detail::store(s, FluidId::KERNEL_SUM, p.kernelSum);
    detail::store(s, FluidId::SURFACE_NEIGHBOURS, p.surfaceNeighbours);
    detail::store(s, FluidId::VOLUME, p.volume);
    detail::store(s, FluidId::PAIR_VELOCITY, p.pairVelocity);
    if (!p.wallVelocity.empty()) detail::store(s, QuantityId::WALL_VELOCITY, p.wallVelocity);
    detail::store(s, FluidId::KERNEL_SUM_GRADIENT, p.kernelSumGradient);
    detail::store(s, FluidId::DENSITY_GRADIENT, p.densityGradient);
    detail::store(s, FluidId::WALL_DIRECTION, p.wallDirection);
    for (int b = 0; b < Dim; ++b)
        detail::store(s, sph::velocityGradientId<Dim>(b), p.velocityGradient[b]);
    if (!p.nu.empty()) detail::store(s, FluidId::KINEMATIC_VISCOSITY, p.nu);
    if (!p.T.empty()) {
        copy(p.T, s.template getValue<Float>(QuantityId::TEMPERATURE));
        copy(p.dT, s.template getDt<Float>(QuantityId::TEMPERATURE));
        detail::store(s, sph::heat_ids::BOUNDARY_TEMPERATURE, p.Tb);
    }
}

/// The device step on the host execution (tests; a reference for the CUDA one).
template <int Dim>
using HostFluidStep = FluidStepOn<Dim, HostExecution>;

/// sph::Run's step over a device step: particles uploaded once, copied back only when asked
/// (outputs, probes, checkpoints).
template <int Dim>
class DeviceRun : public sph::StepClock {
  public:
    using Size = sph::Size;
    DeviceRun(std::unique_ptr<IDeviceFluid<Dim>> fluid, const FluidStepConfig<Dim>& config,
              Float t0 = 0)
        : sph::StepClock(t0), fluid_(std::move(fluid)), config_(config) {
        if (config.movingBodies)
            bodies_.emplace(config.movingBodies, config.bodyForce, config.eos.c0, config.spacing);
    }

    /// Copies the storage's particles to the device. primed: its rates are those at the
    /// current time (a restart), so the first step needs no evaluation first.
    void upload(const sph::Storage<Dim>& s, bool primed) {
        ParticleArrays<Dim> p = particleArrays(s);
        if (bodies_) bodies_->addParticles(s, p);
        fluid_->upload(p);
        if (bodies_) fluid_->setBodies(bodies_->deviceBodies());
        primed_ = primed;
        limits_.reset();
    }
    /// Copies the particles back into the storage they came from.
    void download(sph::Storage<Dim>& s) {
        ParticleArrays<Dim> p;
        fluid_->download(p);
        copyBack(p, s);
    }
    void prime() {
        fluid_->evaluate(time());
        takeBodyLoads();
        primed_ = true;
        limits_.reset();
    }

    /// The limits of the next step, offered as the CPU solver offers them (reduced on the
    /// device once per state).
    sph::TimeStepLimits timeStepLimits() {
        if (!limits_) limits_ = computeLimits();
        return *limits_;
    }

    /// One step, at most up to tEnd (sph::Run::step). Returns the step taken.
    Float step(Float tEnd = std::numeric_limits<Float>::infinity()) {
        if (!primed_) prime();
        const sph::PlannedStep planned = plan(timeStepLimits(), tEnd);
        limits_.reset();
        fluid_->advance(time(), planned.dt);
        takeBodyLoads();
        count(planned, tEnd);
        if (bodies_) {  // RigidBodyCoupling::postStep at the new time, after shifting
            bodies_->advance(time(), planned.dt);
            fluid_->setBodies(bodies_->deviceBodies());
        }
        fluid_->postStep(planned.dt);
        return planned.dt;
    }

    IDeviceFluid<Dim>& fluid() { return *fluid_; }

  private:
    /// The moving bodies' loads of the last evaluation (RigidBodyCoupling's finalize).
    void takeBodyLoads() {
        if (!bodies_) return;
        fluid_->bodyLoads(loads_);
        bodies_->takeLoads(loads_);
    }

    sph::TimeStepLimits computeLimits() {
        sph::TimeStepLimits limits(sequential_);
        if (config_.dtFixed > 0) {
            limits.offer("fixed", config_.dtFixed);
            return limits;
        }
        const StepMaxima m = fluid_->maxima();
        limits.offer("dt_max", config_.dtMax);
        const Float h = config_.h;
        if (m.acceleration2 > 0)
            limits.offer("acceleration", sph::formulas::accelerationStep(config_.accelerationFactor,
                                                                         h, m.acceleration2));
        limits.offer("courant",
                     sph::formulas::courantStep(config_.cfl, h, config_.eos.c0, m.fluidSpeed2));
        if (config_.laminar && m.viscosity > 0)
            limits.offer("viscous",
                         sph::formulas::viscousStep(config_.viscousFactor, h, m.viscosity));
        if (config_.conduction && m.diffusivity > 0)
            limits.offer("diffusion",
                         sph::formulas::diffusionStep(config_.diffusionFactor, h, m.diffusivity));
        return limits;
    }

    std::unique_ptr<IDeviceFluid<Dim>> fluid_;
    FluidStepConfig<Dim> config_;
    sph::SequentialScheduler sequential_;
    bool primed_ = false;
    std::optional<sph::TimeStepLimits> limits_;  ///< of the current state
    std::optional<DeviceBodyRun<Dim>> bodies_;   ///< moving bodies (none: empty)
    BodyLoads<Dim> loads_;
};

}  // namespace num::device
