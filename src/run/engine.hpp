// What steps a Simulation's particles (internal to numerics_app): the CPU engine (cpu_engine.hpp:
// the solver's terms on the CPU's threads, in the host's storage) or the device engine
// (device_backend.hpp: the CUDA back end, the particles on the GPU and copied to the host's
// storage when asked). Simulation holds one and never asks which; the step loop, the landing on
// output times and every observer are the same for both.
#pragma once

#include <cstddef>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "sph/boundary/thermal_walls.hpp"
#include "sph/decomposition.hpp"
#include "sph/timestepping.hpp"

namespace num::app {

template <int Dim>
class IEngine {
  public:
    virtual ~IEngine() = default;

    /// The time, the steps, the last step's dt and what limited it.
    virtual const sph::StepClock& clock() const = 0;
    /// The first evaluation of the host's particles (a new run).
    virtual void prime() = 0;
    /// Continues from a checkpoint at time t after `steps` steps; the host's particles hold
    /// the rates at t.
    virtual void resume(double t, sph::Size steps) = 0;
    /// The step the time-step criteria allow now.
    virtual double allowedStep() = 0;
    /// One step, at most up to `target`; returns its dt. The host's particles may then be out
    /// of date until copyToHost.
    virtual double step(double target) = 0;
    /// Brings the host's particles up to date.
    virtual void copyToHost() = 0;
    /// Whether the host's particles are those of the engine's time.
    virtual bool hostCurrent() const = 0;
    /// The box that holds every fluid particle at the engine's time.
    virtual sph::FluidExtent<Dim> fluidExtent() = 0;
    /// The host's particles were written between steps (a front end): the engine takes them.
    virtual void takeWrittenParticles() = 0;
    /// Particles were added or removed on the host (emitters, inlets, outlets, open sides).
    virtual void takeNewParticleSet() = 0;
    /// The host set imposed values of the same particles between steps (the velocity and the
    /// temperature of an inlet's buffer particles); the rates are still those of the time.
    virtual void takeImposedValues() = 0;
    /// Several processes: the CPU engine's pair loops over each one's share and halo.
    virtual void setDecomposition(sph::IDecomposition<Dim>* decomposition) = 0;
    /// Abandons a step in progress when check() is true (Ctrl-C), where the engine can.
    virtual void setAbandonCheck(std::function<bool()> check) = 0;
    /// The books of the heat walls and bodies gave, or nullptr without conduction.
    virtual sph::WallHeatBooks* wallHeat() = 0;
    /// The mean number of neighbours at the last evaluation (0 where not counted).
    virtual double meanNeighbours() const = 0;
    /// summary.json's `backend`: the CPU's (threads, omp, seq, tbb) or "cuda".
    virtual std::string backend() const = 0;
    /// What summary.json says of the engine: its device, its neighbour lists, its passes.
    virtual void describe(nlohmann::json& summary, std::size_t particles) const = 0;
};

}  // namespace num::app
