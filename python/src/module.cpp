// _numerics: the compiled part of the Python package numerics (python/numerics/).
#include "bindings.hpp"

PYBIND11_MODULE(_numerics, m) {
    m.doc() = "numerics: SPH runs from Python (the package numerics wraps this module)";
    num::python::bindErrors(m);
    num::python::bindScene(m);
    num::python::bindSimulation(m);
}
