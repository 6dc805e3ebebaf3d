// Checks of the initial particles (internal to numerics_io): what the scene's expressions gave
// at every fluid particle must be a state the run can start from. A value that is not finite
// (sqrt(-1), 1/0) is an expression error (exit 6); a temperature below absolute zero or a
// pressure that the equation of state cannot turn into a positive density is a scene error (5).
#pragma once

#include <cmath>
#include <string>

#include "io/formatted.hpp"
#include "io/scene_setup.hpp"

namespace num::io {

template <int Dim>
void checkInitialState(const Scene<Dim>& scene, const SceneSetup<Dim>& setup,
                       const sph::Storage<Dim>& s) {
    using sph::QuantityId;
    const auto x = s.template getValue<sph::Vector<Dim>>(QuantityId::POSITION);
    const auto v = s.template getDt<sph::Vector<Dim>>(QuantityId::POSITION);
    const auto kind = s.template getValue<int>(QuantityId::KIND);
    const auto T = s.template getValue<double>(QuantityId::TEMPERATURE);
    const auto p = s.template getValue<double>(QuantityId::PRESSURE);
    const auto rho = s.template getValue<double>(QuantityId::DENSITY);
    for (sph::Size i = 0; i < s.size(); ++i) {
        if (kind[i] != int(sph::ParticleKind::FLUID)) continue;
        std::size_t b = 0;
        while (b < scene.fluids.size() && !setup.geometry.fluid[b].shape.contains(x[i])) ++b;
        if (b == scene.fluids.size()) continue;
        const FluidBlock<Dim>& f = scene.fluids[b];
        const std::string path = "fluids[" + std::to_string(b) + "].";
        const std::string at = formatted(" at x = %.6g, y = %.6g", x[i][0], x[i][1]) +
                               (Dim == 3 ? formatted(", z = %.6g", x[i][Dim - 1]) : std::string());
        auto fail = [&](const std::string& key, const Expression& e, const std::string& expected,
                        double found, ExitCode code) {
            throw sceneError(scene.file, path + key, expected,
                             formatted("%g", std::isnan(found) ? NAN : found) + at,
                             e.isConstant() ? "" : "from \"" + e.text() + "\"", code);
        };
        bool vFinite = true;
        for (int k = 0; k < Dim; ++k) vFinite = vFinite && std::isfinite(v[i][k]);
        for (int k = 0; k < Dim && !vFinite; ++k)
            if (!std::isfinite(v[i][k]))
                fail("velocity[" + std::to_string(k) + "]", f.velocity[k], "a finite velocity",
                     v[i][k], ExitCode::EXPRESSION);
        if (!std::isfinite(T[i]))
            fail("temperature", f.temperature, "a finite temperature", T[i], ExitCode::EXPRESSION);
        if (T[i] < -273.15)
            fail("temperature", f.temperature,
                 "a temperature at or above absolute zero (-273.15 degC)", T[i], ExitCode::SCENE);
        if (!std::isfinite(p[i]))
            fail("pressure", f.pressure, "a finite pressure", p[i], ExitCode::EXPRESSION);
        if (!(std::isfinite(rho[i]) && rho[i] > 0))
            fail("pressure", f.pressure,
                 "a pressure the equation of state turns into a positive density", p[i],
                 ExitCode::SCENE);
    }
}

/// Gravity must be finite over the whole run: sampled at 1001 times from 0 to the end time.
template <int Dim>
void checkGravity(const Scene<Dim>& scene) {
    for (int n = 0; n <= 1000; ++n) {
        const double t = scene.endTime * n / 1000.0;
        for (int k = 0; k < Dim; ++k) {
            const double g = scene.gravity[k](0, 0, 0, t);
            if (!std::isfinite(g)) {
                throw sceneError(scene.file, "gravity[" + std::to_string(k) + "]",
                                 "a finite acceleration over the run",
                                 formatted("%g at t = %g s", std::isnan(g) ? NAN : g, t),
                                 "from \"" + scene.gravity[k].text() + "\"", ExitCode::EXPRESSION);
            }
        }
    }
}

}  // namespace num::io
