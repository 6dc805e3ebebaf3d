// The seed's heat diffusion example, written as user code against the public headers only:
//     du/dt = +alpha * Laplacian(u)
// (the seed's minus sign would make heat flow from cold to hot). The Laplacian is a pairwise
// sum, an IDerivative, in the second-derivative form of Brookshaw (1985) as written by Price
// (2012, J. Comput. Phys. 231, 759, "second derivatives"):
//     Laplacian(u)_i = sum_j (m_j / rho_j) (u_j - u_i) * (-2 x_ij . grad_i W_ij) / (r_ij^2 + eta^2)
// with x_ij = x_i - x_j, eta^2 = 0.01 h^2 against r -> 0 (Monaghan 1992). With equal m/rho the
// pair terms are antisymmetric, so the total energy sum_i m_i u_i is conserved.
#pragma once

#include <stdexcept>
#include <tuple>

#include "numerics.hpp"

namespace examples {

using num::sph::Float;
using num::sph::Size;

/// Quantities of this example that the engine does not know: negative ids are free for users.
enum class AdditionalId : int { ENERGY_LAPLACIAN = -1 };

/// The Laplacian of the specific energy. Written once as eval<Symmetric>; DerivativeTemplate
/// provides evalSymmetric (each pair once, both particles written) and evalAsymmetric.
template <int Dim>
class EnergyLaplacian : public num::sph::DerivativeTemplate<EnergyLaplacian<Dim>, Dim> {
  public:
    using Vector = num::sph::Vector<Dim>;
    static constexpr auto LAPLACIAN = num::sph::QuantityId(AdditionalId::ENERGY_LAPLACIAN);

    explicit EnergyLaplacian(const num::sph::RunSettings& settings) {
        const Float h = settings.get<double>("smoothing_length");
        eta2_ = 0.01 * h * h;
    }

    void create(num::sph::Accumulated<Dim>& results) override {
        // One buffer per block of particles; the solver sums them into the storage value.
        results.template insert<Float>(LAPLACIAN, num::sph::OrderEnum::ZERO);
    }

    void initialize(const num::sph::Storage<Dim>& input,
                    num::sph::Accumulated<Dim>& results) override {
        using num::sph::QuantityId;
        std::tie(u_, m_, rho_) = input.template getValues<Float>(
            QuantityId::ENERGY, QuantityId::MASS, QuantityId::DENSITY);
        laplacian_ = results.template getValue<Float>(LAPLACIAN);
    }

    template <bool Symmetric>
    void eval(Size i, Size j, const Vector& grad, const num::sph::PairGeometry<Dim>& pair) {
        // pair.dx is x_i - x_j for the nearest periodic image; x_ij . grad_i W_ij <= 0.
        const Float f = (u_[j] - u_[i]) * (-2 * dot(pair.dx, grad) / (pair.r * pair.r + eta2_));
        laplacian_[i] += m_[j] / rho_[j] * f;
        if constexpr (Symmetric) laplacian_[j] -= m_[i] / rho_[i] * f;
    }

  private:
    Float eta2_;
    num::sph::ArrayView<const Float> u_, m_, rho_;
    num::sph::ArrayView<Float> laplacian_;
};

/// The right-hand side du/dt += alpha * Laplacian(u), alpha the diffusivity [m^2/s].
template <int Dim>
class HeatDiffusion : public num::sph::IEquationTerm<Dim> {
  public:
    static constexpr auto LAPLACIAN = EnergyLaplacian<Dim>::LAPLACIAN;

    explicit HeatDiffusion(Float alpha) : alpha_(alpha) {}

    void setDerivatives(num::sph::DerivativeHolder<Dim>& derivatives,
                        const num::sph::RunSettings& settings) override {
        // require() keeps one EnergyLaplacian however many terms ask for it.
        derivatives.template require<EnergyLaplacian<Dim>>(settings);
    }

    void initialize(num::sph::IScheduler&, num::sph::Storage<Dim>&, Float) override {}

    void finalize(num::sph::IScheduler& scheduler, num::sph::Storage<Dim>& storage,
                  Float) override {
        // The pair loop is done: the Laplacian is in the storage. Add, never assign.
        const auto du = storage.template getDt<Float>(num::sph::QuantityId::ENERGY);
        const auto laplacian = storage.template getValue<Float>(LAPLACIAN);
        scheduler.parallelFor(storage.size(), 4096, [&](Size begin, Size end) {
            for (Size i = begin; i < end; ++i) du[i] += alpha_ * laplacian[i];
        });
    }

    void create(num::sph::Storage<Dim>& storage, num::sph::IMaterial&) const override {
        using num::sph::OrderEnum;
        using num::sph::QuantityId;
        if (!storage.has(QuantityId::MASS) || !storage.has(QuantityId::DENSITY))
            throw std::invalid_argument("HeatDiffusion needs QuantityId::MASS and DENSITY");
        // Energy evolves (first order); existing values are kept.
        storage.template insert<Float>(QuantityId::ENERGY, OrderEnum::FIRST, 0.0);
        // Where the solver puts the Laplacian; it can be written out for inspection.
        storage.template insert<Float>(LAPLACIAN, OrderEnum::ZERO, 0.0);
    }

    void limitTimeStep(const num::sph::Storage<Dim>&, const num::sph::RunSettings& settings,
                       num::sph::TimeStepLimits& limits) const override {
        // Explicit diffusion is stable for dt <= f h^2 / alpha.
        limits.offer("diffusion",
                     num::sph::diffusionTimeStep(settings.get<double>("diffusion_factor"),
                                                 settings.get<double>("smoothing_length"), alpha_));
    }

  private:
    Float alpha_;
};

}  // namespace examples
