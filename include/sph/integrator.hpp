// The integrator's interface: it advances every quantity by its order. Quantities of order
// SECOND (positions) are kicked and drifted; quantities of order FIRST (density,
// temperature...) are advanced with their dt. The integrators a run may choose: the table in
// sph/integrator_choice.hpp.
#pragma once

#include <string>
#include <type_traits>

#include "sph/solver.hpp"

namespace num::sph {

namespace detail {
/// Calls f(buffers, order) for every quantity of order FIRST or SECOND.
template <int Dim, class F>
void forEachEvolved(Storage<Dim>& s, F&& f) {
    s.forEach([&](QuantityId, Quantity<Dim>& q) {
        if (q.order() == OrderEnum::ZERO) return;
        q.visit([&](auto& b) {
            using T = typename std::decay_t<decltype(b.value)>::value_type;
            if constexpr (!std::is_same_v<T, int>) f(b, q.order());
        });
    });
}
}  // namespace detail

template <int Dim>
class ITimeStepping {
  public:
    virtual ~ITimeStepping() = default;
    /// Advances the storage from t to t + dt. Derivatives at t must be current (see prime()).
    /// The post-step phase is not part of it: Run::step calls Solver::postStep afterwards.
    virtual void step(Solver<Dim>& solver, Storage<Dim>& storage, Float t, Float dt) = 0;
    virtual std::string name() const = 0;
};

}  // namespace num::sph
