// Driver<Dim>: a Simulation as Python drives it. The GIL is released while the steps run and
// taken again, between steps, for what Python asked for: the callback at its times, the
// progress bar, and a look at the signals (Ctrl-C) every few hundredths of a second. Ctrl-C
// stops the run as a signal stops the apps' (Simulation::requestStop: the last output and
// summary.json as interrupted), then KeyboardInterrupt is raised.
#pragma once

#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <thread>

#include "app/simulation.hpp"
#include "bindings.hpp"
#include "particle_views.hpp"

namespace num::python {

/// Whether time t has reached target, to round-off (as the run decides it).
inline bool reached(double t, double target) {
    return t >= target - 1e-9 * std::max(1e-300, std::abs(target)) - 1e-300;
}

/// Thrown through the run's steps when a Python callback raised: the error waits in the Driver.
struct PythonErrorPending {};

template <int Dim>
class Driver {
  public:
    Driver(const app::SceneDocument& doc, const app::RunOptions& options);

    /// One step (GIL released); returns its dt.
    double step();
    /// Steps to `until` (the end time: the whole run with its end, as the apps run it),
    /// calling `callback()` every `every` seconds of simulated time (after every step when 0)
    /// and `progress()` a few times a second. Returns the exit code of an ended run, else 0.
    int advance(double until, double every, py::object callback, py::object progress);

    app::Simulation<Dim>& simulation() { return sim_; }
    /// Whether the run has ended (summary.json written): no more steps.
    bool finished() const { return finished_; }
    /// Counts the steps started: a Particles object of an earlier count is stale.
    std::uint64_t generation() const { return generation_; }
    py::array view(const py::object& self, const std::string& name, bool writable);

    // The observer's calls (front_end_observer below).
    double landingTime() const;
    void beforeStep();
    void afterStep();

  private:
    using Clock = std::chrono::steady_clock;
    void checkCanStep() const;
    /// Refuses a call from another thread while one runs step() or run().
    void checkSameThread(const char* what) const;
    /// Marks step() or run() as running on this thread while it lives (the GIL held at both
    /// ends).
    struct Running {
        std::optional<std::thread::id>& runner;
        explicit Running(std::optional<std::thread::id>& r) : runner(r) {
            runner = std::this_thread::get_id();
        }
        ~Running() { runner.reset(); }
    };
    void callPython(const py::object& f);
    void keepPythonError(py::error_already_set&& e);
    /// Throws the error a callback or Ctrl-C left, if any.
    void throwPending();

    app::Simulation<Dim> sim_;
    bool finished_ = false;
    std::uint64_t generation_ = 0;
    std::weak_ptr<ViewKeeper> views_;        ///< of the particles as they are now
    std::optional<std::thread::id> runner_;  ///< the thread in step() or run(), if any
    // While advance() runs:
    bool armed_ = false;
    double every_ = 0;
    double nextCall_ = std::numeric_limits<double>::infinity();
    py::object callback_, progress_;
    Clock::time_point lastLook_, lastProgress_;
    std::optional<py::error_already_set> pending_;
};

}  // namespace num::python
