// _numerics.Simulation2 / Simulation3: Driver<Dim> (driver.hpp) and its Python methods.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "driver.hpp"
#include "set_up_interrupt.hpp"

namespace num::python {

namespace {

app::RunOptions runOptions(int threads, const std::optional<std::string>& out, bool quiet,
                           const std::optional<double>& endTime,
                           const std::optional<std::string>& backend) {
    app::RunOptions o;
    o.program = "numerics";
    o.threads = threads, o.outDir = out, o.quiet = quiet, o.endTime = endTime;
    if (backend) o.backend = *backend, o.backendGiven = true;
    o.progressLine = false;   // the Python side draws its own (tqdm)
    o.handleSignals = false;  // Python's: Ctrl-C reaches the run through PyErr_CheckSignals
    return o;
}

/// The moving bodies now: names, and per body rows of position, velocity, attitude (the angle
/// in 2D, the quaternion q0..q3 in 3D), angular velocity, the fluid's force and torque.
template <int Dim>
py::dict bodiesDict(const sph::MovingBodies<Dim>* bodies) {
    py::dict out;
    py::list names;
    std::vector<double> position, velocity, attitude, spin, force, torque;
    constexpr int S = Dim == 2 ? 1 : 3, A = Dim == 2 ? 1 : 4;
    std::size_t n = 0;
    static const std::vector<sph::MovingBody<Dim>> none;
    for (const auto& b : bodies ? bodies->bodies : none) {
        if (!b.motion.moves()) continue;
        ++n, names.append(b.name);
        for (int k = 0; k < Dim; ++k)
            position.push_back(b.state.position[k]), velocity.push_back(b.state.velocity[k]),
                force.push_back(b.fluidForce[k]);
        for (int k = 0; k < S; ++k)
            spin.push_back(b.state.spin[k]), torque.push_back(b.fluidTorque[k]);
        if constexpr (Dim == 2)
            attitude.push_back(b.state.attitude.angle);
        else
            attitude.insert(attitude.end(), b.state.attitude.q.begin(), b.state.attitude.q.end());
    }
    auto rows = [n](const std::vector<double>& v, int columns) {
        py::array_t<double> a({py::ssize_t(n), py::ssize_t(columns)});
        std::copy(v.begin(), v.end(), a.mutable_data());
        return a;
    };
    out["name"] = names;
    out["position"] = rows(position, Dim), out["velocity"] = rows(velocity, Dim);
    out[Dim == 2 ? "angle" : "quaternion"] = rows(attitude, A);
    out["angular_velocity"] = rows(spin, S);
    out["force"] = rows(force, Dim), out["torque"] = rows(torque, S);
    return out;
}

/// Holds a prescribed body's velocity and angular velocity at these values from the next step
/// on (a controlled paddle); the body is named as in bodies.csv.
template <int Dim>
void setBodyVelocity(Driver<Dim>& d, const std::string& body, const std::vector<double>& velocity,
                     const std::vector<double>& angularVelocity) {
    constexpr std::size_t S = Dim == 2 ? 1 : 3;
    sph::MovingBodies<Dim>* bodies = d.simulation().movingBodies();
    sph::MovingBody<Dim>* found = nullptr;
    for (std::size_t i = 0; bodies && i < bodies->bodies.size(); ++i)
        if (bodies->bodies[i].name == body) found = &bodies->bodies[i];
    if (!found || found->motion.type != sph::MotionType::PRESCRIBED)
        throw app::AppError(
            app::ExitCode::USAGE,
            "body: \"" + body +
                "\" is not a prescribed body of this scene (bodies.csv names them)");
    if (velocity.size() != std::size_t(Dim) || angularVelocity.size() != S)
        throw app::AppError(app::ExitCode::USAGE, "velocity: " + std::to_string(Dim) +
                                                      " numbers, angular_velocity: " +
                                                      std::to_string(S) + " (m/s, rad/s)");
    sph::Vector<Dim> v;
    sph::Spin<Dim> w;
    for (int k = 0; k < Dim; ++k) v[k] = velocity[std::size_t(k)];
    for (std::size_t k = 0; k < S; ++k) w[int(k)] = angularVelocity[k];
    found->motion.velocity = [v](sph::Float) { return v; };
    found->motion.spin = [w](sph::Float) { return w; };
}

template <int Dim>
void bindDriver(py::module_& m, const char* name) {
    using D = Driver<Dim>;
    py::class_<D>(m, name)
        .def(py::init([](const app::SceneDocument& doc, int threads,
                         const std::optional<std::string>& out, bool quiet,
                         const std::optional<double>& endTime,
                         const std::optional<std::string>& backend) {
                 const app::RunOptions o = runOptions(threads, out, quiet, endTime, backend);
                 const StopSetUpOnCtrlC ctrlC;
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
        .def("bodies", [](D& d) { return bodiesDict<Dim>(d.simulation().movingBodies()); })
        .def("set_body_velocity", &setBodyVelocity<Dim>, py::arg("body"), py::arg("velocity"),
             py::arg("angular_velocity"))
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
