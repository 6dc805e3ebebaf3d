// The pieces of the extension module _numerics, one file each: errors (AppError to Python's
// numerics.SceneError and numerics.RunError), scenes, runs and their particle views.
#pragma once

#include <pybind11/pybind11.h>

namespace num::python {

namespace py = pybind11;

/// Turns the library's errors into numerics.SceneError / RunError with the apps' messages.
void bindErrors(py::module_& m);
/// _numerics.SceneDocument: a scene file read and parsed, with --set's overrides.
void bindScene(py::module_& m);
/// _numerics.Simulation2 and Simulation3: a run, its steps, callbacks and particle views.
void bindSimulation(py::module_& m);

}  // namespace num::python
