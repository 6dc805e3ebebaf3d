// The plots of a run's time series (probes.csv, ...): drawn after the run by
// scripts/plot_series.py with matplotlib, which the apps run through Python. Internal to
// numerics_app.
#pragma once

#include <string>
#include <vector>

namespace num::app {

/// The plotting script: $NUMERICS_PLOT_SCRIPT, else plot_series.py beside the running program
/// (the build tree copies it there), else in ../share/numerics/ from it (an installed app), else
/// the source tree's scripts/plot_series.py. "" when none of them exists.
std::string plotScript();

/// The Python that runs it: $NUMERICS_PYTHON, else Debian's /usr/bin/python3 (python3-matplotlib
/// is installed for it), else python3 on the PATH. "" when there is none.
std::string plotPython();

/// Draws the CSV `csv` into each of `pictures` (their extension gives the format) under `title`;
/// `log` takes the script's messages for the time it runs. "" when drawn, else why not, in one
/// sentence (e.g. that matplotlib is not installed).
std::string plotSeries(const std::string& csv, const std::vector<std::string>& pictures,
                       const std::string& title, const std::string& log);

}  // namespace num::app
