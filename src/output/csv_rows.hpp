// Rows of a CSV file whose first column is the time (probes.csv, bodies.csv). Internal to
// numerics_io.
#pragma once

#include <cstdlib>
#include <fstream>
#include <string>

#include "io/file.hpp"

namespace num::io {

/// Keeps the header and the rows up to time t (to round-off) of the CSV file at `path`, for a
/// restart from t; false when there is no such file.
inline bool keepCsvRowsUpTo(const std::string& path, double t) {
    std::ifstream in(path);
    if (!in) return false;
    std::string line, kept;
    bool header = true;
    while (std::getline(in, line)) {
        if (!header && std::strtod(line.c_str(), nullptr) > t * (1 + 1e-12)) break;
        kept += line + "\n";
        header = false;
    }
    writeFileAtomically(path, kept);
    return true;
}

}  // namespace num::io
