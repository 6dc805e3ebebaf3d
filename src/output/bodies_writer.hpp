// bodies.csv: a row per moving body per output time, its pose, velocities and the fluid's load
// (docs/scenes.md, "Outputs"), and its plot bodies.png (and .svg: output.plots), drawn by
// scripts/plot_series.py at the end of the run. Internal to numerics_app.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "app/output_writer.hpp"
#include "sph/bodies/moving_bodies.hpp"

namespace num::app {

template <int Dim>
class BodiesWriter final : public IWriter<Dim> {
  public:
    /// `plots`: the formats of the plot ("png", "svg"; none: no plot).
    BodiesWriter(const WriterContext& context, std::shared_ptr<const sph::MovingBodies<Dim>> bodies,
                 std::vector<std::string> plots)
        : c_(context), bodies_(std::move(bodies)), plots_(std::move(plots)) {}

    /// A fresh bodies.csv: its header.
    void start() override;
    /// bodies.csv keeps its rows up to t (a fresh one when there is none).
    void resume(double t, const OutputSeries& series) override;
    void write(const sph::Storage<Dim>& s, const std::vector<OutputField>& fields, double t,
               int index) override;
    /// The plot, where matplotlib is there (a run without it only says so).
    void finish(bool completed, EndOfRun& end) override;
    std::vector<WrittenFile> files() const override {
        return {{"bodies.csv, bodies.png",
                 "the moving bodies' positions, velocities, loads and heat over time, and their "
                 "plot"}};
    }

  private:
    WriterContext c_;
    std::shared_ptr<const sph::MovingBodies<Dim>> bodies_;
    std::vector<std::string> plots_;
};

}  // namespace num::app
