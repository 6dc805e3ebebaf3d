// _numerics.Simulation2 / Simulation3: Driver<Dim> (driver.hpp) and its Python methods.
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "driver.hpp"

namespace num::python {

namespace {

io::RunOptions runOptions(int threads, const std::optional<std::string>& out, bool quiet,
                          const std::optional<double>& endTime,
                          const std::optional<std::string>& backend) {
    io::RunOptions o;
    o.program = "numerics";
    o.threads = threads, o.outDir = out, o.quiet = quiet, o.endTime = endTime;
    if (backend) o.backend = *backend, o.backendGiven = true;
    o.progressLine = false;   // the Python side draws its own (tqdm)
    o.handleSignals = false;  // Python's: Ctrl-C reaches the run through PyErr_CheckSignals
    return o;
}

template <int Dim>
void bindDriver(py::module_& m, const char* name) {
    using D = Driver<Dim>;
    py::class_<D>(m, name)
        .def(py::init([](const io::SceneDocument& doc, int threads,
                         const std::optional<std::string>& out, bool quiet,
                         const std::optional<double>& endTime,
                         const std::optional<std::string>& backend) {
                 const io::RunOptions o = runOptions(threads, out, quiet, endTime, backend);
                 py::gil_scoped_release released;
                 return std::make_unique<D>(doc, o);
             }),
             py::arg("doc"), py::arg("threads"), py::arg("out"), py::arg("quiet"),
             py::arg("end_time"), py::arg("backend"))
        .def("step", &D::step)
        .def("advance", &D::advance, py::arg("until"), py::arg("every"), py::arg("callback"),
             py::arg("progress"))
        .def("view", [](py::object self, const std::string& field,
                        bool writable) { return self.cast<D&>().view(self, field, writable); })
        .def("fields",
             [](D& d) {
                 return particleFieldNames(d.simulation().particles(), d.simulation().fieldNames());
             })
        .def_property_readonly("count", [](D& d) { return d.simulation().particles().size(); })
        .def_property_readonly("time", [](D& d) { return d.simulation().time(); })
        .def_property_readonly("steps", [](D& d) { return d.simulation().steps(); })
        .def_property_readonly("end_time", [](D& d) { return d.simulation().endTime(); })
        .def_property_readonly("finished", &D::finished)
        .def_property_readonly("generation", &D::generation)
        .def_property_readonly("output_directory",
                               [](D& d) { return d.simulation().scene().output.directory; });
}

}  // namespace

void bindSimulation(py::module_& m) {
    bindViewKeeper(m);
    bindDriver<2>(m, "Simulation2");
    bindDriver<3>(m, "Simulation3");
}

}  // namespace num::python
