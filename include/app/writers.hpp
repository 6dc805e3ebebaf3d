// ParaView output (binary VTU, appended raw data, and a .pvd series) and CSV per output time.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "app/fields.hpp"

namespace num::app {

/// Writes all particles as VTK_VERTEX cells of an UnstructuredGrid with the given point data
/// (vectors padded to 3 components), the time in FieldData "TimeValue".
template <int Dim>
void writeVtu(const std::string& path, const sph::Storage<Dim>& s,
              const std::vector<OutputField>& fields, double time);

/// Writes the fluid particles (KIND = fluid) as CSV: x,y[,z], then the fields (vectors as
/// vx,vy[,vz] for velocity, <name>_x... otherwise), one row per particle.
template <int Dim>
void writeCsv(const std::string& path, const sph::Storage<Dim>& s,
              const std::vector<OutputField>& fields);

/// What the ParaView script needs to know of the run.
struct ParaviewView {
    std::string pvdName;                  ///< the series, next to the script
    int dimension = 2;                    ///< 2D: a flat view along z
    int upAxis = 1;                       ///< the axis drawn upwards (against gravity)
    double spacing = 0.01;                ///< particle spacing [m]: points are spheres this wide
    double colorMin = 0, colorMax = 100;  ///< temperature range of the colour map [C]
};

/// Writes a Python script for ParaView that opens the series coloured by temperature, fluid and
/// bodies as spheres of the particle spacing (walls hidden). `paraview --script=FILE` opens it
/// in the window; `pvpython FILE --screenshot` saves FILE's name with .png instead.
void writeParaviewScript(const std::string& path, const ParaviewView& view);

/// A ParaView collection (.pvd) of output files and their times, rewritten atomically.
class PvdSeries {
  public:
    void add(double time, const std::string& fileName) { entries_.emplace_back(time, fileName); }
    /// Drops the entries after `time` (a restart continues the series).
    void truncateAfter(double time);
    void write(const std::string& path) const;
    const std::vector<std::pair<double, std::string>>& entries() const { return entries_; }

  private:
    std::vector<std::pair<double, std::string>> entries_;
};

}  // namespace num::app
