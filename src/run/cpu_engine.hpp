// The CPU engine (internal to numerics_app): the fluid model's terms in a sph::Solver, stepped by
// sph::Run with the scene's integrator on the CPU's threads, in the host's storage itself.
#pragma once

#include <memory>
#include <string>

#include "app/scene_setup.hpp"
#include "run/engine.hpp"

namespace num::app {

template <int Dim>
class CpuEngine final : public IEngine<Dim> {
  public:
    CpuEngine(sph::Storage<Dim>& storage, sph::IScheduler& scheduler, const SceneSetup<Dim>& setup,
              const std::string& integrator, const std::string& backend, double t0)
        : solver_(scheduler, setup.settings, sph::makeFluidEquations(setup.model, setup.geometry),
                  setup.geometry.domain),
          integrator_(sph::makeIntegrator<Dim>(integrator)),
          run_(storage, solver_, *integrator_, t0),
          storage_(storage),
          backend_(backend) {}

    const sph::StepClock& clock() const override { return run_; }
    void prime() override { run_.prime(); }
    void resume(double t, sph::Size steps) override {
        run_.setTime(t, steps);
        run_.markPrimed(true);
    }
    double allowedStep() override { return solver_.timeStepLimits(storage_).dt(); }
    double step(double target) override { return run_.step(target); }
    void copyToHost() override {}
    bool hostCurrent() const override { return true; }
    sph::FluidExtent<Dim> fluidExtent() override {
        const auto x = storage_.template getValue<sph::Vector<Dim>>(sph::QuantityId::POSITION);
        const auto kind = storage_.template getValue<int>(sph::QuantityId::KIND);
        sph::FluidExtent<Dim> extent;
        for (sph::Size i = 0; i < storage_.size(); ++i)
            if (sph::isFluid(kind[i])) extent.add(x[i]);
        return extent;
    }
    void takeWrittenParticles() override {}
    void takeNewParticleSet() override { run_.particlesChanged(); }
    void takeImposedValues() override {}  // set in the storage the solver steps
    void setDecomposition(sph::IDecomposition<Dim>* d) override { solver_.setDecomposition(d); }
    void setAbandonCheck(std::function<bool()> check) override {
        solver_.setAbandonCheck(std::move(check));
    }
    sph::WallHeatBooks* wallHeat() override {
        auto* walls = solver_.equations().template find<sph::ThermalBoundary<Dim>>();
        return walls ? &walls->books() : nullptr;
    }
    double meanNeighbours() const override { return solver_.meanNeighbours(); }
    std::string backend() const override { return backend_; }
    void describe(nlohmann::json& summary, std::size_t) const override {
        summary["neighbour_list_builds"] = solver_.neighbours().builds();
        // The passes of an evaluation, each with its terms in the order they run.
        const std::vector<std::string> termNames = solver_.equations().names();
        for (const auto& pass : solver_.schedule().passes) {
            nlohmann::json names = nlohmann::json::array();
            for (std::size_t t : pass.terms) names.push_back(termNames[t]);
            summary["passes"].push_back(names);
        }
    }

  private:
    sph::Solver<Dim> solver_;
    std::unique_ptr<sph::ITimeStepping<Dim>> integrator_;
    sph::Run<Dim> run_;
    sph::Storage<Dim>& storage_;
    std::string backend_;
};

}  // namespace num::app
