// An emitter's nozzle: the lattice points across it, less those a body or wall takes.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "app/scene.hpp"

namespace num::app {

/// Offsets from an emitter's centre to the lattice points across its nozzle (spacing dx): a row
/// across the direction in 2D, the points of a square lattice within the radius in 3D.
template <int Dim>
std::vector<SceneVec<Dim>> nozzleOffsets(const Emitter<Dim>& e, double dx);

/// The part of emitter `i`'s nozzle that is open: the offsets whose points lie at least half a
/// spacing outside every body and wall of the scene (closer, a new particle would sit on the
/// solid's boundary particles), and what took the others.
template <int Dim>
struct Nozzle {
    std::vector<SceneVec<Dim>> open;  ///< offsets from the emitter's position
    std::size_t cut = 0;              ///< points taken by a body or wall
    std::string cutBy;                ///< the key of the first body or wall that took one
};
template <int Dim>
Nozzle<Dim> openNozzle(const Scene<Dim>& scene, std::size_t i);

}  // namespace num::app
