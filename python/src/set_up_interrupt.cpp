// Ctrl-C during a set-up: see set_up_interrupt.hpp.
#include "set_up_interrupt.hpp"

#include <Python.h>

#include <atomic>
#include <chrono>
#include <csignal>

#include "sph/setup/set_up_interrupt.hpp"

namespace num::python {

namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kEvery = std::chrono::milliseconds(50);

thread_local bool watching = false;
thread_local Clock::time_point lastLook;
/// For tests: the set-up sends itself SIGINT at this poll (0: never).
std::atomic<long> sigintAtPoll{0};

/// The set-up's check: on a watching thread, every kEvery, runs Python's pending signal handlers
/// (taking the GIL for it); the exception one raised stays set for the caller.
void checkCtrlC() {
    if (!watching) return;
    const Clock::time_point now = Clock::now();
    const bool testSignal = sigintAtPoll > 0 && --sigintAtPoll == 0;
    if (testSignal) std::raise(SIGINT);
    if (!testSignal && now - lastLook < kEvery) return;
    lastLook = now;
    const PyGILState_STATE gil = PyGILState_Ensure();
    const bool raised = PyErr_CheckSignals() != 0;
    PyGILState_Release(gil);
    if (raised) throw sph::SetUpInterrupted{};
}

}  // namespace

void installSetUpInterrupt() { sph::setUpInterruptCheck() = &checkCtrlC; }

void sendSigintAtSetUpPoll(long poll) { sigintAtPoll = poll; }

StopSetUpOnCtrlC::StopSetUpOnCtrlC() : outer_(!watching) {
    watching = true;
    lastLook = Clock::now();
}

StopSetUpOnCtrlC::~StopSetUpOnCtrlC() {
    if (outer_) watching = false;
}

}  // namespace num::python
