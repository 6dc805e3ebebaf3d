// The heat part of a case: which heat terms run and how walls and bodies behave thermally.
// FluidModel::heat holds one; makeFluidEquations puts makeHeatPreEquations before the fluid
// terms and makeHeatEquations(model.heat, bodyForce) after them. Materials (FluidModel::materials)
// carry conductivity, heat capacity, thermal expansion and reference temperature; geometry regions,
// walls and bodies carry the initial (or fixed) temperatures and material indices.
#pragma once

#include <functional>

#include "sph/boundary/thermal_walls.hpp"
#include "sph/terms/boussinesq_buoyancy.hpp"
#include "sph/terms/heat_conduction.hpp"
#include "sph/terms/temperature_viscosity.hpp"

namespace num::sph {

template <int Dim>
struct HeatModel {
    /// Conduction between all particles that are not adiabatic (terms/heat_conduction.hpp).
    bool conduction = false;
    /// Thermal condition of wall and body particles (boundary/thermal_walls.hpp); bodies that
    /// conduct with their own material give conjugate heat transfer.
    ThermalCondition walls = ThermalCondition::ADIABATIC;
    ThermalCondition bodies = ThermalCondition::FIXED_TEMPERATURE;
    /// Boussinesq buoyancy -beta (T - T0) g with the body force as g (needs thermal_expansion).
    bool buoyancy = false;
    /// Temperature-dependent viscosity of the fluid (terms/temperature_viscosity.hpp).
    bool temperatureViscosity = false;
    ViscosityOfTemperature viscosityLaw{};

    bool any() const { return conduction || buoyancy || temperatureViscosity; }
};

/// The heat terms that must run before the fluid terms (viscosity from temperature).
template <int Dim>
EquationHolder<Dim> makeHeatPreEquations(const HeatModel<Dim>& heat) {
    EquationHolder<Dim> eq;
    if (heat.temperatureViscosity) eq += makeTerm<TemperatureViscosity<Dim>>(heat.viscosityLaw);
    return eq;
}

/// The heat terms after the fluid terms; gravity is the body force of the run (buoyancy).
template <int Dim>
EquationHolder<Dim> makeHeatEquations(const HeatModel<Dim>& heat,
                                      std::function<Vector<Dim>(Float)> gravity = {}) {
    EquationHolder<Dim> eq;
    if (heat.conduction) {
        eq += makeTerm<HeatConduction<Dim>>();
        eq += makeTerm<ThermalBoundary<Dim>>(heat.walls, heat.bodies);
    }
    if (heat.buoyancy && gravity) eq += makeTerm<BoussinesqBuoyancy<Dim>>(std::move(gravity));
    return eq;
}

}  // namespace num::sph
