// A long set-up (a lattice of millions of points, a large scene's checks) can be stopped by the
// program that runs it: the Python module installs a check that sees Ctrl-C (KeyboardInterrupt).
// Set-up loops poll it now and then; without a check installed a poll is one load.
#pragma once

#include <atomic>

namespace num::sph {

/// Thrown by an installed check to abandon the set-up. Not a std::exception, so that no handler
/// of the set-up's own errors turns it into one.
struct SetUpInterrupted {};

/// Throws SetUpInterrupted when the set-up is to stop; may return on any thread.
using SetUpInterruptCheck = void (*)();

inline std::atomic<SetUpInterruptCheck>& setUpInterruptCheck() {
    static std::atomic<SetUpInterruptCheck> check{nullptr};
    return check;
}

/// Calls the installed check, if any.
inline void pollSetUpInterrupt() {
    if (const SetUpInterruptCheck check = setUpInterruptCheck().load(std::memory_order_relaxed))
        check();
}

}  // namespace num::sph
