// ParaView output (binary VTU, appended raw data, and a .pvd series) and CSV per output time.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "io/fields.hpp"

namespace num::io {

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

}  // namespace num::io
