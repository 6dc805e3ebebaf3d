// The passes of an evaluation, worked out from what each term declares it reads and writes
// (TermAccess). Each pass runs the initialize of its terms, one pair loop over the derivatives
// they required, then their finalize; within a pass, terms keep the order they were added in.
// A term goes to the earliest pass in which what it reads is ready:
//   - a quantity that a term added before it prepares (in initialize) is ready in that term's
//     pass (a term added after it that prepares the quantity corrects it later: the reader sees
//     the value as the terms before it left it);
//   - a quantity that any term produces (by its pair sums or its finalize) is ready from the
//     pass after that term's.
// So a term that needs another's pair sums runs one pass later, whatever the order of adding.
// Terms that declare nothing run in the first pass. Terms placed LAST run in the last pass, so
// their finalize sees every other term's rates (the fluid model's boundary hold zeroes what
// wall particles received); EVERY is for terms that only arrange derivatives (FuseDerivatives).
#pragma once

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "sph/types.hpp"

namespace num::sph {

/// Which pass a term joins, beyond what its reads ask for.
enum class PassPlacement {
    EARLIEST,  ///< the earliest pass in which what it reads is ready
    LAST,      ///< the last pass: its finalize follows every other term's rates
    EVERY,     ///< setDerivatives in every pass (after the pass's terms), other hooks in the first
};

/// A quantity that another term prepares in each evaluation (not part of the state), with the
/// name of that term for the message when it is missing.
struct PreparedInput {
    QuantityId id;
    std::string preparedBy;
};

/// What a term reads and writes, so that the solver can place it (IEquationTerm::access).
/// Name stored quantities (values). Rates (dt, d2t) need no declaration: terms add to them in
/// any order. A term that deliberately reads a value of the previous evaluation (the fluid
/// model's free-surface flags) does not list it.
struct TermAccess {
    /// Read by the term's initialize or by the pair sums of its derivatives.
    std::vector<QuantityId> reads = {};
    /// Read like `reads`, but prepared in each evaluation by another term (PreparedInput::
    /// preparedBy), which must be added before this one: without it the terms are refused.
    std::vector<PreparedInput> needs = {};
    /// Set by its initialize: ready for the terms added after it, in the same pass.
    std::vector<QuantityId> prepares = {};
    /// Set by its pair sums or its finalize: ready from the next pass on.
    std::vector<QuantityId> produces = {};
    PassPlacement placement = PassPlacement::EARLIEST;
};

/// The passes of an evaluation: indices of the terms in the order they were added.
struct EvaluationSchedule {
    struct Pass {
        std::vector<std::size_t> terms;        ///< initialize and finalize, in this order
        std::vector<std::size_t> derivatives;  ///< whose setDerivatives builds the pair loop
    };
    std::vector<Pass> passes;

