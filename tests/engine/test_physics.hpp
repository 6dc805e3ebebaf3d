// Small pairwise terms for the engine tests: a momentum-conserving pressure-like force and a
// random particle set to run it on.
#pragma once

#include <random>
#include <utility>
#include <vector>

#include "numerics.hpp"

namespace enginetest {

using namespace num::sph;

/// a_i += -sum_j m_j (p_i / rho_i^2 + p_j / rho_j^2) grad_i W_ij (Monaghan 1992, eq. 3.3 form):
/// antisymmetric in (i, j), so sum_i m_i a_i = 0.
template <int Dim>
class PairForce : public DerivativeTemplate<PairForce<Dim>, Dim> {
  public:
    explicit PairForce(const RunSettings&) {}
    void create(Accumulated<Dim>& r) override {
        r.template insert<Vector<Dim>>(QuantityId::POSITION, OrderEnum::SECOND);
    }
    void initialize(const Storage<Dim>& s, Accumulated<Dim>& r) override {
        m_ = s.template getValue<Float>(QuantityId::MASS);
        rho_ = s.template getValue<Float>(QuantityId::DENSITY);
        p_ = s.template getValue<Float>(QuantityId::PRESSURE);
        a_ = r.template getValue<Vector<Dim>>(QuantityId::POSITION);
    }
    template <bool Symmetric>
    void eval(Size i, Size j, const Vector<Dim>& grad) {
        const Float f = p_[i] / (rho_[i] * rho_[i]) + p_[j] / (rho_[j] * rho_[j]);
        a_[i] -= grad * (m_[j] * f);
        if constexpr (Symmetric) a_[j] += grad * (m_[i] * f);
    }

  private:
    ArrayView<const Float> m_, rho_, p_;
    ArrayView<Vector<Dim>> a_;
};

/// The term that requires PairForce.
template <int Dim>
class PairForceTerm : public IEquationTerm<Dim> {
  public:
    void setDerivatives(DerivativeHolder<Dim>& d, const RunSettings& s) override {
        d.template require<PairForce<Dim>>(s);
    }
    void initialize(IScheduler&, Storage<Dim>&, Float) override {}
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}
    void create(Storage<Dim>&, IMaterial&) const override {}
};

/// n particles at random in the unit box with random masses, densities, pressures, energies
/// and velocities.
template <int Dim>
Storage<Dim> randomParticles(Size n, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<Vector<Dim>> x(n), v(n);
    std::vector<Float> m(n), rho(n), p(n), u(n);
    for (Size i = 0; i < n; ++i) {
        for (int k = 0; k < Dim; ++k) x[i][k] = unit(rng), v[i][k] = unit(rng) - 0.5;
        m[i] = 0.5 + unit(rng);
        rho[i] = 0.8 + 0.4 * unit(rng);
        p[i] = unit(rng);
        u[i] = unit(rng);
    }
    Storage<Dim> s;
    s.template insert<Vector<Dim>>(QuantityId::POSITION, OrderEnum::SECOND, x);
    for (Size i = 0; i < n; ++i) s.template getDt<Vector<Dim>>(QuantityId::POSITION)[i] = v[i];
    s.template insert<Float>(QuantityId::MASS, OrderEnum::ZERO, m);
    s.template insert<Float>(QuantityId::DENSITY, OrderEnum::ZERO, rho);
    s.template insert<Float>(QuantityId::PRESSURE, OrderEnum::ZERO, p);
    s.template insert<Float>(QuantityId::ENERGY, OrderEnum::FIRST, u);
    return s;
}

/// (density, pressure) of each particle, for terms that set them.
template <int Dim>
std::vector<std::pair<Float, Float>> densityAndPressure(const Storage<Dim>& s) {
    const auto rho = s.template getValue<Float>(QuantityId::DENSITY);
    const auto p = s.template getValue<Float>(QuantityId::PRESSURE);
    std::vector<std::pair<Float, Float>> out;
    for (Size i = 0; i < s.size(); ++i) out.emplace_back(rho[i], p[i]);
    return out;
}

}  // namespace enginetest
