// Ctrl-C (SIGINT), kill (SIGTERM) and a closed terminal (SIGHUP), internal to numerics_app.
// During set-up a signal ends the program at once (nothing of the run is written yet). During
// the run the first signal asks for a stop: between steps the run ends with a final output, a
// checkpoint and summary.json; a step still running kStepGraceSeconds after the signal (a step
// that would take minutes) is abandoned. A second signal ends the program at once.
#pragma once

#include <cstdint>
#include <string>

namespace num::app::stop {

/// How long a step in progress may still run after a stop was asked for.
inline constexpr double kStepGraceSeconds = 0.5;

/// Set-up: a signal prints "<program>: stopped by <signal> during set-up ..." and exits with
/// code 130 at once.
void duringSetUp(const std::string& program);
/// The run: a signal sets the stop flag; a second one ends the program at once.
void duringRun();
/// The default actions again (the end of a run, or an error before it).
void restoreDefaults();

/// The signal that asked for a stop, or 0.
int requested();
/// For the solver's pair loop, asked every few particles of step `step`: true when a stop has
/// waited longer than kStepGraceSeconds, so the step is abandoned.
bool abandonStep(std::uint64_t step);
/// The name of a stop signal ("SIGTERM").
const char* signalName(int sig);

/// For tests: NUMERICS_TEST_SIGNAL="SIGNAL:STEP" raises SIGNAL after step STEP.
struct TestSignal {
    int signal = 0;
    std::uint64_t step = 0;
};
TestSignal testSignal();

/// Restores the default signal actions when a run ends, also by an exception (when `active`:
/// the run installed its handlers).
struct DefaultsOnExit {
    explicit DefaultsOnExit(bool active_ = true) : active(active_) {}
    DefaultsOnExit(const DefaultsOnExit&) = delete;
    DefaultsOnExit& operator=(const DefaultsOnExit&) = delete;
    ~DefaultsOnExit() {
        if (active) restoreDefaults();
    }
    const bool active;
};

}  // namespace num::app::stop
