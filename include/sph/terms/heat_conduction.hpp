// Heat conduction between particles, also across materials (conjugate heat transfer).
//
// Brookshaw (1985) Laplacian with the conductivity of a pair as the harmonic mean
// (Cleary & Monaghan 1999, J. Comput. Phys. 148, eq. 10; Cleary 1998):
//
//   c_a dT_a/dt = sum_b  4 m_b k_a k_b / (rho_a rho_b (k_a + k_b))
//                        (T_a - T_b) (r_ab . grad_a W_ab) / (r_ab^2 + eta^2),   eta^2 = 0.001 h^2
//                        (defaults.hpp; the last factor is PairGeometry::laplacian)
//
// r_ab . grad_a W_ab <= 0, so a particle hotter than its neighbours cools: heat flows from hot
// to cold (the seed's "du += -alpha * delta" has the opposite sign and is anti-diffusion).
// The pair term is antisymmetric: what a gains, m_a c_a dT_a, b loses, so the total heat
// sum m c T is conserved to round-off when no boundary adds or removes heat. The harmonic
// mean gives the flux through an interface between two materials its correct value
// (continuous temperature and flux), so two materials in contact exchange heat correctly.
//
// Temperature is QuantityId::TEMPERATURE (first order). Pairs with an ADIABATIC particle
// exchange nothing (boundary/thermal_condition.hpp). A FIXED_TEMPERATURE particle shows
// heat_ids::BOUNDARY_TEMPERATURE where the wall condition provides it (the mirrored
// temperature that puts the prescribed one on the wall surface), else its own temperature.
// Time-step limit (explicit diffusion): dt <= diffusion_factor h^2 / alpha_max with alpha = k /
// (rho c).
// The pair formula: sph/formulas/heat_pairs.hpp (host and device).
#pragma once

#include <algorithm>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>

#include "sph/boundary/thermal_condition.hpp"
#include "sph/equation_term.hpp"
#include "sph/formulas/heat_pairs.hpp"
#include "sph/formulas/time_step.hpp"

namespace num::sph {

/// Every particle's material index and thermal condition. A storage without the quantity reads
/// as zeros (the first material; CONDUCTING), kept in `zeros`, which stays empty otherwise.
template <int Dim>
std::pair<ArrayView<const int>, ArrayView<const int>> materialAndCondition(
    const Storage<Dim>& s, std::vector<int>& zeros) {
    const bool hasMaterial = s.has(QuantityId::MATERIAL);
    const bool hasCondition = s.has(heat_ids::THERMAL_CONDITION);
    zeros.assign(hasMaterial && hasCondition ? 0 : s.size(), 0);
    return {
        hasMaterial ? s.template getValue<int>(QuantityId::MATERIAL) : ArrayView<const int>(zeros),
        hasCondition ? s.template getValue<int>(heat_ids::THERMAL_CONDITION)
                     : ArrayView<const int>(zeros)};
}

/// The pair sum of the conduction operator, accumulated directly into dT/dt.
template <int Dim>
class HeatConductionDerivative : public DerivativeTemplate<HeatConductionDerivative<Dim>, Dim> {
  public:
    /// A boundary particle's conduction sum is needed unless it is adiabatic (a fixed
    /// temperature's for the books of thermal_walls.hpp, a conducting body's for its own T).
    bool gathersAtBoundary(Size i) const override {
        return cond_[i] != int(ThermalCondition::ADIABATIC);
    }
    void create(Accumulated<Dim>& results) override {
        results.template insert<Float>(QuantityId::TEMPERATURE, OrderEnum::FIRST);
    }

    void initialize(const Storage<Dim>& s, Accumulated<Dim>& results) override {
        const std::vector<ThermalMaterial> table = thermalMaterials(s);
        k_.resize(table.size());
        invC_.resize(table.size());
        for (std::size_t m = 0; m < table.size(); ++m) {
            k_[m] = table[m].conductivity;
            invC_[m] = 1.0 / table[m].heatCapacity;
        }
        std::tie(mat_, cond_) = materialAndCondition(s, zeros_);
        if (s.has(QuantityId::MATERIAL))  // stand-in zeros need no check
            for (int m : mat_)
                if (m < 0 || std::size_t(m) >= table.size())
                    throw std::out_of_range("heat conduction: material index out of the table");
        bindStates(s, results);
    }
    /// Shares block 0's material table and its checked material and condition views: the
    /// check of every particle's material runs once per evaluation, not once per block.
    void initializeLike(const IDerivative<Dim>& first, const Storage<Dim>& s,
                        Accumulated<Dim>& results) override {
        const auto& block0 = static_cast<const HeatConductionDerivative&>(first);
        k_ = block0.k_, invC_ = block0.invC_;
        mat_ = block0.mat_, cond_ = block0.cond_;
        bindStates(s, results);
    }

