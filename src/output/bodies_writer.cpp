#include "output/bodies_writer.hpp"

#include "app/file.hpp"
#include "app/formatted.hpp"
#include "output/csv_rows.hpp"
#include "output/series_plot.hpp"

namespace num::app {

namespace {

/// The columns after time and body: position, velocity, attitude, angular velocity, force and
/// torque of the fluid.
template <int Dim>
std::string columns() {
    if constexpr (Dim == 2) return "x,y,vx,vy,angle,omega,fx,fy,torque,heat";
    return "x,y,z,vx,vy,vz,q0,q1,q2,q3,wx,wy,wz,fx,fy,fz,tx,ty,tz,heat";
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

/// Each body's heat sum m c T over its particles [J; 2D: J/m], T in degC (0 without heat).
template <int Dim>
std::vector<double> bodyHeat(const sph::Storage<Dim>& s, std::size_t bodies) {
    using sph::QuantityId;
    std::vector<double> heat(bodies, 0.0);
    if (!s.has(QuantityId::TEMPERATURE)) return heat;
    const auto body = s.template getValue<int>(QuantityId::BODY_INDEX);
    const auto m = s.template getValue<double>(QuantityId::MASS);
    const auto T = s.template getValue<double>(QuantityId::TEMPERATURE);
    const auto material = s.template getValue<int>(QuantityId::MATERIAL);
    std::vector<double> c;
    for (const auto& mat : s.materials())
        c.push_back(mat->params().template get<double>("heat_capacity"));
    for (sph::Size j = 0; j < s.size(); ++j)
        if (body[j] >= 0) heat[std::size_t(body[j])] += m[j] * c[std::size_t(material[j])] * T[j];
    return heat;
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
void BodiesWriter<Dim>::write(const sph::Storage<Dim>& storage, const std::vector<OutputField>&,
                              double t, int) {
    const std::vector<double> heat = bodyHeat(storage, bodies_->bodies.size());
    std::string rows;
    for (std::size_t i = 0; i < bodies_->bodies.size(); ++i) {
        const sph::MovingBody<Dim>& b = bodies_->bodies[i];
        if (!b.motion.moves()) continue;
        const sph::BodyState<Dim>& s = b.state;
        rows += formatted("%.10g", t) + "," + csvField(b.name) + numbers(s.position) +
                numbers(s.velocity) + attitude(s.attitude) + numbers(s.spin) +
                numbers(b.fluidForce) + numbers(b.fluidTorque) + formatted(",%.10g", heat[i]) +
                "\n";
    }
    appendToFile(c_.path("bodies.csv"), rows);
}

template <int Dim>
void BodiesWriter<Dim>::finish(bool, EndOfRun&) {
    if (plots_.empty()) return;
    std::vector<std::string> pictures;
    for (const std::string& format : plots_) pictures.push_back(c_.path("bodies." + format));
    // Without matplotlib the probe plot's note says why; the bodies' plot is then left out too.
    plotSeries(c_.path("bodies.csv"), pictures, "bodies: " + c_.title, c_.path("plot_series.log"));
}

template class BodiesWriter<2>;
template class BodiesWriter<3>;

}  // namespace num::app
