// One kind of output file of a run: the interface every writer implements (the formats of the
// scene's output.formats, the pictures, the probes), what it is made with, and what the end of a
// run reports. app/writer_registry.hpp finds the formats by name.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "app/fields.hpp"
#include "app/formatted.hpp"
#include "app/writers.hpp"

namespace num::app {

/// Where a writer writes and what it may use of the run (the same for every writer of a run).
struct WriterContext {
    std::string directory;  ///< the output directory; it exists when start or resume is called
    std::string prefix;     ///< output.prefix
    std::string title;      ///< the scene's name
    double spacing = 0.01;  ///< the particle spacing [m]
    int upAxis = 1;         ///< the axis against gravity
    double colorMin = 0, colorMax = 100;  ///< the colour range of temperature [degC]

    std::string path(const std::string& name) const { return directory + "/" + name; }
    /// The file of output number `index`: <prefix>_NNNN.<extension>.
    std::string fileName(int index, const std::string& extension) const {
        return prefix + formatted("_%04d.", index) + extension;
    }
};

/// The files made at the end of a run, and why the movie is missing when it is.
struct EndOfRun {
    std::string video;           ///< path of <prefix>.mp4, or ""
    std::string videoNote;       ///< why there is no movie ("" when there is one)
    bool videoWanted = false;    ///< the scene asked for pictures and a movie
    std::string probePlot;       ///< path of probes.png (or .svg), or "" (no probes or plot)
    std::string probePlotNote;   ///< why the probes' plot is missing ("" when drawn or not asked)
    std::string paraviewScript;  ///< path of <prefix>_paraview.py, or "" (no VTU output)
};

/// A file (or a pattern of files) a writer made and what it holds: a line of the run's report.
struct WrittenFile {
    std::string name, what;
};

/// (time, file name) of each output a checkpoint keeps so that a restart continues a series.
using OutputSeries = std::vector<std::pair<double, std::string>>;

/// A writer of output files. Outputs<Dim> calls start (a new run) or resume (a restart), then
/// write at every output time, then finish; every call on the root process, in one thread.
template <int Dim>
class IWriter {
  public:
    static constexpr int dim = Dim;
    virtual ~IWriter() = default;

    /// A new run: the directory holds no earlier run's files of the names this run writes.
    virtual void start() {}
    /// A run continued from a checkpoint at time t; `series` is the series the checkpoint kept,
    /// up to t.
    virtual void resume(double /*t*/, const OutputSeries& /*series*/) {}
    /// Output number `index` (0 at t = 0) at time t: every particle, and the fields to write
    /// (app/fields.hpp).
    virtual void write(const sph::Storage<Dim>& s, const std::vector<OutputField>& fields, double t,
                       int index) = 0;
    /// The end of the run (`completed`: it reached its end time); notes its files in `end`.
    virtual void finish(bool /*completed*/, EndOfRun& /*end*/) {}

    /// The files it made, for the lines the apps print at the end of a run.
    virtual std::vector<WrittenFile> files() const { return {}; }
    /// The series a checkpoint keeps for resume (the VTU files), or nullptr.
    virtual const PvdSeries* series() const { return nullptr; }
};

}  // namespace num::app
