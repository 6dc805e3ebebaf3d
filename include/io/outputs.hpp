// Everything a run writes per output time: VTU (+ the .pvd series), CSV, PNG, a row of
// probes.csv; and at the end an MP4 of the pictures when ffmpeg is installed.
#pragma once

#include <string>
#include <vector>

#include "io/fields.hpp"
#include "io/render.hpp"
#include "io/scene_setup.hpp"
#include "io/writers.hpp"

namespace num::io {

template <int Dim>
class Outputs {
  public:
    /// `initial`: the scene's initial particles (sets the colour range of the pictures).
    Outputs(const Scene<Dim>& scene, const SceneSetup<Dim>& setup, std::string directory,
            const sph::Storage<Dim>& initial, FieldNames names = {});

    /// Creates the directory and a fresh probes.csv (a new run).
    void start();
    /// Continues an earlier run at time t: the series and probes.csv keep what is up to t.
    void resume(double t, std::vector<std::pair<double, std::string>> series);

    /// Writes the files of output number `index` at time t.
    void write(const sph::Storage<Dim>& s, double t, int index);

    /// Makes <prefix>.mp4 from the pictures when ffmpeg is on the PATH; returns its path or "".
    std::string makeVideo(bool quiet) const;

    const std::string& directory() const { return dir_; }
    std::string path(const std::string& name) const { return dir_ + "/" + name; }
    std::string fileName(int index, const std::string& extension) const;
    const PvdSeries& series() const { return series_; }
    int pictures() const { return pictures_; }

  private:
    void writeProbes(const sph::Storage<Dim>& s, double t);

    const Scene<Dim>& scene_;
    const SceneSetup<Dim>& setup_;
    std::string dir_;
    FieldNames names_;
    RenderSettings<Dim> render_;
    PvdSeries series_;
    int pictures_ = 0;
};

/// Whether an executable is on the PATH.
bool onPath(const std::string& program);

}  // namespace num::io
