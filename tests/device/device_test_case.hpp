// What the device step's tests share: the numerics of their dam breaks, and the CPU's particles
// sorted as the device grid sorts them, so that both engines meet the neighbours in one order
// and their sums agree bit for bit.
#pragma once

#include <string>
#include <vector>

#include "device/fluid_run.hpp"

namespace num::device_tests {

/// Gravity, U = 2.5 m/s, laminar (1e-6 m^2/s) and artificial (0.02) viscosity, the Wendland C2
/// kernel with h = 1.5 dx.
template <int Dim>
void setDamBreakNumerics(sph::FluidModel<Dim>& model, sph::RunSettings& settings, double dx) {
    sph::Vector<Dim> g{};
    g[Dim - 1] = -9.81;
    model.bodyForce = sph::constantForce(g);
    model.maxVelocity = 2.5;
    model.viscosity = 1e-6;
    model.artificialViscosity = 0.02;
    settings.set("kernel", std::string("wendland_c2")).set("smoothing_length", 1.5 * dx);
}

/// Sorts the storage's particles as the device grid sorts them (by cell, stably).
template <int Dim>
void sortAsTheDevice(sph::Storage<Dim>& s, const device::FluidStepConfig<Dim>& c) {
    device::HostExecution exec;
    device::NeighbourGrid<Dim, device::HostExecution> grid(exec, c.supportRadius, c.domainMin,
                                                           c.domainMax, c.periodic);
    const auto x = s.template getValue<sph::Vector<Dim>>(sph::QuantityId::POSITION);
    grid.build(x.data(), device::Index(x.size()));
    std::vector<sph::Size> order(grid.order(), grid.order() + x.size());
    s.reorder(order);
}

}  // namespace num::device_tests
