// The "vtu" format: a binary VTU file per output time (app/writers.hpp), the .pvd series that
// lists them with their times, and a ParaView script that opens the series.
#include <algorithm>
#include <cmath>

#include "app/writer_registry.hpp"
#include "app/writers.hpp"

namespace num::app {

namespace {

template <int Dim>
class VtuWriter final : public IWriter<Dim> {
  public:
    explicit VtuWriter(const WriterContext& context) : c_(context) {}

    void start() override { writeScript(); }
    void resume(double, const OutputSeries& series) override {
        writeScript();
        for (const auto& [time, file] : series) series_.add(time, file);
    }
    void write(const sph::Storage<Dim>& s, const std::vector<OutputField>& fields, double t,
               int index) override {
        const std::string file = c_.fileName(index, "vtu");
        writeVtu(c_.path(file), s, fields, t);
        // A later output at an earlier time (after a restart) replaces what follows it.
        series_.truncateAfter(t - 1e-12 * std::max(1.0, std::abs(t)));
        series_.add(t, file);
        series_.write(c_.path(c_.prefix + ".pvd"));
    }
    void finish(bool, EndOfRun& end) override { end.paraviewScript = c_.path(script()); }

    std::vector<WrittenFile> files() const override {
        return {{c_.prefix + ".pvd", "open in ParaView (File > Open, Apply) to play the series"},
                {script(), "ParaView coloured by temperature: paraview --script=" + script()}};
    }
    const PvdSeries* series() const override { return &series_; }

  private:
    std::string script() const { return c_.prefix + "_paraview.py"; }
    void writeScript() const {
        ParaviewView v;
        v.pvdName = c_.prefix + ".pvd";
        v.dimension = Dim;
        v.upAxis = Dim == 2 ? 1 : c_.upAxis;
        v.spacing = c_.spacing;
        v.colorMin = c_.colorMin, v.colorMax = c_.colorMax;
        writeParaviewScript(c_.path(script()), v);
    }

    WriterContext c_;
    PvdSeries series_;
};

}  // namespace

void vtuFormat(WriterRegistry& registry) { registry.add<VtuWriter>("vtu"); }

}  // namespace num::app