    template <bool Symmetric>
    void eval(Size a, Size b, const Vector<Dim>&, const PairGeometry<Dim>& pair) {
        if (!conductsHeat(cond_[a], cond_[b])) return;
        const Float ka = k_[mat_[a]], kb = k_[mat_[b]];
        if (!(ka + kb > 0)) return;
        const Float f = formulas::heatExchange(ka, kb, rho_[a], rho_[b], temperature(a),
                                               temperature(b), pair.laplacian);
        dT_[a] += formulas::heatRate(m_[b], f, invC_[mat_[a]]);
        if constexpr (Symmetric) dT_[b] -= formulas::heatRate(m_[a], f, invC_[mat_[b]]);
    }
    /// Gather (asymmetric) evaluation: particle a's own data read once and its sum kept in a
    /// register, with eval's arithmetic in eval's order, so the result is bitwise eval's.
    void gatherNeighbours(Size a, ArrayView<const Size> neighs, ArrayView<const Vector<Dim>>,
                          const NeighbourGeometry<Dim>& geometry) {
        const int condA = cond_[a];
        const Float ka = k_[mat_[a]], rhoA = rho_[a], Ta = temperature(a), invCa = invC_[mat_[a]];
        Float sum = dT_[a];
        for (std::size_t k = 0; k < neighs.size(); ++k) {
            const Size b = neighs[k];
            if (!conductsHeat(condA, cond_[b])) continue;
            const Float kb = k_[mat_[b]];
            if (!(ka + kb > 0)) continue;
            sum += formulas::heatRate(m_[b],
                                      formulas::heatExchange(ka, kb, rhoA, rho_[b], Ta,
                                                             temperature(b), geometry.laplacian[k]),
                                      invCa);
        }
        dT_[a] = sum;
    }

  private:
    /// The temperature particle a shows to conduction: a fixed-temperature particle's wall value.
    Float temperature(Size a) const {
        return formulas::conductionTemperature(cond_[a], T_[a], Tfixed_[a]);
    }
    void bindStates(const Storage<Dim>& s, Accumulated<Dim>& results) {
        T_ = s.template getValue<Float>(QuantityId::TEMPERATURE);
        Tfixed_ = s.has(heat_ids::BOUNDARY_TEMPERATURE)
                      ? s.template getValue<Float>(heat_ids::BOUNDARY_TEMPERATURE)
                      : T_;
        m_ = s.template getValue<Float>(QuantityId::MASS);
        rho_ = s.template getValue<Float>(QuantityId::DENSITY);
        dT_ = results.template getValue<Float>(QuantityId::TEMPERATURE);
    }
    std::vector<Float> k_, invC_;
    std::vector<int> zeros_;
    ArrayView<const int> mat_, cond_;
    ArrayView<const Float> T_, Tfixed_, m_, rho_;
    ArrayView<Float> dT_;
};

/// The conduction term: requires the pair sum, creates temperature, offers the diffusion limit.
template <int Dim>
class HeatConduction : public IEquationTerm<Dim> {
  public:
    void setDerivatives(DerivativeHolder<Dim>& derivatives, const RunSettings&) override {
        derivatives.template require<HeatConductionDerivative<Dim>>();
    }
    void initialize(IScheduler&, Storage<Dim>&, Float) override {}
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}

    /// Temperature (first order, starting at the material's reference temperature where it
    /// does not exist yet), density and material index.
    TermAccess access() const override {
        return {.reads = {QuantityId::TEMPERATURE, heat_ids::BOUNDARY_TEMPERATURE,
                          QuantityId::DENSITY}};
    }
    void create(Storage<Dim>& storage, IMaterial& material) const override {
        const ParameterSet& p = material.params();
        storage.template insert<Float>(QuantityId::TEMPERATURE, OrderEnum::FIRST,
                                       p.get<double>("reference_temperature"));
        storage.template insert<Float>(QuantityId::DENSITY, OrderEnum::ZERO,
                                       p.get<double>("density"));
        storage.template insert<int>(QuantityId::MATERIAL, OrderEnum::ZERO, 0);
    }

    /// dt <= diffusion_factor h^2 / max alpha, alpha = k / (rho c) of particles that conduct.
    void limitTimeStep(const Storage<Dim>& s, const RunSettings& settings,
                       TimeStepLimits& limits) const override {
        const std::vector<ThermalMaterial> table = thermalMaterials(s);
        const auto rho = s.template getValue<Float>(QuantityId::DENSITY);
        std::vector<int> zeros;
        // Not a structured binding: clang 14 cannot capture one in the lambda below.
        const auto materialCondition = materialAndCondition(s, zeros);
        const ArrayView<const int> mat = materialCondition.first, cond = materialCondition.second;
        // alpha = k / (rho c) is largest at a material's smallest density: one division per
        // material (rounding is monotonic, so this is bitwise the largest alpha of a particle).
        const std::vector<Float> rhoMin = reduceChunks(
            limits.scheduler(), s.size(), 8192,
            std::vector<Float>(table.size(), std::numeric_limits<Float>::infinity()),
            [&](Size b, Size e, std::vector<Float>& least) {
                for (Size i = b; i < e; ++i)
                    if (cond[i] != int(ThermalCondition::ADIABATIC))
                        least[mat[i]] = std::min(least[mat[i]], rho[i]);
            },
            [](std::vector<Float>& least, const std::vector<Float>& partial) {
                for (std::size_t m = 0; m < least.size(); ++m)
                    least[m] = std::min(least[m], partial[m]);
            });
        Float alphaMax = 0;
        for (std::size_t m = 0; m < table.size(); ++m)
            if (rhoMin[m] < std::numeric_limits<Float>::infinity())
                alphaMax =
                    std::max(alphaMax, table[m].conductivity / (rhoMin[m] * table[m].heatCapacity));
        const Float h = settings.get<double>("smoothing_length");
        if (alphaMax > 0)
            limits.offer("diffusion", formulas::diffusionStep(
                                          settings.get<double>("diffusion_factor"), h, alphaMax));
    }
};

}  // namespace num::sph
