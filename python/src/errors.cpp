// The library's errors as Python exceptions with the apps' one-line messages and exit codes
// (src/app/app.cpp, reportingErrors): numerics.SceneError for the scene's file, syntax,
// content and expressions, numerics.RunError for the rest (python/numerics/errors.py).
#include <new>
#include <string>

#include "app/errors.hpp"
#include "app/expression.hpp"
#include "bindings.hpp"
#include "set_up_interrupt.hpp"
#include "sph/scheduler.hpp"
#include "sph/settings_error.hpp"
#include "sph/setup/set_up_interrupt.hpp"

namespace num::python {

namespace {

using app::ExitCode;

bool isSceneCode(ExitCode code) {
    return code == ExitCode::SCENE_FILE || code == ExitCode::JSON_SYNTAX ||
           code == ExitCode::SCENE || code == ExitCode::EXPRESSION;
}

/// Sets the Python error numerics.SceneError or RunError(message, exit_code).
void raise(ExitCode code, const std::string& message) {
    const py::object errors = py::module_::import("numerics.errors");
    const py::object type = errors.attr(isSceneCode(code) ? "SceneError" : "RunError");
    const py::object error = type(message, int(code));
    PyErr_SetObject(type.ptr(), error.ptr());
}

void translate(std::exception_ptr thrown) {
    try {
        std::rethrow_exception(thrown);
    } catch (const py::builtin_exception&) {
        throw;  // pybind11's own (ValueError, KeyError...)
    } catch (const py::error_already_set&) {
        throw;  // a Python error on its way back
    } catch (const sph::SetUpInterrupted&) {
        // Ctrl-C in a set-up: the signal handler's exception (KeyboardInterrupt) is set.
        if (!PyErr_Occurred()) PyErr_SetNone(PyExc_KeyboardInterrupt);
    } catch (const app::AppError& e) {
        raise(e.code(), e.what());
    } catch (const app::ExpressionError& e) {
        raise(ExitCode::EXPRESSION, std::string("expression: ") + e.what());
    } catch (const sph::SettingsError& e) {
        raise(ExitCode::SCENE, std::string("scene setting: ") + e.what());
    } catch (const sph::ThreadStartError& e) {
        raise(ExitCode::RESOURCES, std::string(e.what()) +
                                       ": run with fewer threads, or raise the limit on processes "
                                       "or memory (ulimit -u, ulimit -v)");
    } catch (const std::bad_alloc&) {
        raise(ExitCode::RESOURCES,
              "out of memory (try a larger particles.spacing, fewer threads, or raise the memory "
              "limit: ulimit -v)");
    } catch (const std::exception& e) {
        raise(ExitCode::INTERNAL,
              std::string("internal error: ") + e.what() + " (please report it)");
    }
}

}  // namespace

void bindErrors(py::module_& m) {
    py::register_exception_translator(translate);
    installSetUpInterrupt();
    m.def("_sigint_at_set_up_poll", &sendSigintAtSetUpPoll, py::arg("poll"),
          "For tests: the next set-up sends itself SIGINT at this poll (0: never).");
}

}  // namespace num::python
