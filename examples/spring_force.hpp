// The seed's harmonic spring force, written as user code against the public headers only:
// every particle is pulled to the origin, dv/dt += -k/m r (a harmonic oscillator of angular
// frequency sqrt(k/m)). It needs no pairwise sum, so it works in finalize() alone.
#pragma once

#include <cmath>
#include <stdexcept>

#include "numerics.hpp"

namespace examples {

using num::sph::Float;
using num::sph::Size;

template <int Dim>
class SpringForce : public num::sph::IEquationTerm<Dim> {
  public:
    using Vector = num::sph::Vector<Dim>;

    /// `springConstant` k [N/m]; `stepsPerRadian` sets the time-step limit dt <= sqrt(m/k) / it.
    explicit SpringForce(Float springConstant, Float stepsPerRadian = 20)
        : k_(springConstant), stepsPerRadian_(stepsPerRadian) {}

    void setDerivatives(num::sph::DerivativeHolder<Dim>&, const num::sph::RunSettings&) override {
        // No pairwise sum is needed.
    }

    void initialize(num::sph::IScheduler&, num::sph::Storage<Dim>&, Float) override {
        // Nothing to prepare before the pair loop.
    }

    void finalize(num::sph::IScheduler& scheduler, num::sph::Storage<Dim>& storage,
                  Float) override {
        using num::sph::QuantityId;
        const auto r = storage.template getValue<Vector>(QuantityId::POSITION);
        const auto dv = storage.template getD2t<Vector>(QuantityId::POSITION);
        const auto m = storage.template getValue<Float>(QuantityId::MASS);
        // Add (never assign): other terms write the same acceleration.
        scheduler.parallelFor(storage.size(), 4096, [&](Size begin, Size end) {
            for (Size i = begin; i < end; ++i) dv[i] += r[i] * (-k_ / m[i]);
        });
    }

    void create(num::sph::Storage<Dim>& storage, num::sph::IMaterial&) const override {
        // Positions (second order) are created by the solver; the force needs the masses.
        if (!storage.has(num::sph::QuantityId::MASS))
            throw std::invalid_argument("SpringForce needs particle masses (QuantityId::MASS)");
    }

    void limitTimeStep(const num::sph::Storage<Dim>& storage, const num::sph::RunSettings&,
                       num::sph::TimeStepLimits& limits) const override {
        // The oscillation period is 2 pi sqrt(m/k): resolve each radian with a few steps.
        for (Float m : storage.template getValue<Float>(num::sph::QuantityId::MASS))
            limits.offer("spring", std::sqrt(m / k_) / stepsPerRadian_);
    }

  private:
    Float k_;
    Float stepsPerRadian_;
};

}  // namespace examples
