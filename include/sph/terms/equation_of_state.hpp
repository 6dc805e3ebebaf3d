// Equation of state of a weakly-compressible fluid, and the term that applies it.
//
// Tait (Monaghan 1994, eq. 3.5) or linear (Morris et al. 1997, eq. 10): EquationOfState in
// sph/formulas/equation_of_state.hpp, callable on host and device.
// The term holds each fluid particle's pressure at or above p_b - T_max: liquid stretched
// beyond the tension T_max cavitates (sph/defaults.hpp, maxTension); its density is left as it
// is, the particle's larger volume standing for the cavity.
// The term also offers the Courant limit dt <= C h / (c0 + max|v|) (Monaghan 1992, sec. 10).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "sph/equation_term.hpp"
#include "sph/formulas/equation_of_state.hpp"
#include "sph/formulas/time_step.hpp"
#include "sph/terms/fluid_quantities.hpp"

namespace num::sph {

/// Sets the pressure of every fluid particle from its density, p_i = max(p(rho_i), p_b - T_max)
/// (boundary particles get theirs from the wall condition).
template <int Dim>
class EquationOfStateTerm : public IEquationTerm<Dim> {
  public:
    /// maxTension: T_max [Pa], the most tension the liquid holds; infinite: no limit.
    explicit EquationOfStateTerm(EquationOfState eos,
                                 Float maxTension = std::numeric_limits<Float>::infinity())
        : eos_(eos), pMin_(eos.backgroundPressure - maxTension) {}

    const EquationOfState& eos() const { return eos_; }

    void setDerivatives(DerivativeHolder<Dim>&, const RunSettings&) override {}

    void initialize(IScheduler& scheduler, Storage<Dim>& s, Float) override {
        auto rho = s.template getValue<Float>(QuantityId::DENSITY);
        auto p = s.template getValue<Float>(QuantityId::PRESSURE);
        auto kind = s.template getValue<int>(QuantityId::KIND);
        scheduler.parallelFor(s.size(), 4096, [&](Size b, Size e) {
            for (Size i = b; i < e; ++i)
                if (isFluid(kind[i])) p[i] = formulas::fluidPressure(eos_, rho[i], pMin_);
        });
    }
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}

    TermAccess access() const override {
        return {.reads = {QuantityId::DENSITY}, .prepares = {QuantityId::PRESSURE}};
    }
    void create(Storage<Dim>& s, IMaterial&) const override {
        s.template insert<Float>(QuantityId::DENSITY, OrderEnum::ZERO, eos_.rho0);
        s.template insert<Float>(QuantityId::PRESSURE, OrderEnum::ZERO, eos_.backgroundPressure);
        s.template insert<int>(QuantityId::KIND, OrderEnum::ZERO, int(ParticleKind::FLUID));
    }

    void limitTimeStep(const Storage<Dim>& s, const RunSettings& settings,
                       TimeStepLimits& limits) const override {
        const auto v = s.template getDt<Vector<Dim>>(QuantityId::POSITION);
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        const Float v2 = largestOf(limits.scheduler(), s.size(), [&](Size i) {
            return isFluid(kind[i]) ? normSqr(v[i]) : Float(0);
        });
        const Float h = settings.get<double>("smoothing_length");
        limits.offer("courant", formulas::courantStep(settings.get<double>("cfl"), h, eos_.c0, v2));
    }

  private:
    EquationOfState eos_;
    Float pMin_;  ///< p_b - T_max
};

}  // namespace num::sph
