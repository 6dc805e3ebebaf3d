// The command line shared by fluid_sim (Dim = 2) and fluid_sim_3d (Dim = 3): options, the
// built-in default scene, and the mapping of every error to its message and exit code.
#pragma once

#include <string>

#include "app/fields.hpp"

namespace num::app {

struct AppInfo {
    std::string name;          ///< program name
    std::string defaultScene;  ///< the built-in scene's JSON text
    std::string
        defaultSceneName;   ///< its file name (for messages), e.g. dam_break_hot_cold_2d.json
    FieldNames fieldNames;  ///< names of user quantities in the outputs
    std::string scenesDir;  ///< the shipped scenes (--list-scenes), when ./scenes is absent
};

/// Prints the scenes of `dir` (its *.json, then validation/*.json): the app that runs each, its
/// file and the first sentence of its description. Returns the exit code.
int listScenes(const std::string& dir, const AppInfo& info);

/// Parses the command line and runs; returns the process exit code (docs/scenes.md).
template <int Dim>
int runApp(int argc, char** argv, const AppInfo& info);

}  // namespace num::app
