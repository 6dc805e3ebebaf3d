// Conservation diagnostics over the fluid particles, and probes that interpolate fields at
// points (Shepard-normalised SPH interpolation over fluid neighbours).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "sph/kernel_choice.hpp"
#include "sph/storage.hpp"

namespace num::app {

template <int Dim>
struct Conservation {
    double mass = 0;              ///< sum m [kg]
    sph::Vector<Dim> momentum{};  ///< sum m v [kg m/s]
    double kinetic = 0;           ///< sum m |v|^2 / 2 [J]
    double potential = 0;         ///< -sum m g . x [J]
    double thermal = 0;           ///< sum m c T [J], T in degC (relative to 0 degC)
};

/// Sums over fluid particles (all particles when the storage has no KIND).
template <int Dim>
Conservation<Dim> conservation(const sph::Storage<Dim>& s, const sph::Vector<Dim>& gravity) {
    using sph::QuantityId;
    Conservation<Dim> c;
    const auto x = s.template getValue<sph::Vector<Dim>>(QuantityId::POSITION);
    const auto v = s.template getDt<sph::Vector<Dim>>(QuantityId::POSITION);
    const auto m = s.template getValue<double>(QuantityId::MASS);
    const bool kind = s.has(QuantityId::KIND), temp = s.has(QuantityId::TEMPERATURE);
    std::vector<double> heatCapacity;
    for (const auto& mat : s.materials())
        heatCapacity.push_back(mat->params().template get<double>("heat_capacity"));
    for (sph::Size i = 0; i < s.size(); ++i) {
        if (kind && s.template getValue<int>(QuantityId::KIND)[i] != 0) continue;
        c.mass += m[i];
        c.momentum += v[i] * m[i];
        c.kinetic += 0.5 * m[i] * normSqr(v[i]);
        c.potential -= m[i] * dot(gravity, x[i]);
        if (temp && !heatCapacity.empty()) {
            const int mat =
                s.has(QuantityId::MATERIAL) ? s.template getValue<int>(QuantityId::MATERIAL)[i] : 0;
            c.thermal +=
                m[i] * heatCapacity[mat] * s.template getValue<double>(QuantityId::TEMPERATURE)[i];
        }
    }
    return c;
}

/// The volume flow rate through side `high` of `axis` of the box [lo, hi], along +axis
/// [m^3/s; m^2/s in 2D]: the fluid in the slab one spacing dx deep inside the side,
/// Q = sum_i V_i u_i,axis / dx with V_i = m_i / rho_i (the slab's mean of u times its area).
template <int Dim>
double sideFlowRate(const sph::Storage<Dim>& s, int axis, int high, const sph::Vector<Dim>& lo,
                    const sph::Vector<Dim>& hi, double dx) {
    using sph::QuantityId;
    const auto x = s.template getValue<sph::Vector<Dim>>(QuantityId::POSITION);
    const auto v = s.template getDt<sph::Vector<Dim>>(QuantityId::POSITION);
    const auto m = s.template getValue<double>(QuantityId::MASS);
    const auto rho = s.template getValue<double>(QuantityId::DENSITY);
    const auto kind = s.template getValue<int>(QuantityId::KIND);
    const double from = high ? hi[axis] - dx : lo[axis], to = from + dx;
    double q = 0;
    for (sph::Size i = 0; i < s.size(); ++i)
        if (sph::isFluid(kind[i]) && x[i][axis] >= from && x[i][axis] < to)
            q += m[i] / rho[i] * v[i][axis];
    return q / dx;
}

/// The value of `field` (velocity gives one value per axis) at point p, interpolated from the
/// fluid particles within the kernel support; NaN where no fluid particle is near.
template <int Dim>
std::vector<double> probe(const sph::Storage<Dim>& s, const sph::RunKernel<Dim>& kernel,
                          const sph::Vector<Dim>& p, const std::string& field) {
    using sph::QuantityId;
    const auto x = s.template getValue<sph::Vector<Dim>>(QuantityId::POSITION);
    const auto m = s.template getValue<double>(QuantityId::MASS);
    const auto rho = s.template getValue<double>(QuantityId::DENSITY);
    const bool kind = s.has(QuantityId::KIND);
    const double support = kernel.supportRadius();
    const std::size_t n = field == "velocity" ? Dim : 1;
    std::vector<double> sum(n, 0.0);
    double weight = 0;
    for (sph::Size j = 0; j < s.size(); ++j) {
        if (kind && s.template getValue<int>(QuantityId::KIND)[j] != 0) continue;
        const double r = norm(p - x[j]);
        if (r >= support) continue;
        const double w = m[j] / rho[j] * kernel.W(r);
        weight += w;
        if (field == "velocity") {
            const auto v = s.template getDt<sph::Vector<Dim>>(QuantityId::POSITION)[j];
            for (int k = 0; k < Dim; ++k) sum[k] += w * v[k];
        } else {
            const QuantityId id = field == "density"    ? QuantityId::DENSITY
                                  : field == "pressure" ? QuantityId::PRESSURE
                                                        : QuantityId::TEMPERATURE;
            if (s.has(id)) sum[0] += w * s.template getValue<double>(id)[j];
        }
    }
    for (double& v : sum) v = weight > 0 ? v / weight : std::nan("");
    return sum;
}

}  // namespace num::app
