// Driver<Dim> (driver.hpp): a Simulation's steps with Python's callbacks, progress, Ctrl-C and
// particle views between them.
#include "driver.hpp"

#include <string>
#include <utility>

#include "app/formatted.hpp"

namespace num::python {

namespace {

/// The Driver's part in each step: callbacks land on their times, views detach before a step.
template <int Dim>
class FrontEndObserver final : public app::IStepObserver<Dim> {
  public:
    explicit FrontEndObserver(Driver<Dim>& d) : d_(d) {}
    double landingTime() const override { return d_.landingTime(); }
    void beforeStep(app::Simulation<Dim>&, bool) override { d_.beforeStep(); }
    void afterStep(app::Simulation<Dim>&) override { d_.afterStep(); }

  private:
    Driver<Dim>& d_;
};

/// Releases the callbacks when advance() returns, however it returns.
struct Disarm {
    bool& armed;
    py::object &callback, &progress;
    ~Disarm() {
        armed = false;
        callback = py::none(), progress = py::none();
    }
};

}  // namespace

template <int Dim>
Driver<Dim>::Driver(const app::SceneDocument& doc, const app::RunOptions& options)
    : sim_(doc, options) {
    sim_.addObserver(std::make_unique<FrontEndObserver<Dim>>(*this));
}

template <int Dim>
void Driver<Dim>::checkSameThread(const char* what) const {
    if (runner_ && *runner_ != std::this_thread::get_id())
        throw app::AppError(app::ExitCode::USAGE,
                            std::string(what) +
                                " cannot be called while another thread runs this Simulation "
                                "(its step() or run()): drive one Simulation from one thread at "
                                "a time, or wait for that call to return");
}

template <int Dim>
void Driver<Dim>::checkCanStep() const {
    checkSameThread("step() and run()");
    if (armed_)
        throw app::AppError(app::ExitCode::USAGE,
                            "step() and run() cannot be called from a callback of run(): return "
                            "from it, and the run goes on");
    if (finished_)
        throw app::AppError(app::ExitCode::USAGE,
                            "the run has ended (summary.json written): make a new Simulation to "
                            "run again");
    if (reached(sim_.time(), sim_.endTime()))
        throw app::AppError(app::ExitCode::USAGE,
                            "the run is at its end time (t = " + app::formatted("%g", sim_.time()) +
                                " s): call run() to write its end, or give a later end_time");
}

template <int Dim>
double Driver<Dim>::step() {
    checkCanStep();
    const Running running(runner_);
    py::gil_scoped_release released;
    return sim_.step();
}

template <int Dim>
int Driver<Dim>::advance(double until, double every, py::object callback, py::object progress) {
    if (finished_ || armed_ || runner_) checkCanStep();
    if (!std::isfinite(until) || !std::isfinite(every) || every < 0)
        throw app::AppError(app::ExitCode::USAGE,
                            "run: until and every must be finite (every >= 0), found until = " +
                                app::formatted("%g", until) +
                                ", every = " + app::formatted("%g", every));
    const Running running(runner_);
    armed_ = true, every_ = every, callback_ = std::move(callback), progress_ = std::move(progress);
    nextCall_ = every_ > 0 ? (std::floor(sim_.time() / every_ + 1e-9) + 1) * every_ : 0;
    lastLook_ = lastProgress_ = Clock::now();
    const Disarm disarm{armed_, callback_, progress_};
    int code = 0;
    const bool whole = reached(until, sim_.endTime());
    try {
        py::gil_scoped_release released;
        if (!whole) sim_.advanceTo(until);
        if (whole || sim_.stopRequested()) code = sim_.run(), finished_ = true;
    } catch (const PythonErrorPending&) {
        // A callback raised: the steps stopped after it; its error is thrown below.
    } catch (...) {
        finished_ = finished_ || whole;  // a failed run's end is written (summary.json)
        throw;
    }
    throwPending();
    return code;
}

template <int Dim>
double Driver<Dim>::landingTime() const {
    return armed_ && !callback_.is_none() && every_ > 0 ? nextCall_
                                                        : std::numeric_limits<double>::infinity();
}

template <int Dim>
void Driver<Dim>::beforeStep() {
    ++generation_;
    if (views_.expired()) return;
    py::gil_scoped_acquire gil;
    // The values stay: only the buffers move, into the views' keeper.
    if (auto keeper = views_.lock())
        keeper->detach(const_cast<sph::Storage<Dim>&>(sim_.particles()));
    views_.reset();
}

template <int Dim>
void Driver<Dim>::afterStep() {
    if (!armed_) return;
    const bool call = !callback_.is_none() && reached(sim_.time(), nextCall_);
    const Clock::time_point now = Clock::now();
    if (!call && now - lastLook_ < std::chrono::milliseconds(20)) return;
    py::gil_scoped_acquire gil;
    lastLook_ = now;
    if (call) {
        if (every_ > 0) nextCall_ = (std::floor(sim_.time() / every_ + 1e-9) + 1) * every_;
        callPython(callback_);
    }
    if (!progress_.is_none() && now - lastProgress_ > std::chrono::milliseconds(100))
        lastProgress_ = now, callPython(progress_);
    if (PyErr_CheckSignals() != 0) keepPythonError(py::error_already_set());
}

template <int Dim>
void Driver<Dim>::callPython(const py::object& f) {
    try {
        f();
    } catch (py::error_already_set& e) {
        keepPythonError(std::move(e));
    }
}

/// Ctrl-C (KeyboardInterrupt) stops the run cleanly; another error stops the steps at once.
template <int Dim>
void Driver<Dim>::keepPythonError(py::error_already_set&& e) {
    const bool interrupt = e.matches(PyExc_KeyboardInterrupt);
    if (!pending_) pending_.emplace(std::move(e));
    if (interrupt)
        sim_.requestStop();
    else
        throw PythonErrorPending{};
}

template <int Dim>
void Driver<Dim>::throwPending() {
    if (!pending_) return;
    py::error_already_set e = std::move(*pending_);
    pending_.reset();
    throw e;
}

template <int Dim>
py::array Driver<Dim>::view(const py::object& self, const std::string& name, bool writable) {
    checkSameThread("particles");
    std::shared_ptr<ViewKeeper> keeper = views_.lock();
    if (!keeper) keeper = std::make_shared<ViewKeeper>(self), views_ = keeper;
    sph::Storage<Dim>& s =
        writable ? sim_.particlesToChange() : const_cast<sph::Storage<Dim>&>(sim_.particles());
    return particleView(s, sim_.fieldNames(), name, writable, keeper);
}

template class Driver<2>;
template class Driver<3>;

}  // namespace num::python
