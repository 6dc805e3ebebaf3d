// _numerics.SceneDocument over app::SceneDocument: the scene as the apps read it, with --set.
#include <pybind11/stl.h>

#include "app/scene_loader.hpp"
#include "bindings.hpp"
#include "set_up_interrupt.hpp"

namespace num::python {

void bindScene(py::module_& m) {
    using app::SceneDocument;
    py::class_<SceneDocument>(m, "SceneDocument")
        .def_static("from_file", &SceneDocument::fromFile, py::arg("path"),
                    "Reads and parses a scene file.")
        .def_static("from_text", &SceneDocument::fromText, py::arg("text"), py::arg("file"),
                    "Parses scene text; `file` names it in messages.")
        .def("set", &SceneDocument::set, py::arg("assignment"),
             "Applies \"a.b.c=VALUE\" as --set does.")
        .def_property_readonly("dimension", &SceneDocument::dimension)
        .def_property_readonly("file", &SceneDocument::file)
        .def("dump", &SceneDocument::dump, "The document as JSON text.")
        .def(
            "check",
            [](const SceneDocument& d) {
                const StopSetUpOnCtrlC ctrlC;
                py::gil_scoped_release released;  // other Python threads run meanwhile
                if (d.dimension() == 3)
                    app::readScene<3>(d);
                else
                    app::readScene<2>(d);
            },
            "Reads and checks every key as a run does (its errors).")
        .def("copy", [](const SceneDocument& d) { return SceneDocument(d); });
}

}  // namespace num::python
