// The CPU terms the device step implements. A model runs on the device only if every term of its
// CPU equations (sph::makeFluidEquations) is one of these, of exactly that type: a term the device
// does not know (a plugin's, a user's, a subclass of a built-in one, one added to the CPU engine
// later) is refused by its name. The device step reads each term's parameters from the model
// (makeFluidStepConfig).
#pragma once

#include <string>
#include <tuple>
#include <typeinfo>

#include "sph/fluid_model.hpp"

namespace num::device {

template <int Dim>
using DeviceTerms =
    std::tuple<sph::TemperatureViscosity<Dim>, sph::NeighbourRefresh<Dim>,
               sph::SummationDensity<Dim>, sph::EquationOfStateTerm<Dim>,
               sph::FreeSurfaceTensionLimit<Dim>, sph::GeneralizedWall<Dim>,
               sph::WallTemperature<Dim>, sph::OutletCondition<Dim>, sph::PairInputs<Dim>,
               sph::ContinuityDensity<Dim>, sph::DeltaSph<Dim>, sph::PressureGradient<Dim>,
               sph::LaminarViscosity<Dim>, sph::ArtificialViscosity<Dim>, sph::BodyForceTerm<Dim>,
               sph::ParticleShifting<Dim>, sph::HeatConduction<Dim>, sph::ThermalBoundary<Dim>,
               sph::BoussinesqBuoyancy<Dim>, sph::RigidBodyCoupling<Dim>, sph::BoundaryHold<Dim>,
               sph::ParticleContainment<Dim>, sph::BuiltInPairSums<Dim>>;

template <int Dim, class... Known>
bool isOneOf(const sph::IEquationTerm<Dim>& term, const std::tuple<Known...>*) {
    return ((typeid(term) == typeid(Known)) || ...);
}

/// Whether the device step implements this term (its exact type is one of DeviceTerms).
template <int Dim>
bool runsOnDevice(const sph::IEquationTerm<Dim>& term) {
    return isOneOf(term, static_cast<const DeviceTerms<Dim>*>(nullptr));
}

/// The name of the first term the device step does not implement, or "" when it runs them all.
template <int Dim>
std::string firstTermNotOnDevice(const sph::EquationHolder<Dim>& equations) {
    std::string found;
    equations.forTerms([&](const sph::IEquationTerm<Dim>& term) {
        if (found.empty() && !runsOnDevice(term)) found = term.name();
    });
    return found;
}

}  // namespace num::device
