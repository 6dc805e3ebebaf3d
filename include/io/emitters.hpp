// Emitters (inflow nozzles): layers of particles injected across a nozzle as the flow moves
// one spacing, except at lattice points that water already occupies.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "io/scene_setup.hpp"

namespace num::io {

/// Which of `points` lie closer than `radius` to a fluid particle of `storage` (1) or not (0),
/// distances taken to the nearest periodic image.
template <int Dim>
std::vector<char> fluidNear(const sph::Storage<Dim>& storage, const Domain<Dim>& domain,
                            const std::vector<sph::Vector<Dim>>& points, double radius);

/// Emitter state: the layers each emitter has injected so far and the particles it added or
/// left out.
template <int Dim>
class Emitters {
  public:
    /// Which of the given points water occupies (1), the same answer on every process.
    using Occupied = std::function<std::vector<char>(const std::vector<sph::Vector<Dim>>&)>;

    Emitters(const Scene<Dim>& scene, const SceneSetup<Dim>& setup);
    /// Adds the layers due by time t, each lattice point of a layer unless `occupied` says that
    /// water is there (closer than half a spacing); returns the number of particles added.
    std::size_t emit(sph::Storage<Dim>& storage, double t, const Occupied& occupied);
    std::vector<std::uint64_t>& layers() { return layers_; }
    std::size_t emitted() const { return emitted_; }
    void setEmitted(std::size_t n) { emitted_ = n; }
    /// Lattice points of due layers left out because water was there.
    std::uint64_t blocked() const { return blocked_; }
    void setBlocked(std::uint64_t n) { blocked_ = n; }

  private:
    const Scene<Dim>& scene_;
    const SceneSetup<Dim>& setup_;
    std::vector<std::vector<sph::Vector<Dim>>> discs_;  ///< lattice offsets of each nozzle
    std::vector<std::uint64_t> layers_;
    std::size_t emitted_ = 0;
    std::uint64_t blocked_ = 0;
};

}  // namespace num::io
