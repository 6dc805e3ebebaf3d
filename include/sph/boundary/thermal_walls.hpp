// Thermal walls and bodies: fixed temperature, adiabatic, fixed heat flux, conducting.
//
// Boundary particles (QuantityId::KIND = WALL or BODY) take part in heat conduction like any
// particle (terms/heat_conduction.hpp); their heat_ids::THERMAL_CONDITION says what happens:
//   FIXED_TEMPERATURE  Dirichlet: T_b is held, dT_b/dt := 0 after the pair sums; the heat the
//                      conduction operator moved into them is counted as delivered to the rest.
//   ADIABATIC          Neumann, zero flux: the conduction pair sum skips every pair with them.
//   HEAT_FLUX          prescribed flux q'' [W/m^2]: the particles conduct and receive
//                      dT/dt += s / c with s = heat_ids::HEAT_SOURCE [W/kg]; setHeatFlux gives
//                      a layer of them of mass M the source s = q'' A / M, so the
//                      power q'' A enters the domain exactly and reaches the fluid by conduction
//                      (a heater plate; in steady state the flux into the fluid is q'').
//   CONDUCTING         a solid (or fluid) with its own material: conjugate heat transfer.
// HEAT_SOURCE also works as a plain volumetric source on any particle (c dT/dt = s), the
// reference implementation of a heat source.
//
// Energy books (trapezoidal in time, as the leapfrog and predictor-corrector integrators
// advance first-order quantities, WallHeatBooks): heatFromFixed() is the heat fixed-temperature
// particles gave to the others, heatFromSources() the heat the sources added; the total sum m c T
// of the evolving particles changes by exactly their sum (to round-off). Each evaluation measures
// the powers; the post-step phase books 0.5 (P_start + P_end) dt once per step, P_end the power of
// the step's last evaluation.
#pragma once

#include <cmath>
#include <stdexcept>
#include <vector>

#include "sph/boundary/thermal_condition.hpp"
#include "sph/equation_term.hpp"

namespace num::sph {

/// The heat fixed temperatures and sources gave, booked step by step with the trapezoidal rule
/// from the powers each evaluation measured (the CPU's ThermalBoundary, the device engine).
class WallHeatBooks {
  public:
    /// The powers of an evaluation [W]: fixed-temperature particles to the others, sources.
    void measured(double fixedPower, double sourcePower) {
        lastFixed_ = fixedPower, lastSource_ = sourcePower;
        if (!started_) startFixed_ = fixedPower, startSource_ = sourcePower, started_ = true;
    }
    /// Books a step of dt: 0.5 (P_start + P_end) dt, P_end the last evaluation's power.
    void book(double dt) {
        fromFixed_ += 0.5 * (startFixed_ + lastFixed_) * dt;
        fromSources_ += 0.5 * (startSource_ + lastSource_) * dt;
        startFixed_ = lastFixed_, startSource_ = lastSource_;
    }
    /// Heat given by fixed-temperature particles to the others in the steps so far [J].
    double heatFromFixed() const { return fromFixed_; }
    /// Heat added by heat sources (and flux walls) in the steps so far [J].
    double heatFromSources() const { return fromSources_; }
    /// Power of the fixed-temperature particles and of the sources at the last evaluation [W].
    double fixedPower() const { return lastFixed_; }
    double sourcePower() const { return lastSource_; }
    /// For a checkpoint: the heats so far and the powers the next step starts from.
    std::vector<double> save() const {
        return {fromFixed_, fromSources_, startFixed_, startSource_, double(started_)};
    }
    /// Throws std::invalid_argument on a vector that save() did not make.
    void restore(const std::vector<double>& b) {
        if (b.size() != 5) throw std::invalid_argument("holds no heat books of the walls");
        fromFixed_ = b[0], fromSources_ = b[1], startFixed_ = b[2], startSource_ = b[3];
        started_ = b[4] != 0;
    }

  private:
    bool started_ = false;  // the powers at the start of the first step are known
    double startFixed_ = 0, startSource_ = 0, lastFixed_ = 0, lastSource_ = 0;
    double fromFixed_ = 0, fromSources_ = 0;
};

template <int Dim>
class ThermalBoundary : public IEquationTerm<Dim> {
  public:
    /// wallDefault / bodyDefault: the condition given to WALL / BODY particles when this term
    /// creates heat_ids::THERMAL_CONDITION (an existing quantity is kept as it is).
    explicit ThermalBoundary(ThermalCondition wallDefault = ThermalCondition::ADIABATIC,
                             ThermalCondition bodyDefault = ThermalCondition::FIXED_TEMPERATURE)
        : wallDefault_(wallDefault), bodyDefault_(bodyDefault) {}

