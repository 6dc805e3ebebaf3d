#include "output/bodies_writer.hpp"

#include "io/file.hpp"
#include "io/formatted.hpp"
#include "output/csv_rows.hpp"

namespace num::io {

namespace {

/// The columns after time and body: position, velocity, attitude, angular velocity, force and
/// torque of the fluid.
template <int Dim>
std::string columns() {
    if constexpr (Dim == 2) return "x,y,vx,vy,angle,omega,fx,fy,torque";
    return "x,y,z,vx,vy,vz,q0,q1,q2,q3,wx,wy,wz,fx,fy,fz,tx,ty,tz";
}

template <int N>
std::string numbers(const Vec<double, N>& v) {
    std::string out;
    for (int k = 0; k < N; ++k) out += formatted(",%.10g", v[k]);
    return out;
}

template <int Dim>
std::string attitude(const sph::Attitude<Dim>& a) {
    if constexpr (Dim == 2)
        return formatted(",%.10g", a.angle);
    else
        return formatted(",%.10g,%.10g,%.10g,%.10g", a.q[0], a.q[1], a.q[2], a.q[3]);
}

/// A CSV field, quoted where needed (RFC 4180).
std::string field(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string q = "\"";
    for (char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

}  // namespace

template <int Dim>
void BodiesWriter<Dim>::start() {
    writeFileAtomically(c_.path("bodies.csv"), "time,body," + columns<Dim>() + "\n");
}

template <int Dim>
void BodiesWriter<Dim>::resume(double t, const OutputSeries&) {
    if (!keepCsvRowsUpTo(c_.path("bodies.csv"), t)) start();
}

template <int Dim>
void BodiesWriter<Dim>::write(const sph::Storage<Dim>&, const std::vector<OutputField>&, double t,
                              int) {
    std::string rows;
    for (const sph::MovingBody<Dim>& b : bodies_->bodies) {
        if (!b.motion.moves()) continue;
        const sph::BodyState<Dim>& s = b.state;
        rows += formatted("%.10g", t) + "," + field(b.name) + numbers(s.position) +
                numbers(s.velocity) + attitude(s.attitude) + numbers(s.spin) +
                numbers(b.fluidForce) + numbers(b.fluidTorque) + "\n";
    }
    appendToFile(c_.path("bodies.csv"), rows);
}

template class BodiesWriter<2>;
template class BodiesWriter<3>;

}  // namespace num::io
