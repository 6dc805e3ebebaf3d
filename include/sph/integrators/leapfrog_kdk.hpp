// Kick-drift-kick leapfrog, the default integrator.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "sph/formulas/leapfrog.hpp"
#include "sph/integrator.hpp"

namespace num::sph {

/// Kick-drift-kick leapfrog (velocity Verlet) for second-order quantities: symplectic and
/// second order (Hairer, Lubich & Wanner 2003, sec. I.1.4):
///     v += dt/2 a_n;  x += dt v;  evaluate;  v += dt/2 a_{n+1}.
/// First-order quantities (density, energy...) are advanced with Heun's rule, also second
/// order: predicted q* = q_n + dt dq_n at evaluation, then q_{n+1} = q_n + dt/2 (dq_n + dq*).
template <int Dim>
class LeapfrogKDK final : public ITimeStepping<Dim> {
  public:
    void step(Solver<Dim>& solver, Storage<Dim>& s, Float t, Float dt) override {
        const Float half = 0.5 * dt;
        IScheduler& sch = solver.scheduler();
        const Size grain = 8192;
        std::size_t k = 0;
        detail::forEachEvolved(s, [&](auto& b, OrderEnum o) {
            const Size n = Size(b.value.size());
            if (o == OrderEnum::SECOND) {
                sch.parallelFor(n, grain, [&](Size i0, Size i1) {
                    for (Size i = i0; i < i1; ++i)
                        formulas::kickDrift(b.value[i], b.dt[i], b.d2t[i], half, dt);
                });
            } else {
                using V = std::decay_t<decltype(b.dt)>;
                if (k == saved_.size()) saved_.emplace_back(V{});
                if (!std::holds_alternative<V>(saved_[k])) saved_[k] = V{};
                V& old = std::get<V>(saved_[k++]);
                old.resize(n);
                sch.parallelFor(n, grain, [&](Size i0, Size i1) {
                    for (Size i = i0; i < i1; ++i)
                        formulas::heunPredict(b.value[i], old[i], b.dt[i], dt);
                });
            }
        });
        solver.evaluate(s, t + dt);
        k = 0;
        detail::forEachEvolved(s, [&](auto& b, OrderEnum o) {
            const Size n = Size(b.value.size());
            if (o == OrderEnum::SECOND) {
                sch.parallelFor(n, grain, [&](Size i0, Size i1) {
                    for (Size i = i0; i < i1; ++i) formulas::kick(b.dt[i], b.d2t[i], half);
                });
            } else {
                const auto& old = std::get<std::decay_t<decltype(b.dt)>>(saved_[k++]);
                sch.parallelFor(n, grain, [&](Size i0, Size i1) {
                    for (Size i = i0; i < i1; ++i)
                        formulas::heunCorrect(b.value[i], b.dt[i], old[i], half);
                });
            }
        });
    }
    std::string name() const override { return "leapfrog"; }

  private:
    std::vector<std::variant<std::vector<Float>, std::vector<Vector<Dim>>>> saved_;
};

}  // namespace num::sph
