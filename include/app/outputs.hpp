// Everything a run writes per output time, through its writers (app/output_writer.hpp): the
// formats of output.formats by name (app/writer_registry.hpp: VTU with its .pvd series and a
// ParaView script, CSV, and those plugins add), the pictures (PNG, and at the end an MP4 by
// ffmpeg when it is installed) and the probes (a row of probes.csv at each probe time,
// output.probes_every, and at the end their plot by scripts/plot_series.py).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "app/fields.hpp"
#include "app/file.hpp"
#include "app/output_writer.hpp"
#include "app/render.hpp"
#include "app/scene_setup.hpp"
#include "app/writer_registry.hpp"
#include "app/writers.hpp"

namespace num::app {

template <int Dim>
class PicturesWriter;

template <int Dim>
class Outputs {
  public:
    /// `initial`: the scene's initial particles (sets the colour range of the pictures).
    /// `writers`: the formats that output.formats may name (with the plugins' writers); a name
    /// that is not among them is an AppError SCENE (checkOutputFormats).
    Outputs(const Scene<Dim>& scene, const SceneSetup<Dim>& setup, std::string directory,
            const sph::Storage<Dim>& initial, FieldNames names = {},
            const WriterRegistry& writers = builtInWriters());

    /// Creates the directory and starts every writer (a new run: a fresh probes.csv). Files an
    /// earlier run left under the names this run writes (its series, movie, probes, summary and
    /// checkpoints) are removed first; earlierRunNote() then says so.
    void start();
    /// "" or the warning that start() removed an earlier run's files.
    const std::string& earlierRunNote() const { return earlierRunNote_; }
    /// Continues an earlier run at time t: the series (of the checkpoint) and probes.csv keep
    /// what is up to t.
    void resume(double t, std::vector<std::pair<double, std::string>> series);

    /// Writes the files of output number `index` at time t (all but the probes).
    void write(const sph::Storage<Dim>& s, double t, int index);
    /// Writes the probes' row of time t (output.probes_every; none without probes).
    void writeProbes(const sph::Storage<Dim>& s, double t);

    /// The end of a run: the probe plot, and the movie when the run completed.
    EndOfRun finish(bool completed) const;
    /// Releases the output directory's lock (start() and resume() take it, so that a second
    /// run writing the directory at once is refused): after the run's last file.
    void releaseLock() { lock_.reset(); }
    /// The files the run made and what they hold, for the lines printed at its end.
    std::vector<WrittenFile> files() const;

    const std::string& directory() const { return dir_; }
    std::string path(const std::string& name) const { return dir_ + "/" + name; }
    std::string fileName(int index, const std::string& extension) const;
    /// The series a checkpoint keeps (the VTU files; empty without "vtu").
    const PvdSeries& series() const;
    /// The pictures of the run so far (0 without output.images).
    int pictures() const;

  private:
    /// Whether a file name is one this run writes (or a checkpoint's).
    bool earlierRunFile(const std::string& name) const;
    void removeEarlierRun();
    void makeWriters(const Scene<Dim>& scene, const SceneSetup<Dim>& setup,
                     const sph::Storage<Dim>& initial, const WriterRegistry& writers);

    const Scene<Dim>& scene_;
    std::string dir_;
    FieldNames names_;
    WriterContext context_;                               ///< what every writer is made with
    std::vector<std::unique_ptr<IWriter<Dim>>> writers_;  ///< formats, pictures, probes
    const PicturesWriter<Dim>* pictures_ = nullptr;       ///< among writers_, or none
    IWriter<Dim>* probes_ = nullptr;                      ///< among writers_, or none
    std::string earlierRunNote_;
    std::unique_ptr<OutputLock> lock_;  ///< while the run writes the directory
};

/// Whether an executable is on the PATH.
bool onPath(const std::string& program);

}  // namespace num::app
