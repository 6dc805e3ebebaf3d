// The state of a run a checkpoint keeps besides the particles (internal to numerics_app).
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "app/checkpoint.hpp"

namespace num::app {

template <int Dim>
struct RunState {
    double time = 0;
    std::uint64_t steps = 0;
    std::int64_t outputIndex = 0, checkpointCount = 0;
    std::vector<std::uint64_t> emitterLayers;
    std::uint64_t emitted = 0, removed = 0;
    std::uint64_t emitterBlocked = 0;  ///< nozzle points left out: water was there
    std::vector<double> start;         ///< conservation at t = 0 (see conservationVector)
    std::vector<std::pair<double, std::string>> series;
    std::vector<double> bodies;    ///< the moving bodies' states (MovingBodies::save); or empty
    std::vector<double> flow;      ///< the inlets' and outlets' books (FlowBooks::save); or empty
    std::vector<double> wallHeat;  ///< the walls' heat books (WallHeatBooks::save); or empty

    void write(ByteWriter& w) const {
        w.put(time), w.put(steps), w.put(outputIndex), w.put(checkpointCount);
        w.putVector(emitterLayers), w.put(emitted), w.put(removed), w.put(emitterBlocked);
        w.putVector(start);
        w.put<std::uint64_t>(series.size());
        for (const auto& [t, f] : series) w.put(t), w.putString(f);
        w.putVector(bodies);
        w.putVector(flow);
        w.putVector(wallHeat);
    }
    void read(ByteReader& r) {
        time = r.get<double>(), steps = r.get<std::uint64_t>();
        outputIndex = r.get<std::int64_t>(), checkpointCount = r.get<std::int64_t>();
        emitterLayers = r.getVector<std::uint64_t>();
        emitted = r.get<std::uint64_t>(), removed = r.get<std::uint64_t>();
        emitterBlocked = r.get<std::uint64_t>();
        start = r.getVector<double>();
        const auto n = r.get<std::uint64_t>();
        for (std::uint64_t k = 0; k < n && !r.atEnd(); ++k) {
            const double t = r.get<double>();
            series.emplace_back(t, r.getString());
            if (!std::isfinite(t)) invalid(r, "an output time that is not finite");
        }
        if (series.size() != n) invalid(r, "fewer outputs than it counts");
        bodies = r.getVector<double>();
        flow = r.getVector<double>();
        wallHeat = r.getVector<double>();
        if (!std::isfinite(time) || time < 0) invalid(r, "a time that is not finite or below 0");
        if (outputIndex < 0 || checkpointCount < 0) invalid(r, "a negative output count");
    }

  private:
    [[noreturn]] static void invalid(const ByteReader& r, const std::string& what) {
        throw AppError(ExitCode::CHECKPOINT, r.file() + ": the checkpoint's run state holds " +
                                                 what +
                                                 "; it cannot be used for --restart (was it "
                                                 "edited?)");
    }
};

}  // namespace num::app
