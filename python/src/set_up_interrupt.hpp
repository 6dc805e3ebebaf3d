// Ctrl-C during a set-up (Simulation(), Scene.check()), which runs in C++ and may take minutes
// for millions of particles: the set-up polls (sph/setup/set_up_interrupt.hpp), and on the thread
// that asked for it Python's signal handlers run at most every 50 ms; the exception they raise
// (KeyboardInterrupt) stops the set-up and reaches the caller.
#pragma once

namespace num::python {

/// Installs the check; once, when the module is imported.
void installSetUpInterrupt();

/// For tests (_numerics._sigint_at_set_up_poll): the next set-up sends itself SIGINT, as Ctrl-C
/// does, at its poll-th poll (0: never), so that a test stops a set-up at a known point.
void sendSigintAtSetUpPoll(long poll);

/// While one lives, the set-up on this thread stops on Ctrl-C. The GIL may be released.
class StopSetUpOnCtrlC {
  public:
    StopSetUpOnCtrlC();
    ~StopSetUpOnCtrlC();
    StopSetUpOnCtrlC(const StopSetUpOnCtrlC&) = delete;
    StopSetUpOnCtrlC& operator=(const StopSetUpOnCtrlC&) = delete;

  private:
    bool outer_;
};

}  // namespace num::python
