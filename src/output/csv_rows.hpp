// Fields and rows of a CSV file whose first column is the time (probes.csv, bodies.csv).
// Internal to numerics_app.
#pragma once

#include <cstdlib>
#include <fstream>
#include <string>

#include "app/file.hpp"

namespace num::app {

/// A CSV field, quoted where needed (RFC 4180): a name with a comma, quote or line break.
inline std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string q = "\"";
    for (char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

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

}  // namespace num::app
