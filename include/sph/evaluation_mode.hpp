// How the pair loop runs (RunSettings "evaluation", a scene's particles.evaluation): one table.
#pragma once

#include <array>
#include <string>

#include "sph/choice_table.hpp"

namespace num::sph {

enum class Evaluation { ASYMMETRIC, SYMMETRIC };

inline constexpr std::array evaluationTable{
    Choice<Evaluation>{"asymmetric", Evaluation::ASYMMETRIC,
                       "each particle gathers over all its neighbours"},
    Choice<Evaluation>{"symmetric", Evaluation::SYMMETRIC,
                       "each pair once, both particles written (momentum conserved to round-off)"},
};

inline Evaluation evaluationFromName(const std::string& name) {
    return evaluationTable[chooseIndex(evaluationTable, "evaluation", name)].value;
}

}  // namespace num::sph
