// Output of the validation cases: when NUMERICS_VALIDATION_OUT names a directory, each case
// writes <case>.json (case, resolution, error, tolerance, passed, notes) and
// <case>_profile.csv (coordinate, numeric, analytic[, time]) for validation/report.py;
// NUMERICS_VALIDATION_FULL=1 asks for the documentation resolution.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace num::sph::validation {

/// True when NUMERICS_VALIDATION_FULL=1 asks for the documentation resolution.
inline bool fullResolution() {
    const char* v = std::getenv("NUMERICS_VALIDATION_FULL");
    return v && std::string(v) == "1";
}

/// One row of a profile: coordinate, numeric, analytic, and optionally the time.
struct ProfileRow {
    double coordinate, numeric, analytic, time = -1;
};

/// The result of a validation case, written as <case>.json and <case>_profile.csv into the
/// directory named by NUMERICS_VALIDATION_OUT (nothing is written when it is unset).
struct ValidationResult {
    std::string name, resolution, notes;
    double error = 0, tolerance = 0;
    bool passed = false;
    std::vector<ProfileRow> profile;

    void write() const {
        const char* dir = std::getenv("NUMERICS_VALIDATION_OUT");
        if (!dir || !*dir) return;
        std::filesystem::create_directories(dir);
        const std::filesystem::path base(dir);
        std::ofstream json(base / (name + ".json"));
        json.precision(10);
        json << "{\"case\": \"" << escape(name) << "\", \"resolution\": \"" << escape(resolution)
             << "\", \"error\": " << error << ", \"tolerance\": " << tolerance
             << ", \"passed\": " << (passed ? "true" : "false") << ", \"notes\": \""
             << escape(notes) << "\"}\n";
        std::ofstream csv(base / (name + "_profile.csv"));
        csv.precision(10);
        const bool timed = !profile.empty() && profile.front().time >= 0;
        csv << "coordinate,numeric,analytic" << (timed ? ",time" : "") << "\n";
        for (const ProfileRow& r : profile) {
            csv << r.coordinate << "," << r.numeric << "," << r.analytic;
            if (timed) csv << "," << r.time;
            csv << "\n";
        }
    }

  private:
    static std::string escape(const std::string& s) {
        std::string o;
        for (char c : s) {
            if (c == '"' || c == '\\') o += '\\';
            o += c;
        }
        return o;
    }
};

}  // namespace num::sph::validation
