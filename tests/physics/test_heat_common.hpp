// Shared set-up of the heat tests: particle lattices, materials, a conduction-only solver, and
// the validation output (NUMERICS_VALIDATION_OUT / NUMERICS_VALIDATION_FULL).
#pragma once

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "../validation_output.hpp"
#include "sph/boundary/thermal_walls.hpp"
#include "sph/terms/heat_conduction.hpp"
#include "sph/timestepping.hpp"

namespace num::sph::heat_test {

using validation::fullResolution;
using validation::ProfileRow;
using validation::ValidationResult;

/// Cell centres of a lattice of spacing dx filling [lo, hi) (n = round((hi - lo) / dx) per axis).
template <int Dim>
std::vector<Vector<Dim>> lattice(Vector<Dim> lo, Vector<Dim> hi, double dx) {
    std::array<int, Dim> n{};
    std::size_t total = 1;
    for (int k = 0; k < Dim; ++k) {
        n[k] = int(std::lround((hi[k] - lo[k]) / dx));
        total *= std::size_t(n[k]);
    }
    std::vector<Vector<Dim>> x;
    x.reserve(total);
    std::array<int, Dim> idx{};
    for (std::size_t c = 0; c < total; ++c) {
        Vector<Dim> p;
        for (int k = 0; k < Dim; ++k) p[k] = lo[k] + (idx[k] + 0.5) * dx;
        x.push_back(p);
        for (int k = 0; k < Dim && ++idx[k] == n[k]; ++k) idx[k] = 0;
    }
    return x;
}

/// A material with the given conductivity, density and heat capacity.
inline std::shared_ptr<Material> thermalMaterial(const std::string& name, double k, double rho,
                                                 double c) {
    auto m = std::make_shared<Material>(name);
    m->params().set("conductivity", k).set("density", rho).set("heat_capacity", c);
    return m;
}

/// Fixed particles on the given positions, volume dx^Dim each, of material materialOf(x) and
/// temperature T0(x); every particle is a fluid particle unless kindOf says otherwise.
template <int Dim>
Storage<Dim> thermalStorage(const std::vector<Vector<Dim>>& x, double dx,
                            const std::vector<std::shared_ptr<Material>>& materials,
                            const std::function<int(const Vector<Dim>&)>& materialOf,
                            const std::function<double(const Vector<Dim>&)>& T0,
                            const std::function<ParticleKind(const Vector<Dim>&)>& kindOf = {}) {
    Storage<Dim> s;
    s.template insert<Vector<Dim>>(QuantityId::POSITION, OrderEnum::SECOND, x);
    const double volume = std::pow(dx, Dim);
    std::vector<int> mat(x.size()), kind(x.size());
    std::vector<double> m(x.size()), rho(x.size()), T(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        mat[i] = materialOf(x[i]);
        rho[i] = materials[mat[i]]->params().get<double>("density");
        m[i] = rho[i] * volume;
        T[i] = T0(x[i]);
        kind[i] = int(kindOf ? kindOf(x[i]) : ParticleKind::FLUID);
    }
    s.template insert<int>(QuantityId::MATERIAL, OrderEnum::ZERO, mat);
    s.template insert<int>(QuantityId::KIND, OrderEnum::ZERO, kind);
    s.template insert<double>(QuantityId::MASS, OrderEnum::ZERO, m);
    s.template insert<double>(QuantityId::DENSITY, OrderEnum::ZERO, rho);
    s.template insert<double>(QuantityId::TEMPERATURE, OrderEnum::FIRST, T);
    for (const auto& mm : materials) s.materials().push_back(mm);
    return s;
}

/// Total heat sum_i m_i c_i T_i of the particles for which select(i) is true (all by default).
template <int Dim>
double totalHeat(const Storage<Dim>& s, const std::function<bool(Size)>& select = {}) {
    const auto m = s.template getValue<double>(QuantityId::MASS);
    const auto T = s.template getValue<double>(QuantityId::TEMPERATURE);
    const auto mat = s.template getValue<int>(QuantityId::MATERIAL);
    double sum = 0;
    for (Size i = 0; i < s.size(); ++i)
        if (!select || select(i))
            sum +=
                m[i] * s.materials()[mat[i]]->params().template get<double>("heat_capacity") * T[i];
    return sum;
}

/// Run settings for particles on a lattice of spacing dx with h = hOverDx dx.
inline RunSettings heatSettings(double dx, double hOverDx = 1.3,
                                const std::string& kernel = "wendland_c2") {
    RunSettings rs;
    rs.set("smoothing_length", hOverDx * dx).set("kernel", kernel).set("reorder_every", 0);
    return rs;
}

}  // namespace num::sph::heat_test
