#include "run/stop_signals.hpp"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <thread>

namespace num::app::stop {

namespace {

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

// Lock-free atomics: safe in a signal handler and read by the pair loop's threads.
std::atomic<int> gStop{0};
std::atomic<std::int64_t> gStopAt{0};  ///< CLOCK_MONOTONIC of the first signal [ns]
std::string gProgram = "fluid_sim";
std::string gSetUpLines[3];  ///< one per kSignals entry, made before the handler is installed
std::uint64_t gHoldStep = 0;
std::atomic<bool> gHoldAnnounced{false};

std::int64_t monotonicNanos() {
    timespec ts{};
    ::clock_gettime(CLOCK_MONOTONIC, &ts);  // async-signal-safe
    return std::int64_t(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

extern "C" void onSignalDuringSetUp(int sig) {
    for (int k = 0; k < 3; ++k)
        if (kSignals[k] == sig) (void)!::write(2, gSetUpLines[k].data(), gSetUpLines[k].size());
    ::_exit(130);
}

extern "C" void onSignalDuringRun(int sig) {
    gStopAt.store(monotonicNanos());
    gStop.store(sig);
    for (int s : kSignals) std::signal(s, SIG_DFL);  // a second signal ends the program at once
}

bool graceOver() {
    return gStop.load(std::memory_order_acquire) != 0 &&
           double(monotonicNanos() - gStopAt.load()) > kStepGraceSeconds * 1e9;
}

/// For tests: NUMERICS_TEST_HOLD_STEP=STEP makes step STEP wait in its pair loop until stopped,
/// as a step that would take minutes.
std::uint64_t holdStepOfEnvironment() {
    const char* v = std::getenv("NUMERICS_TEST_HOLD_STEP");
    return v ? std::strtoull(v, nullptr, 10) : 0;
}

}  // namespace

const char* signalName(int sig) {
    return sig == SIGINT ? "SIGINT (Ctrl-C)" : sig == SIGTERM ? "SIGTERM" : "SIGHUP";
}

void duringSetUp(const std::string& program) {
    gProgram = program;
    for (int k = 0; k < 3; ++k)
        gSetUpLines[k] = program + ": stopped by " + signalName(kSignals[k]) +
                         " during set-up, before the run wrote any file (exit code 130)\n";
    for (int s : kSignals) std::signal(s, onSignalDuringSetUp);
}

void duringRun() {
    gStop.store(0);
    gHoldStep = holdStepOfEnvironment();
    for (int s : kSignals) std::signal(s, onSignalDuringRun);
}

void restoreDefaults() {
    for (int s : kSignals) std::signal(s, SIG_DFL);
}

int requested() { return gStop.load(); }

bool abandonStep(std::uint64_t step) {
    if (gHoldStep == 0 || step != gHoldStep) return graceOver();
    if (!gHoldAnnounced.exchange(true)) {
        std::fprintf(stderr, "%s: test: holding step %llu until a signal\n", gProgram.c_str(),
                     (unsigned long long)step);
        std::fflush(stderr);
    }
    while (!graceOver()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    return true;
}

TestSignal testSignal() {
    const char* v = std::getenv("NUMERICS_TEST_SIGNAL");
    int sig = 0;
    unsigned long long step = 0;
    if (!v || std::sscanf(v, "%d:%llu", &sig, &step) != 2) return {};
    return {sig, step};
}

}  // namespace num::app::stop
