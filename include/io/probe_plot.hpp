// The probes of a run over time as a picture (probes.png): one panel per quantity (temperature,
// pressure, velocity, density), a line per probe column, drawn with the apps' own raster.
#pragma once

#include <string>

#include "io/image.hpp"

namespace num::io {

/// Plots the text of a probes.csv ("time,<probe>.<field>,..." then rows); columns of a field
/// share a panel. An empty or unreadable table gives a picture that says so.
Image plotProbes(const std::string& csvText, const std::string& title, int width = 960);

}  // namespace num::io
