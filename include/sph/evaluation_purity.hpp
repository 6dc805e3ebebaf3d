// The check that an evaluation has no side effects on the state (sph/solver.hpp): the evolved
// state, i.e. the values of every quantity of order FIRST or SECOND and the velocities of those
// of order SECOND (never the rates an evaluation fills), is kept when the evaluation starts
// (after Solver::constrain) and compared bit for bit after every term's initialize and finalize
// and every pair loop. Debug builds (no NDEBUG) check every evaluation; Solver::
// evaluateCheckingPurity checks in any build.
//
// One exemption: a term may write what it declares it prepares (TermAccess::prepares) at
// boundary particles (KIND not fluid). The wall condition writes their density in each
// evaluation (Adami et al. 2012, eq. 28): there the density is derived from the wall pressure,
// not evolved (their rates are held at zero, boundary/boundary_hold.hpp).
#pragma once

#include <algorithm>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "sph/storage.hpp"

namespace num::sph {

/// An evaluation changed the evolved state: the message names the quantity, the particle and
/// the hook that changed it.
struct ImpureEvaluation : std::logic_error {
    using std::logic_error::logic_error;
};

/// The evolved state of a storage, kept to check that an evaluation leaves it as it was.
template <int Dim>
class EvaluationPurity {
  public:
    /// Keeps the evolved state of s.
    explicit EvaluationPurity(const Storage<Dim>& s) { keep(s); }

    /// Keeps the evolved state of s as it is now (after a halo exchange, which brings the
    /// owners' values: their evaluations are checked where they run).
    void keep(const Storage<Dim>& s) {
        kept_.clear();
        forEachEvolvedLevel(
            s, [&](QuantityId id, int level, const char* data, std::size_t bytes, std::size_t n) {
                kept_.push_back({id, level, bytes, std::vector<char>(data, data + bytes * n)});
            });
    }

    /// Throws ImpureEvaluation when the evolved state of s is not the kept one, naming `who`
    /// (e.g. "the term X (initialize)"). At boundary particles, the quantities in `prepared`
    /// may change: their new values are kept.
    void verify(const Storage<Dim>& s, const std::string& who,
                std::span<const QuantityId> prepared = {}) {
        const int* kind =
            s.has(QuantityId::KIND) ? s.template getValue<int>(QuantityId::KIND).data() : nullptr;
        std::size_t found = 0;
        forEachEvolvedLevel(
            s, [&](QuantityId id, int level, const char* data, std::size_t bytes, std::size_t n) {
                Level& kept = keptLevel(id, level, who);
                ++found;
                if (kept.data.size() != bytes * n)
                    throw ImpureEvaluation(who +
                                           " changed the number of particles during an "
                                           "evaluation: add or remove particles between steps");
                if (std::memcmp(kept.data.data(), data, kept.data.size()) == 0) return;
                const bool mayChange =
                    std::find(prepared.begin(), prepared.end(), id) != prepared.end();
                for (std::size_t i = 0; i < n; ++i) {
                    char* before = kept.data.data() + i * bytes;
                    if (std::memcmp(before, data + i * bytes, bytes) == 0) continue;
                    if (!(mayChange && kind && !isFluid(kind[i]))) throw changed(who, id, level, i);
                    std::memcpy(before, data + i * bytes, bytes);
                }
            });
        if (found != kept_.size())
            throw ImpureEvaluation(who + " removed an evolved quantity during an evaluation");
    }

  private:
    struct Level {
        QuantityId id;
        int level;  ///< 0: the values; 1: the velocities of a quantity of order SECOND
        std::size_t bytes;
        std::vector<char> data;
    };

    /// Calls f(id, level, data, bytes per particle, particles) for every evolved level of s.
    template <class F>
    static void forEachEvolvedLevel(const Storage<Dim>& s, F&& f) {
        s.forEach([&](QuantityId id, const Quantity<Dim>& q) {
            if (q.order() == OrderEnum::ZERO) return;
            q.visit([&](const auto& b) {
                using T = typename std::decay_t<decltype(b.value)>::value_type;
                for (int level = 0; level < int(q.order()); ++level) {
                    const auto& values = b.level(level);
                    f(id, level, reinterpret_cast<const char*>(values.data()), sizeof(T),
                      values.size());
                }
            });
        });
    }

    Level& keptLevel(QuantityId id, int level, const std::string& who) {
        for (Level& l : kept_)
            if (l.id == id && l.level == level) return l;
        throw ImpureEvaluation(who + " added an evolved quantity (" + describe(id, level) +
                               ") during an evaluation: create it in create()");
    }

    static std::string describe(QuantityId id, int level) {
        return std::string(level == 0 ? "the values" : "the velocities") + " of quantity " +
               std::to_string(int(id));
    }

    static ImpureEvaluation changed(const std::string& who, QuantityId id, int level,
                                    std::size_t particle) {
        return ImpureEvaluation(
            who + " changed " + describe(id, level) + " (particle " + std::to_string(particle) +
            ") during an evaluation, which must leave the evolved state as it found it: change "
            "the state in postStep (once per step) or constrain (before every evaluation)");
    }

    std::vector<Level> kept_;
};

}  // namespace num::sph
