// The integrators a run may choose (a scene's time.integrator): one line each. A new integrator
// is its header in sph/integrators/ (a class template over Dim implementing ITimeStepping),
// included here, and its line in integratorTable; the scene reader, its error text and
// makeIntegrator take it from there.
#pragma once

#include <memory>
#include <string>
#include <tuple>

#include "sph/choice_table.hpp"
#include "sph/integrators/explicit_euler.hpp"
#include "sph/integrators/leapfrog_kdk.hpp"
#include "sph/integrators/predictor_corrector.hpp"

namespace num::sph {

/// An integrator of the table: its name, a line of help and its class template over Dim.
template <template <int> class Integrator>
struct IntegratorChoice {
    std::string_view name, help;
    template <int Dim>
    using type = Integrator<Dim>;
};

inline constexpr std::tuple integratorTable{
    IntegratorChoice<LeapfrogKDK>{"leapfrog", "kick-drift-kick: second order, symplectic"},
    IntegratorChoice<PredictorCorrector>{"predictor_corrector", "predictor-corrector"},
    IntegratorChoice<ExplicitEuler>{"euler", "explicit Euler: first order"},
};

/// The integrator of the table called `name`; a SettingsError listing the names if none is.
template <int Dim>
std::unique_ptr<ITimeStepping<Dim>> makeIntegrator(const std::string& name) {
    const std::size_t index = chooseIndex(integratorTable, "integrator", name);
    return withChoice(integratorTable, index,
                      [](auto entry) -> std::unique_ptr<ITimeStepping<Dim>> {
                          return std::make_unique<typename decltype(entry)::template type<Dim>>();
                      });
}

}  // namespace num::sph
