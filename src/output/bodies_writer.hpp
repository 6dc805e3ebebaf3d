// bodies.csv: a row per moving body per output time, its pose, velocities and the fluid's load
// (docs/scenes.md, "Outputs"). Internal to numerics_io.
#pragma once

#include <memory>

#include "io/output_writer.hpp"
#include "sph/bodies/moving_bodies.hpp"

namespace num::io {

template <int Dim>
class BodiesWriter final : public IWriter<Dim> {
  public:
    BodiesWriter(const WriterContext& context, std::shared_ptr<const sph::MovingBodies<Dim>> bodies)
        : c_(context), bodies_(std::move(bodies)) {}

    /// A fresh bodies.csv: its header.
    void start() override;
    /// bodies.csv keeps its rows up to t (a fresh one when there is none).
    void resume(double t, const OutputSeries& series) override;
    void write(const sph::Storage<Dim>& s, const std::vector<OutputField>& fields, double t,
               int index) override;
    void finish(bool, EndOfRun&) override {}
    std::vector<WrittenFile> files() const override {
        return {{"bodies.csv", "the moving bodies' positions, velocities and loads over time"}};
    }

  private:
    WriterContext c_;
    std::shared_ptr<const sph::MovingBodies<Dim>> bodies_;
};

}  // namespace num::io
