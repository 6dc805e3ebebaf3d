// Particles a front end wrote between steps (Simulation::particlesToChange, Python's
// particles_writable()): before the next step every written quantity is checked, so that a
// value the steps cannot take is refused naming the quantity and the particle (exit code 2,
// the front end's mistake) instead of crashing a step or running on without a word.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "app/errors.hpp"
#include "app/fields.hpp"
#include "app/formatted.hpp"
#include "spatial/cell_grid.hpp"
#include "sph/storage.hpp"

namespace num::app {

template <int Dim>
class WrittenParticles {
  public:
    /// What may not change, as it is when the particles are handed out to be written.
    void remember(const sph::Storage<Dim>& s) {
        kind_ = ints(s, sph::QuantityId::KIND);
        id_ = ints(s, sph::QuantityId::PARTICLE_ID);
    }

    /// Throws AppError (USAGE) at the first written value the next step cannot take; `domain`:
    /// the box the fluid lives in.
    void check(const sph::Storage<Dim>& s, const FieldNames& names,
               const Domain<Dim>& domain) const {
        using sph::QuantityId;
        const std::size_t n = s.size();
        const bool same = kind_.size() == n;  // a C++ front end may have added particles
        checkUnchanged(s, QuantityId::KIND, "kind", same ? kind_ : std::vector<int>{});
        checkUnchanged(s, QuantityId::PARTICLE_ID, "id", same ? id_ : std::vector<int>{});
        const auto kind = ints(s, QuantityId::KIND);
        for (std::size_t i = 0; i < kind.size(); ++i)
            if (kind[i] < 0 || kind[i] >= sph::kParticleKinds)
                refuse(i, "kind", std::to_string(kind[i]),
                       "0 (fluid), 1 (wall), 2 (body), 3 (inlet) or 4 (outlet)");
        const int materials = int(s.materials().size());
        const auto material = ints(s, QuantityId::MATERIAL);
        for (std::size_t i = 0; i < material.size(); ++i)
            if (material[i] < 0 || material[i] >= materials)
                refuse(i, "material", std::to_string(material[i]),
                       "the index of one of the run's materials, 0 to " +
                           std::to_string(materials - 1) + materialNames(s));
        // Every number finite: the steps bin positions into cells and divide by densities.
        s.forEach([&](QuantityId id, const sph::Quantity<Dim>& q) {
            const std::string name = id == QuantityId::POSITION ? "position" : nameOf(id, s, names);
            q.visit([&](const auto& b) {
                using T = typename std::decay_t<decltype(b.value)>::value_type;
                if constexpr (!std::is_same_v<T, int>) {
                    checkFinite(b.level(0), name);
                    if (id == QuantityId::POSITION && q.levels() > 1)
                        checkFinite(b.level(1), "velocity");
                }
            });
        });
        for (const auto& [id, name] :
             {std::pair{QuantityId::MASS, "mass"}, std::pair{QuantityId::DENSITY, "density"}})
            if (s.has(id) && s.get(id).template holds<sph::Float>()) {
                const auto v = s.template getValue<sph::Float>(id);
                for (std::size_t i = 0; i < v.size(); ++i)
                    if (!(v[i] > 0)) refuse(i, name, formatted("%g", v[i]), "a number > 0");
            }
        checkFluidState(s, kind, material);
        checkFluidInside(s, kind, domain);
        if (s.has(QuantityId::TEMPERATURE) &&
            s.get(QuantityId::TEMPERATURE).template holds<sph::Float>()) {
            const auto T = s.template getValue<sph::Float>(QuantityId::TEMPERATURE);
            for (std::size_t i = 0; i < T.size(); ++i)
                if (!(T[i] >= kAbsoluteZero))
                    refuse(i, "temperature", formatted("%g degC", T[i]),
                           "a temperature above absolute zero, -273.15 degC");
        }
    }

  private:
    static std::vector<int> ints(const sph::Storage<Dim>& s, sph::QuantityId id) {
        if (!s.has(id) || !s.get(id).template holds<int>()) return {};
        const auto v = s.template getValue<int>(id);
        return std::vector<int>(v.begin(), v.end());
    }

    [[noreturn]] static void refuse(std::size_t i, const std::string& quantity,
                                    const std::string& value, const std::string& expected) {
        throw AppError(ExitCode::USAGE, "particle " + std::to_string(i) + " was given the " +
                                            quantity + " " + value + " between steps: expected " +
                                            expected);
    }

