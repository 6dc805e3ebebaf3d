// A run of a scene from start (or a checkpoint) to its end time: the time loop with outputs,
// emitters, open boundaries, health checks, checkpoints, Ctrl-C, progress and summary.json.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "io/fields.hpp"
#include "io/scene_loader.hpp"
#include "parallel/communicator.hpp"

namespace num::io {

struct RunOptions {
    std::string program = "fluid_sim";
    std::optional<std::string> outDir;   ///< overrides output.directory
    int threads = 0;                     ///< 0: all hardware threads
    std::string backend = "threads";     ///< seq, omp, threads, cpu (= threads) or cuda
    bool backendGiven = false;           ///< --backend given: it overrides numerics.backend
    std::optional<double> endTime;       ///< overrides time.end
    std::optional<std::string> restart;  ///< checkpoint to continue from
    double checkpointEvery = 0;          ///< simulated seconds between checkpoints (0: none)
    bool quiet = false;
    FieldNames fieldNames;  ///< names of user quantities in the outputs
    /// The processes of the run (mpirun); nullptr: this process alone.
    const parallel::Communicator* communicator = nullptr;
};

/// Runs the scene; returns the exit code (0, INTERRUPTED). Errors are AppErrors.
template <int Dim>
int runSimulation(const SceneDocument& doc, const RunOptions& options);

/// Reads the scene document stored in a checkpoint (for --restart without a scene file).
SceneDocument sceneOfCheckpoint(const std::string& path, int dimension);

}  // namespace num::io
