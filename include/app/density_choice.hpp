// How a scene's density evolves (physics.density): one table. "auto" holds no mode: the scene
// set-up picks summation under gravity in a full box closed by walls, else continuity.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "sph/choice_table.hpp"
#include "sph/fluid_model.hpp"

namespace num::app {

inline constexpr std::array densityTable{
    sph::Choice<std::optional<sph::DensityMode>>{
        "auto", std::nullopt,
        "summation in a full box closed by walls under gravity, else continuity"},
    sph::Choice<std::optional<sph::DensityMode>>{"continuity", sph::DensityMode::CONTINUITY,
                                                 "d rho / dt from the velocity divergence"},
    sph::Choice<std::optional<sph::DensityMode>>{"summation", sph::DensityMode::SUMMATION,
                                                 "rho = sum_j m_j W_ij"},
};

/// The mode of a name of the table; empty for "auto".
inline std::optional<sph::DensityMode> densityFromName(const std::string& name) {
    return densityTable[sph::chooseIndex(densityTable, "density", name)].value;
}

}  // namespace num::app
