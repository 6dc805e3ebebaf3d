// The equations of state a scene may choose (physics.eos): one table.
#pragma once

#include <array>
#include <string>

#include "sph/choice_table.hpp"
#include "sph/defaults.hpp"
#include "sph/formulas/equation_of_state.hpp"

namespace num::sph {

inline constexpr std::array eosTable{
    Choice<EosType>{"tait", EosType::TAIT, "p = B ((rho / rho0)^gamma - 1), B = rho0 c0^2 / gamma"},
    Choice<EosType>{"linear", EosType::LINEAR, "p = c0^2 (rho - rho0)"},
};

/// The default equation of state (defaults::eos), checked against the table when compiled.
inline constexpr EosType defaultEos = eosTable[*choiceIndex(eosTable, defaults::eos)].value;

inline EosType eosFromName(const std::string& name) {
    return eosTable[chooseIndex(eosTable, "equation of state", name)].value;
}

}  // namespace num::sph
