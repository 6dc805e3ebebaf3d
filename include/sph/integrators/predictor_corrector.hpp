// A predictor-corrector integrator.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "sph/integrator.hpp"

namespace num::sph {

/// Predictor-corrector: predict with the derivatives at t, evaluate, correct with the change
/// of the highest derivative (v += dt/2 da, x += dt^2/6 da; first order q += dt/2 dq).
template <int Dim>
class PredictorCorrector final : public ITimeStepping<Dim> {
  public:
    void step(Solver<Dim>& solver, Storage<Dim>& s, Float t, Float dt) override {
        saved_.clear();
        detail::forEachEvolved(s, [&](auto& b, OrderEnum o) {
            saved_.emplace_back(o == OrderEnum::SECOND ? b.d2t : b.dt);
            for (std::size_t i = 0; i < b.value.size(); ++i) {
                if (o == OrderEnum::SECOND) {
                    b.value[i] += b.dt[i] * dt + b.d2t[i] * (0.5 * dt * dt);
                    b.dt[i] += b.d2t[i] * dt;
                } else {
                    b.value[i] += b.dt[i] * dt;
                }
            }
        });
        solver.evaluate(s, t + dt);
        std::size_t k = 0;
        detail::forEachEvolved(s, [&](auto& b, OrderEnum o) {
            const auto& top = o == OrderEnum::SECOND ? b.d2t : b.dt;
            const auto& old = std::get<std::decay_t<decltype(top)>>(saved_[k++]);
            for (std::size_t i = 0; i < top.size(); ++i) {
                const auto change = top[i] - old[i];
                if (o == OrderEnum::SECOND) {
                    b.dt[i] += change * (0.5 * dt);
                    b.value[i] += change * (dt * dt / 6.0);
                } else {
                    b.value[i] += change * (0.5 * dt);
                }
            }
        });
    }
    std::string name() const override { return "predictor_corrector"; }

  private:
    std::vector<std::variant<std::vector<Float>, std::vector<Vector<Dim>>>> saved_;
};

}  // namespace num::sph
