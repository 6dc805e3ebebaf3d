// Errors a user can act on, and the exit codes of the apps (documented in docs/scenes.md).
#pragma once

#include <stdexcept>
#include <string>

namespace num::app {

/// Exit codes of fluid_sim and fluid_sim_3d.
enum class ExitCode : int {
    OK = 0,
    INTERNAL = 1,      ///< an unexpected failure (a bug: please report it)
    USAGE = 2,         ///< bad command line
    SCENE_FILE = 3,    ///< scene file missing or unreadable
    JSON_SYNTAX = 4,   ///< scene file is not valid JSON
    SCENE = 5,         ///< scene content invalid (key, type, range, geometry, dimension)
    EXPRESSION = 6,    ///< an expression that does not parse or evaluate
    OUTPUT = 7,        ///< output cannot be written (permissions, disk full)
    CHECKPOINT = 8,    ///< checkpoint missing, corrupted, truncated or incompatible
    UNSTABLE = 9,      ///< the run went unstable (NaN, particles leaving through a wall)
    PLUGIN = 10,       ///< a plugin is not loadable, of another API version, or its code failed
    RESOURCES = 11,    ///< the system refused threads or memory (a process or memory limit)
    NO_GPU = 12,       ///< --backend cuda: no CUDA back end in this build, or no GPU to run it
    INTERRUPTED = 130  ///< stopped by Ctrl-C (SIGINT) or SIGTERM after writing final output
};

/// An error with the exit code it maps to. The message is complete and ready to print.
class AppError : public std::runtime_error {
  public:
    AppError(ExitCode code, const std::string& message)
        : std::runtime_error(message), code_(code) {}
    ExitCode code() const { return code_; }

  private:
    ExitCode code_;
};

/// A mistake in a scene: file, key path, what was expected and what was found (+ a hint).
inline AppError sceneError(const std::string& file, const std::string& path,
                           const std::string& expected, const std::string& found,
                           const std::string& hint = "", ExitCode code = ExitCode::SCENE) {
    std::string m =
        file + ": " + (path.empty() ? std::string("(top level)") : path) + ": expected " + expected;
    if (!found.empty()) m += ", found " + found;
    if (!hint.empty()) m += " (" + hint + ")";
    return AppError(code, m);
}

}  // namespace num::app
