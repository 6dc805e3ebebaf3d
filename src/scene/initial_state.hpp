// Checks of the initial particles (internal to numerics_app): what the scene's expressions gave
// at every fluid particle must be a state the run can start from. A value that is not finite
// (sqrt(-1), 1/0) is an expression error (exit 6); a temperature below absolute zero or a
// pressure that the equation of state turns into a density beyond half or twice the rest
// density (where the run would stop) is a scene error (5). setUpWarnings: temperatures outside
// the range a liquid's properties hold for, and runs of very many steps.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "app/formatted.hpp"
#include "app/scene_setup.hpp"

namespace num::app {

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
    const sph::EquationOfState eos = setup.model.equationOfState();
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
        // The run stops at a density beyond half or twice the rest density (physical_check.hpp):
        // a pressure giving one is refused here, before any step.
        if (!(std::isfinite(rho[i]) && rho[i] >= 0.5 * eos.rho0 && rho[i] <= 2 * eos.rho0))
            fail("pressure", f.pressure,
                 formatted("a pressure from %g to %g Pa, which the equation of state turns into a "
                           "density of half to twice the rest density %g kg/m^3",
                           eos.pressure(0.5 * eos.rho0), eos.pressure(2 * eos.rho0), eos.rho0),
                 p[i], ExitCode::SCENE);
    }
}

/// The temperatures [degC] within which a liquid's constant properties (density, viscosity,
/// conductivity, heat capacity, thermal expansion: water's by default) are taken to hold: water
/// stays liquid supercooled to about -20 degC and, under pressure, up to 200 degC (15.5 bar);
/// beyond, it is ice or steam, or its properties are off by a factor (docs/scenes.md).
inline constexpr double liquidTemperatureMin = -20, liquidTemperatureMax = 200;

/// A run estimated to take more steps than this is warned about.
inline constexpr double manySteps = 1e7;

/// Warnings about a valid scene at the edge of sense, each "file: key: text": a fluid block's
/// or emitter's temperature (the fluid's own) outside liquidTemperatureMin..Max, and a run of
/// more than manySteps steps, estimated from time.end over the acoustic step cfl h / c0. (A
/// wall or body held at another temperature is a boundary condition: validation cases hold
/// walls at -30 degC for a fluid of made-up properties.)
template <int Dim>
std::vector<std::string> setUpWarnings(const Scene<Dim>& scene, const SceneSetup<Dim>& setup,
                                       const sph::Storage<Dim>& s) {
    std::vector<std::string> out;
    auto checkTemperature = [&](const std::string& key, double lo, double hi) {
        if (lo >= liquidTemperatureMin && hi <= liquidTemperatureMax) return;
        out.push_back(
            scene.file + ": " + key + ": " +
            (lo == hi ? formatted("%g degC", lo) : formatted("%g to %g degC", lo, hi)) +
            formatted(" is outside %g to %g degC, the range where a liquid's constant properties "
                      "(water's) hold: the run takes them as they are",
                      liquidTemperatureMin, liquidTemperatureMax));
    };
    // Each fluid block's temperatures, at its particles.
    const auto x = s.template getValue<sph::Vector<Dim>>(sph::QuantityId::POSITION);
    const auto kind = s.template getValue<int>(sph::QuantityId::KIND);
    const auto T = s.template getValue<double>(sph::QuantityId::TEMPERATURE);
    std::vector<double> lo(scene.fluids.size(), INFINITY), hi(scene.fluids.size(), -INFINITY);
    for (sph::Size i = 0; i < s.size(); ++i) {
        if (kind[i] != int(sph::ParticleKind::FLUID)) continue;
        std::size_t b = 0;
        while (b < scene.fluids.size() && !setup.geometry.fluid[b].shape.contains(x[i])) ++b;
        if (b == scene.fluids.size()) continue;
        lo[b] = std::min(lo[b], double(T[i])), hi[b] = std::max(hi[b], double(T[i]));
    }
    for (std::size_t b = 0; b < scene.fluids.size(); ++b)
        if (lo[b] <= hi[b])
            checkTemperature("fluids[" + std::to_string(b) + "].temperature", lo[b], hi[b]);
    for (std::size_t e = 0; e < scene.emitters.size(); ++e)
        checkTemperature("emitters[" + std::to_string(e) + "].temperature",
                         scene.emitters[e].temperature, scene.emitters[e].temperature);
    // The steps: the acoustic time step bounds the step from above, so this is a least number.
    const double c0 = setup.model.equationOfState().c0, h = scene.hOverSpacing * scene.spacing;
    const double dt = scene.cfl * h / c0, steps = scene.endTime / dt;
    if (steps > manySteps)
        out.push_back(scene.file + ": time.end: " +
                      formatted("the run takes about %.2g steps or more (%g s over the acoustic "
                                "time step cfl h / c0 = %g x %g m / %g m/s = %.3g s), beyond %g",
                                steps, scene.endTime, scene.cfl, h, c0, dt, manySteps) +
                      ": raise particles.spacing, lower the sound speed (or physics.max_speed, "
                      "the wall and emitter speeds it follows), or shorten time.end");
    return out;
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

}  // namespace num::app
