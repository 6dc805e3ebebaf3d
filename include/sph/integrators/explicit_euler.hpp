// The explicit Euler integrator (first order; for tests and comparisons).
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "sph/integrator.hpp"

namespace num::sph {

/// Explicit Euler: x += v dt, v += a dt, q += dq dt with every derivative at t. First order;
/// for tests and comparisons.
template <int Dim>
class ExplicitEuler final : public ITimeStepping<Dim> {
  public:
    void step(Solver<Dim>& solver, Storage<Dim>& s, Float t, Float dt) override {
        detail::forEachEvolved(s, [&](auto& b, OrderEnum o) {
            for (std::size_t i = 0; i < b.value.size(); ++i) {
                b.value[i] += b.dt[i] * dt;
                if (o == OrderEnum::SECOND) b.dt[i] += b.d2t[i] * dt;
            }
        });
        solver.evaluate(s, t + dt);
    }
    std::string name() const override { return "euler"; }
};

}  // namespace num::sph
