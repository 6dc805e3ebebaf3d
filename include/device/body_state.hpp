// The moving bodies as the device step sees them (plain data; device/body_step.hpp holds them in
// the execution's memory): each body's frame (sph/bodies/body_frame.hpp) and contact law, which
// bodies move and which are hinged together, set by the host (device/body_run.hpp) before the
// first evaluation and after every advance of the bodies; and the loads an evaluation leaves on
// the moving particles, which the host sums into each body's force and torque.
#pragma once

#include <vector>

#include "sph/bodies/body_frame.hpp"
#include "sph/formulas/contact_law.hpp"

namespace num::sph {
template <int Dim>
class MovingBodies;
}

namespace num::device {

template <int Dim>
struct DeviceBodies {
    std::vector<sph::BodyFrame<Dim>> frames;  ///< every body's (a fixed one's unused)
    std::vector<sph::ContactLaw<Dim>> laws;   ///< every body's (kn = 0: no contacts)
    std::vector<char> moves;                  ///< whether body b moves
    std::vector<char> hinged;                 ///< [a * count + b]: a and b hinged together
};

/// The moving particles' positions and loads of the last evaluation, in the storage's order: the
/// fluid's force (boundary_force.hpp) and the contacts' (contact_law.hpp) on each.
template <int Dim>
struct BodyLoads {
    std::vector<sph::Vector<Dim>> x, force, contact;
};

}  // namespace num::device