    void setDerivatives(DerivativeHolder<Dim>&, const RunSettings&) override {}
    void initialize(IScheduler&, Storage<Dim>&, Float) override {}

    void finalize(IScheduler& scheduler, Storage<Dim>& s, Float) override {
        const std::vector<ThermalMaterial> table = thermalMaterials(s);
        const auto cond = s.template getValue<int>(heat_ids::THERMAL_CONDITION);
        const auto src = s.template getValue<Float>(heat_ids::HEAT_SOURCE);
        const auto m = s.template getValue<Float>(QuantityId::MASS);
        const auto dT = s.template getDt<Float>(QuantityId::TEMPERATURE);
        const std::vector<int> zeros(s.has(QuantityId::MATERIAL) ? 0 : s.size(), 0);
        const ArrayView<const int> mat = s.has(QuantityId::MATERIAL)
                                             ? s.template getValue<int>(QuantityId::MATERIAL)
                                             : ArrayView<const int>(zeros);
        // Powers are summed in particle order on one thread (bitwise reproducible); the
        // per-particle updates are independent.
        Float fixedPower = 0, sourcePower = 0;
        for (Size i = 0; i < s.size(); ++i) {
            const Float c = table[mat[i]].heatCapacity;
            if (cond[i] == int(ThermalCondition::FIXED_TEMPERATURE))
                fixedPower -= m[i] * c * dT[i];
            else
                sourcePower += m[i] * src[i];
        }
        scheduler.parallelFor(s.size(), 4096, [&](Size b, Size e) {
            for (Size i = b; i < e; ++i) {
                if (cond[i] == int(ThermalCondition::FIXED_TEMPERATURE))
                    dT[i] = 0;
                else if (src[i] != 0)
                    dT[i] += src[i] / table[mat[i]].heatCapacity;
            }
        });
        books_.measured(fixedPower, sourcePower);
    }

    void postStep(IScheduler&, Storage<Dim>&, Float, Float dt) override { books_.book(dt); }

    /// The last pass: fixed temperatures hold against every term's dT/dt.
    TermAccess access() const override { return {.placement = PassPlacement::LAST}; }
    void create(Storage<Dim>& storage, IMaterial&) const override {
        storage.template insert<Float>(QuantityId::TEMPERATURE, OrderEnum::FIRST, 0.0);
        storage.template insert<Float>(heat_ids::HEAT_SOURCE, OrderEnum::ZERO, 0.0);
        if (storage.has(heat_ids::THERMAL_CONDITION)) return;
        std::vector<int> c(storage.size(), int(ThermalCondition::CONDUCTING));
        if (storage.has(QuantityId::KIND)) {
            const auto kind = storage.template getValue<int>(QuantityId::KIND);
            for (Size i = 0; i < storage.size(); ++i) {
                if (kind[i] == int(ParticleKind::WALL)) c[i] = int(wallDefault_);
                if (kind[i] == int(ParticleKind::BODY)) c[i] = int(bodyDefault_);
            }
        }
        storage.template insert<int>(heat_ids::THERMAL_CONDITION, OrderEnum::ZERO, std::move(c));
    }

    /// Makes the selected particles a heater delivering `flux` [W/m^2] through `area` [m^2]
    /// (in 2D a length, per unit depth): each gets the source s = q'' A / M [W/kg], M the mass
    /// of the selected particles, so that the total power is flux * area.
    static void setHeatFlux(Storage<Dim>& s, Float flux, Float area,
                            const std::function<bool(Size)>& select) {
        setThermalCondition(s, ThermalCondition::HEAT_FLUX, select);
        s.template insert<Float>(heat_ids::HEAT_SOURCE, OrderEnum::ZERO, 0.0);
        const auto m = s.template getValue<Float>(QuantityId::MASS);
        const auto src = s.template getValue<Float>(heat_ids::HEAT_SOURCE);
        Float mass = 0;
        for (Size i = 0; i < s.size(); ++i)
            if (select(i)) mass += m[i];
        if (!(mass > 0)) throw std::invalid_argument("setHeatFlux: no particle selected");
        for (Size i = 0; i < s.size(); ++i)
            if (select(i)) src[i] = flux * area / mass;
    }

    /// The heat books: what fixed temperatures and sources gave so far.
    const WallHeatBooks& books() const { return books_; }
    WallHeatBooks& books() { return books_; }

  private:
    ThermalCondition wallDefault_, bodyDefault_;
    WallHeatBooks books_;
};

}  // namespace num::sph
