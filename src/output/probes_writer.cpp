#include "output/probes_writer.hpp"

#include <cstdlib>
#include <fstream>

#include "app/diagnostics.hpp"
#include "app/file.hpp"
#include "output/csv_rows.hpp"
#include "output/series_plot.hpp"

namespace num::app {

template <int Dim>
void ProbesWriter<Dim>::start() {
    std::string header = "time";
    const char* axes = "xyz";
    for (const auto& p : probes_)
        for (const auto& f : p.fields) {
            if (f == "velocity" || f == "force")
                for (int k = 0; k < Dim; ++k)
                    header += "," + csvField(p.name + (f == "force" ? ".force_" : ".v") +
                                             std::string(1, axes[k]));
            else
                header += "," + csvField(p.name + "." + f);
        }
    writeFileAtomically(c_.path("probes.csv"), header + "\n");
}

template <int Dim>
void ProbesWriter<Dim>::resume(double t, const OutputSeries&) {
    if (!keepCsvRowsUpTo(c_.path("probes.csv"), t)) start();
}

template <int Dim>
void ProbesWriter<Dim>::write(const sph::Storage<Dim>& s, const std::vector<OutputField>&, double t,
                              int) {
    std::string row = formatted("%.10g", t);
    std::vector<sph::Vector<Dim>> forces;
    if (bodyForces_) forces = (*bodyForces_)(s);
    for (const auto& p : probes_)
        for (const auto& f : p.fields)
            if (const int target = p.body >= 0   ? p.body
                                   : p.wall >= 0 ? bodies_ + p.wall
                                                 : -1;
                target >= 0)
                for (int k = 0; k < Dim; ++k) row += formatted(",%.10g", forces.at(target)[k]);
            else if (p.side >= 0)
                row += formatted(
                    ",%.10g", sideFlowRate(s, p.side / 2, p.side % 2, box_[0], box_[1], spacing_));
            else
                for (double v : probe(s, kernel_, p.point, f)) row += formatted(",%.10g", v);
    appendToFile(c_.path("probes.csv"), row + "\n");
}

/// The plot of probes.csv, in each format of output.plots; a plot that cannot be drawn (no
/// Python or matplotlib) is a note at the end of the run, not a failure.
template <int Dim>
void ProbesWriter<Dim>::finish(bool, EndOfRun& end) {
    if (plots_.empty()) return;
    std::vector<std::string> pictures;
    for (const std::string& format : plots_) pictures.push_back(c_.path("probes." + format));
    end.probePlotNote = plotSeries(c_.path("probes.csv"), pictures, "probes: " + c_.title,
                                   c_.path("plot_series.log"));
    plotted_ = end.probePlotNote.empty();
    if (plotted_) end.probePlot = pictures.front();
}

template <int Dim>
std::vector<WrittenFile> ProbesWriter<Dim>::files() const {
    std::vector<WrittenFile> out = {{"probes.csv", "probe values over time"}};
    std::string names;
    for (const std::string& format : plots_)
        names += (names.empty() ? "probes." : ", probes.") + format;
    if (plotted_) out.push_back({names, "their plot"});
    return out;
}

template class ProbesWriter<2>;
template class ProbesWriter<3>;

}  // namespace num::app
