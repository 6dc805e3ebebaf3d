// Laminar viscosity (Morris, Fox & Zhu 1997, eq. 8), with the smooth kernel's derivative:
//   dv_i/dt = sum_j m_j (mu_i + mu_j) / (rho_i rho_j) (r_ij . grad_i W_ij) / (r_ij^2 + eta^2) v_ij,
//   mu = rho nu, r_ij = x_i - x_j, v_ij = v_i - v_j, eta^2 = 0.001 h^2 (defaults.hpp),
// evaluated as (mu_i + mu_j) L_ij V_j / rho_i with V_j = m_j / rho_j (FluidId::VOLUME) and
// L_ij = r_ij . grad_i W_ij / (r_ij^2 + eta^2) (PairGeometry::laplacian).
// Since r_ij . grad_i W_ij <= 0 the term pulls v_i towards v_j; the pair terms are
// antisymmetric, so momentum is conserved. A boundary particle shows the velocity of the wall
// condition (2 v_wall - v~ for no-slip, Adami et al. 2012, eq. 23); free-slip boundary
// particles are skipped (the velocities: FluidId::PAIR_VELOCITY, terms/pair_inputs.hpp).
// Time-step limit: dt <= f h^2 / nu (Morris et al. 1997, eq. 13).
// The formula: sph/formulas/fluid_pairs.hpp.
#pragma once

#include <memory>
#include <vector>

#include "sph/formulas/fluid_pairs.hpp"
#include "sph/formulas/time_step.hpp"
#include "sph/terms/fluid_quantities.hpp"
#include "sph/terms/pair_inputs.hpp"

namespace num::sph {

template <int Dim>
struct ViscousData {
    std::vector<Float> mu;     // dynamic viscosity rho nu
    std::vector<char> active;  // 0: free-slip boundary particle
};

template <int Dim>
class LaminarViscosityPart : public DerivativeTemplate<LaminarViscosityPart<Dim>, Dim> {
  public:
    using Vec = Vector<Dim>;
    explicit LaminarViscosityPart(std::shared_ptr<const ViscousData<Dim>> data)
        : data_(std::move(data)) {}

    /// The gather writes fluid particles only.
    bool gathersAtBoundary(Size) const override { return false; }
    void create(Accumulated<Dim>& r) override {
        r.template insert<Vec>(QuantityId::POSITION, OrderEnum::SECOND);
    }
    void initialize(const Storage<Dim>& s, Accumulated<Dim>& r) override {
        volume_ = s.template getValue<Float>(FluidId::VOLUME);
        rho_ = s.template getValue<Float>(QuantityId::DENSITY);
        kind_ = s.template getValue<int>(QuantityId::KIND);
        v_ = s.template getValue<Vec>(FluidId::PAIR_VELOCITY);
        a_ = r.template getValue<Vec>(QuantityId::POSITION);
    }
    template <bool Symmetric>
    void eval(Size i, Size j, const Vec&, const PairGeometry<Dim>& pair) {
        const bool fi = isFluid(kind_[i]), fj = isFluid(kind_[j]);
        const ViscousData<Dim>& d = *data_;
        if (!(fi || (Symmetric && fj)) || !d.active[i] || !d.active[j]) return;
        const Float f = formulas::laminarViscosityFactor(d.mu[i], d.mu[j], pair.laplacian);
        const Vec dv = v_[i] - v_[j];
        if (fi) a_[i] += formulas::laminarViscosityAcceleration(dv, f, volume_[j], 1.0 / rho_[i]);
        if constexpr (Symmetric)
            if (fj)
                a_[j] -= formulas::laminarViscosityAcceleration(dv, f, volume_[i], 1.0 / rho_[j]);
    }
    /// Gather (asymmetric) evaluation: the particle's own data read once and its sum kept in a
    /// register, with eval's formula in eval's order, so the result is bitwise eval's.
    void gatherNeighbours(Size i, ArrayView<const Size> neighs, ArrayView<const Vec>,
                          const NeighbourGeometry<Dim>& geometry) {
        const ViscousData<Dim>& d = *data_;
        if (!isFluid(kind_[i]) || !d.active[i]) return;
        const Vec vi = v_[i];
        const Float mui = d.mu[i], invRhoi = 1.0 / rho_[i];  // once per particle, not per pair
        Vec sum = a_[i];
        for (std::size_t k = 0; k < neighs.size(); ++k) {
            const Size j = neighs[k];
            if (!d.active[j]) continue;
            const Float f = formulas::laminarViscosityFactor(mui, d.mu[j], geometry.laplacian[k]);
            sum += formulas::laminarViscosityAcceleration(vi - v_[j], f, volume_[j], invRhoi);
        }
        a_[i] = sum;
    }

  private:
    std::shared_ptr<const ViscousData<Dim>> data_;
    ArrayView<const Vec> v_;
    ArrayView<const Float> volume_, rho_;
    ArrayView<const int> kind_;
    ArrayView<Vec> a_;
};

template <int Dim>
class LaminarViscosity : public IEquationTerm<Dim> {
  public:
    using Vec = Vector<Dim>;
    /// nu: the kinematic viscosity every particle starts with (KINEMATIC_VISCOSITY).
    explicit LaminarViscosity(Float nu) : nu_(nu) {}

    void setDerivatives(DerivativeHolder<Dim>& d, const RunSettings&) override {
        d.template require<LaminarViscosityPart<Dim>>(data_);
    }
    void initialize(IScheduler& scheduler, Storage<Dim>& s, Float) override {
        const auto rho = s.template getValue<Float>(QuantityId::DENSITY);
        const auto nu = s.template getValue<Float>(FluidId::KINEMATIC_VISCOSITY);
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        const auto slip = s.template getValue<int>(FluidId::WALL_SLIP);
        ViscousData<Dim>& d = *data_;
        d.mu.resize(s.size()), d.active.resize(s.size());
        scheduler.parallelFor(s.size(), 4096, [&](Size b, Size e) {
            for (Size i = b; i < e; ++i) {
                d.mu[i] = formulas::dynamicViscosity(rho[i], nu[i]);
                d.active[i] = isFluid(kind[i]) || slip[i] == int(WallSlip::NO_SLIP);
            }
        });
    }
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}
    TermAccess access() const override {
        return {.reads = {QuantityId::DENSITY, FluidId::KINEMATIC_VISCOSITY},
                .needs = {pairVolume, pairVelocity}};
    }
    void create(Storage<Dim>& s, IMaterial&) const override {
        s.template insert<Float>(FluidId::KINEMATIC_VISCOSITY, OrderEnum::ZERO, nu_);
        s.template insert<int>(FluidId::WALL_SLIP, OrderEnum::ZERO, int(WallSlip::NO_SLIP));
    }
    void limitTimeStep(const Storage<Dim>& s, const RunSettings& settings,
                       TimeStepLimits& limits) const override {
        const auto nu = s.template getValue<Float>(FluidId::KINEMATIC_VISCOSITY);
        const Float numax = largestOf(limits.scheduler(), s.size(), [&](Size i) { return nu[i]; });
        const Float h = settings.get<double>("smoothing_length");
        if (numax > 0)
            limits.offer("viscous",
                         formulas::viscousStep(settings.get<double>("viscous_factor"), h, numax));
    }

  private:
    Float nu_;
    std::shared_ptr<ViscousData<Dim>> data_ = std::make_shared<ViscousData<Dim>>();
};

}  // namespace num::sph
