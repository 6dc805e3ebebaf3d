// Errors every process of a run reports alike: a failure one process meets (an unwritable output
// on the root, an unstable particle in one subdomain) ends every process with the same message
// and exit code, rather than leaving the others waiting for it.
#pragma once

#include <algorithm>
#include <cstring>
#include <string>

#include "app/errors.hpp"
#include "parallel/communicator.hpp"

namespace num::app {

/// An error one process met in the middle of a step, while the others wait for it in an
/// exchange: the app reports it from that process and ends every process at once.
struct LoneFailure : AppError {
    explicit LoneFailure(const AppError& e) : AppError(e.code(), e.what()) {}
};

namespace detail {
inline parallel::Bytes encode(const AppError& e) {
    const int code = int(e.code());
    const std::string text = e.what();
    parallel::Bytes b(sizeof code + text.size());
    std::memcpy(b.data(), &code, sizeof code);
    std::copy(text.begin(), text.end(), b.begin() + sizeof code);
    return b;
}
inline void throwIfAny(const std::vector<parallel::Bytes>& outcomes) {
    for (const parallel::Bytes& b : outcomes)
        if (!b.empty()) {
            int code;
            std::memcpy(&code, b.data(), sizeof code);
            throw AppError(ExitCode(code), std::string(b.begin() + sizeof code, b.end()));
        }
}
}  // namespace detail

/// Runs f on every process; the AppError of the lowest-ranked process that threw one is thrown
/// on all of them.
template <class F>
void agreed(const parallel::Communicator& comm, F&& f) {
    if (comm.size() == 1) return f();
    parallel::Bytes outcome;
    try {
        f();
    } catch (const AppError& e) {
        outcome = detail::encode(e);
    }
    detail::throwIfAny(comm.allGather(outcome));
}

/// Runs f on the root only; an AppError it throws is thrown on every process.
template <class F>
void onRoot(const parallel::Communicator& comm, F&& f) {
    if (comm.size() == 1) return f();
    parallel::Bytes outcome;
    if (comm.isRoot()) try {
            f();
        } catch (const AppError& e) {
            outcome = detail::encode(e);
        }
    detail::throwIfAny({comm.broadcast(outcome)});
}

}  // namespace num::app
