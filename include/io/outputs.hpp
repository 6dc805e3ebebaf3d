// Everything a run writes per output time: VTU (+ the .pvd series and a ParaView script), CSV,
// PNG, a row of probes.csv; and at the end an MP4 of the pictures (when ffmpeg is installed) and
// a plot of the probes.
#pragma once

#include <string>
#include <vector>

#include "io/fields.hpp"
#include "io/render.hpp"
#include "io/scene_setup.hpp"
#include "io/writers.hpp"

namespace num::io {

/// The files made at the end of a run, and why the movie is missing when it is.
struct EndOfRun {
    std::string video;           ///< path of <prefix>.mp4, or ""
    std::string videoNote;       ///< why there is no movie ("" when there is one)
    bool videoWanted = false;    ///< the scene asked for pictures and a movie
    std::string probePlot;       ///< path of probes.png, or "" (no probes)
    std::string paraviewScript;  ///< path of <prefix>_paraview.py, or "" (no VTU output)
};

template <int Dim>
class Outputs {
  public:
    /// `initial`: the scene's initial particles (sets the colour range of the pictures).
    Outputs(const Scene<Dim>& scene, const SceneSetup<Dim>& setup, std::string directory,
            const sph::Storage<Dim>& initial, FieldNames names = {});

    /// Creates the directory and a fresh probes.csv (a new run). Files an earlier run left under
    /// the names this run writes (its series, movie, probes, summary and checkpoints) are
    /// removed first; earlierRunNote() then says so.
    void start();
    /// "" or the warning that start() removed an earlier run's files.
    const std::string& earlierRunNote() const { return earlierRunNote_; }
    /// Continues an earlier run at time t: the series and probes.csv keep what is up to t.
    void resume(double t, std::vector<std::pair<double, std::string>> series);

    /// Writes the files of output number `index` at time t.
    void write(const sph::Storage<Dim>& s, double t, int index);

    /// The end of a run: the probe plot, and the movie when the run completed.
    EndOfRun finish(bool completed) const;

    const std::string& directory() const { return dir_; }
    std::string path(const std::string& name) const { return dir_ + "/" + name; }
    std::string fileName(int index, const std::string& extension) const;
    const PvdSeries& series() const { return series_; }
    int pictures() const { return pictures_; }

  private:
    /// Whether a file name is one this run writes (or a checkpoint's).
    bool earlierRunFile(const std::string& name) const;
    void removeEarlierRun();
    void writeProbes(const sph::Storage<Dim>& s, double t);
    void writeParaviewScript() const;
    /// Makes <prefix>.mp4 from the pictures with ffmpeg; returns "" or why it could not.
    std::string makeVideo() const;

    const Scene<Dim>& scene_;
    const SceneSetup<Dim>& setup_;
    std::string dir_;
    FieldNames names_;
    RenderSettings<Dim> render_;
    PvdSeries series_;
    int pictures_ = 0;
    std::string earlierRunNote_;
};

/// Whether an executable is on the PATH.
bool onPath(const std::string& program);

}  // namespace num::io
