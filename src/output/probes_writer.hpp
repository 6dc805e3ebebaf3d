// The probes of a run: a row of probes.csv per probe time (output.probes_every: the fields
// interpolated at each probe's point, the force on a probe's body or wall, or the flow rate
// through a probe's side: app/diagnostics.hpp, sideFlowRate), and at the end
// their plot, probes.png (and .svg: output.plots), drawn by scripts/plot_series.py.
// Internal to numerics_app.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "app/output_writer.hpp"
#include "app/scene.hpp"
#include "output/body_force.hpp"
#include "sph/kernel_choice.hpp"

namespace num::app {

template <int Dim>
class ProbesWriter final : public IWriter<Dim> {
  public:
    /// `plots`: the formats of the plot ("png", "svg"; none: no plot); `bodyForces`: what the
    /// probes on bodies and walls read, the scene's `bodies` first, then its walls.
    /// `box`: the domain [min, max] and `spacing` its particles', where probes on sides read.
    ProbesWriter(const WriterContext& context, std::vector<Probe<Dim>> probes,
                 const sph::RunSettings& settings, std::vector<std::string> plots,
                 std::array<sph::Vector<Dim>, 2> box, double spacing,
                 std::optional<BodyForces<Dim>> bodyForces = std::nullopt, int bodies = 0)
        : c_(context),
          probes_(std::move(probes)),
          box_(box),
          spacing_(spacing),
          kernel_(settings),
          plots_(std::move(plots)),
          bodyForces_(std::move(bodyForces)),
          bodies_(bodies) {}

    /// A fresh probes.csv: its header.
    void start() override;
    /// probes.csv keeps its rows up to t (a fresh one when there is none).
    void resume(double t, const OutputSeries& series) override;
    void write(const sph::Storage<Dim>& s, const std::vector<OutputField>& fields, double t,
               int index) override;
    void finish(bool completed, EndOfRun& end) override;
    std::vector<WrittenFile> files() const override;

  private:
    WriterContext c_;
    std::vector<Probe<Dim>> probes_;
    std::array<sph::Vector<Dim>, 2> box_;
    double spacing_;
    sph::RunKernel<Dim> kernel_;
    std::vector<std::string> plots_;
    bool plotted_ = false;  ///< the plot was drawn
    std::optional<BodyForces<Dim>> bodyForces_;
    int bodies_;
};

}  // namespace num::app