    /// One line per pass with its terms: "pass 1: A, B".
    std::string describe(const std::vector<std::string>& names) const {
        std::string text;
        for (std::size_t p = 0; p < passes.size(); ++p) {
            text += "pass " + std::to_string(p + 1) + ":";
            for (std::size_t k = 0; k < passes[p].terms.size(); ++k)
                text += (k ? ", " : " ") + names[passes[p].terms[k]];
            text += "\n";
        }
        return text;
    }
};

namespace detail {
inline bool listsAny(const std::vector<QuantityId>& ids, const std::vector<QuantityId>& wanted) {
    for (QuantityId q : wanted)
        if (std::find(ids.begin(), ids.end(), q) != ids.end()) return true;
    return false;
}

[[noreturn]] inline void failSchedule(const std::string& what) {
    throw std::logic_error(what + ": check what their access() declares");
}

inline bool placedEarliest(const TermAccess& access) {
    return access.placement == PassPlacement::EARLIEST;
}

/// What a term needs is read like the rest, once a term added before it prepares it.
inline void addPreparedReads(std::vector<TermAccess>& access,
                             const std::vector<std::string>& names) {
    for (std::size_t b = 0; b < access.size(); ++b)
        for (const PreparedInput& input : access[b].needs) {
            bool prepared = false;
            for (std::size_t a = 0; a < b; ++a)
                prepared |= listsAny(access[a].prepares, {input.id});
            if (!prepared)
                throw std::logic_error("the term " + names[b] + " reads quantity " +
                                       std::to_string(int(input.id)) + ", which " +
                                       input.preparedBy + " prepares in each evaluation: add " +
                                       input.preparedBy + " before it");
            access[b].reads.push_back(input.id);
        }
}

/// Refuses a term that reads what a term placed in the last pass or in every pass writes.
inline void checkLatePlacedReads(const std::vector<TermAccess>& access,
                                 const std::vector<std::string>& names) {
    const std::size_t n = access.size();
    for (std::size_t b = 0; b < n; ++b)
        for (std::size_t a = 0; a < n; ++a)
            if (a != b && !placedEarliest(access[a]) &&
                (listsAny(access[a].produces, access[b].reads) ||
                 (a < b && listsAny(access[a].prepares, access[b].reads))))
                failSchedule("the term " + names[b] + " reads what " + names[a] +
                             " writes, which is placed in the last pass or in every pass");
}

/// The least pass of each term placed earliest that satisfies its reads: a longest path, found
/// by relaxing. After n + 1 rounds with changes, a chain of production has closed on itself.
inline std::vector<std::size_t> leastPasses(const std::vector<TermAccess>& access,
                                            const std::vector<std::string>& names) {
    const std::size_t n = access.size();
    std::vector<std::size_t> pass(n, 0);
    for (std::size_t round = 0;; ++round) {
        bool changed = false;
        for (std::size_t b = 0; b < n; ++b)
            for (std::size_t a = 0; a < n; ++a) {
                if (a == b || !placedEarliest(access[a]) || !placedEarliest(access[b])) continue;
                std::size_t least = 0;
                if (listsAny(access[a].produces, access[b].reads)) least = pass[a] + 1;
                if (a < b && listsAny(access[a].prepares, access[b].reads))
                    least = std::max(least, pass[a]);
                if (least > pass[b]) pass[b] = least, changed = true;
            }
        if (!changed) return pass;
        if (round > n) {
            std::string cycle;
            for (std::size_t t = 0; t < n; ++t)
                if (pass[t] > n) cycle += (cycle.empty() ? "" : ", ") + names[t];
            failSchedule("the terms " + cycle +
                         " read what each other produce, so none can run first");
        }
    }
}

/// The passes: each term in its least pass, a term placed last in the last, one placed in every
/// pass in each (its derivatives too; the others' derivatives in their own pass).
inline EvaluationSchedule assemblePasses(const std::vector<TermAccess>& access,
                                         std::vector<std::size_t> pass) {
    const std::size_t n = access.size();
    std::size_t last = 0;
    for (std::size_t t = 0; t < n; ++t)
        if (placedEarliest(access[t])) last = std::max(last, pass[t]);
    EvaluationSchedule schedule;
    schedule.passes.resize(last + 1);
    for (std::size_t t = 0; t < n; ++t) {
        if (access[t].placement == PassPlacement::LAST) pass[t] = last;
        schedule.passes[pass[t]].terms.push_back(t);
        if (access[t].placement != PassPlacement::EVERY)
            schedule.passes[pass[t]].derivatives.push_back(t);
    }
    for (auto& p : schedule.passes)
        for (std::size_t t = 0; t < n; ++t)
            if (access[t].placement == PassPlacement::EVERY) p.derivatives.push_back(t);
    return schedule;
}
}  // namespace detail

/// The schedule of terms with the given accesses (in the order the terms were added); names
/// are for messages. Throws std::logic_error when no order of passes satisfies the declarations.
inline EvaluationSchedule scheduleEvaluation(std::vector<TermAccess> access,
                                             const std::vector<std::string>& names) {
    detail::addPreparedReads(access, names);
    detail::checkLatePlacedReads(access, names);
    return detail::assemblePasses(access, detail::leastPasses(access, names));
}

}  // namespace num::sph