    static void checkUnchanged(const sph::Storage<Dim>& s, sph::QuantityId id, const char* name,
                               const std::vector<int>& before) {
        const auto now = ints(s, id);
        if (before.size() != now.size()) return;
        for (std::size_t i = 0; i < now.size(); ++i)
            if (now[i] != before[i])
                refuse(i, name, std::to_string(now[i]),
                       "its " + std::string(name) + " as it was, " + std::to_string(before[i]) +
                           " (a particle's " + name + " cannot be changed)");
    }

    static std::string materialNames(const sph::Storage<Dim>& s) {
        std::string out;
        for (const auto& m : s.materials()) out += (out.empty() ? "" : ", ") + (m ? m->name() : "");
        return out.empty() ? "" : " (" + out + ")";
    }

    static std::string nameOf(sph::QuantityId id, const sph::Storage<Dim>& s,
                              const FieldNames& names) {
        for (const OutputField& f : outputFields(s, names))
            if (f.id == id && !f.derivative) return f.name;
        return "quantity " + std::to_string(int(id));
    }

    template <class Values>
    static void checkFinite(const Values& v, const std::string& name) {
        for (std::size_t i = 0; i < v.size(); ++i) {
            if constexpr (std::is_same_v<std::decay_t<decltype(v[i])>, sph::Float>) {
                if (!std::isfinite(v[i])) refuse(i, name, formatted("%g", v[i]), "a finite number");
            } else {
                for (int k = 0; k < Dim; ++k)
                    if (!std::isfinite(v[i][k]))
                        refuse(i, name, formatted("%g", v[i][k]) + " on axis " + std::to_string(k),
                               "finite numbers");
            }
        }
    }

    /// A fluid particle at or above its material's sound speed, or at a density beyond half
    /// or twice its rest density, stops the run on its next step (physical_check.hpp).
    static void checkFluidState(const sph::Storage<Dim>& s, const std::vector<int>& kind,
                                const std::vector<int>& material) {
        using sph::QuantityId;
        if (kind.size() != s.size() || material.size() != s.size() || !s.has(QuantityId::DENSITY) ||
            !s.get(QuantityId::DENSITY).template holds<sph::Float>() ||
            s.order(QuantityId::POSITION) != sph::OrderEnum::SECOND)
            return;
        const auto v = s.template getDt<sph::Vector<Dim>>(QuantityId::POSITION);
        const auto rho = s.template getValue<sph::Float>(QuantityId::DENSITY);
        for (std::size_t i = 0; i < s.size(); ++i) {
            if (kind[i] != int(sph::ParticleKind::FLUID) || !s.materials()[material[i]]) continue;
            const auto& params = s.materials()[material[i]]->params();
            const double rho0 = params.template get<double>("density");
            const double c0 = params.template get<double>("sound_speed");
            if (!(norm(v[i]) < c0))
                refuse(i, "velocity", formatted("%g m/s", norm(v[i])),
                       "a speed below its material's sound speed, " + formatted("%g m/s", c0));
            if (!(rho[i] >= 0.5 * rho0 && rho[i] <= 2 * rho0))
                refuse(
                    i, "density", formatted("%g kg/m^3", rho[i]),
                    "half to twice its material's rest density, " + formatted("%g kg/m^3", rho0));
        }
    }

    static constexpr double kAbsoluteZero = -273.15;  ///< degC

    /// A fluid particle lies inside the domain on its axes that are not periodic (the steps
    /// would mirror it back from a wall or drop it at an open side).
    static void checkFluidInside(const sph::Storage<Dim>& s, const std::vector<int>& kind,
                                 const Domain<Dim>& domain) {
        if (kind.size() != s.size()) return;
        const auto x = s.template getValue<sph::Vector<Dim>>(sph::QuantityId::POSITION);
        for (std::size_t i = 0; i < s.size(); ++i)
            for (int k = 0; k < Dim; ++k)
                if (kind[i] == int(sph::ParticleKind::FLUID) && !domain.periodic[k] &&
                    !(x[i][k] >= domain.min[k] && x[i][k] <= domain.max[k]))
                    refuse(i, "position", formatted("%g on axis ", x[i][k]) + std::to_string(k),
                           "a fluid particle inside the domain, " +
                               formatted("%g to %g", domain.min[k], domain.max[k]) +
                               " on that axis");
    }

    std::vector<int> kind_, id_;
};

}  // namespace num::app
