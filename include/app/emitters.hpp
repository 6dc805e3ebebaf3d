// Emitters (inflow nozzles): layers of particles injected across a nozzle as the flow moves
// one spacing, except at lattice points that water already occupies.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "app/scene_setup.hpp"
#include "parallel/communicator.hpp"
#include "sph/kernel_choice.hpp"

namespace num::app {

/// Water's kernel sum above which a nozzle point counts as occupied (see WaterAt).
inline constexpr double kOccupiedFraction = 0.4;

/// The water at each of some points: the kernel sum of the fluid particles that `counts` selects
/// (sum_j m_j / rho_j W(|p - x_j|): about 1 inside water, 0.5 half a spacing above a free
/// surface, 0.2 at a nozzle whose earlier layers have moved on by a spacing) and whether any
/// fluid particle lies closer than `radius` (distances to the nearest periodic image).
struct WaterAt {
    std::vector<double> fraction;
    std::vector<char> near;
    /// The points water occupies: a fluid particle near, or a sum above kOccupiedFraction.
    std::vector<char> occupied() const;
};
template <int Dim>
WaterAt waterAt(const sph::Storage<Dim>& storage, const Domain<Dim>& domain,
                const sph::RunKernel<Dim>& kernel, const std::vector<sph::Vector<Dim>>& points,
                double radius, const std::function<bool(sph::Size)>& counts);

/// The points water occupies (WaterAt::occupied, half a spacing for `near`), the same answer on
/// every process of `comm`: each adds the kernel sums of the particles it owns (the root those
/// not yet assigned) and looks for near particles among all it holds, halo copies included.
template <int Dim>
std::vector<char> occupiedPoints(const sph::Storage<Dim>& storage, const Domain<Dim>& domain,
                                 const sph::RunKernel<Dim>& kernel,
                                 const std::vector<sph::Vector<Dim>>& points, double spacing,
                                 const parallel::Communicator& comm);

/// Emitter state: the layers each emitter has injected so far and the particles it added or
/// left out.
template <int Dim>
class Emitters {
  public:
    /// Which of the given points water occupies (1), the same answer on every process.
    using Occupied = std::function<std::vector<char>(const std::vector<sph::Vector<Dim>>&)>;

    Emitters(const Scene<Dim>& scene, const SceneSetup<Dim>& setup);
    /// Adds the layers due by time t, each lattice point of a layer unless `occupied` says that
    /// water is there; returns the number of particles added.
    std::size_t emit(sph::Storage<Dim>& storage, double t, const Occupied& occupied);
    /// Whether emit(t) has a layer to add.
    bool anyDue(double t) const;
    std::vector<std::uint64_t>& layers() { return layers_; }
    std::size_t emitted() const { return emitted_; }
    void setEmitted(std::size_t n) { emitted_ = n; }
    /// Lattice points of due layers left out because water was there.
    std::uint64_t blocked() const { return blocked_; }
    void setBlocked(std::uint64_t n) { blocked_ = n; }
    /// One warning per emitter, made the first time it left points out (in the order made).
    const std::vector<std::string>& warnings() const { return warnings_; }

  private:
    /// The layers emitter e has injected once emit(t) ran: the nozzle's travel over dx, plus one.
    std::uint64_t layersDue(std::size_t e, double t) const;

    const Scene<Dim>& scene_;
    const SceneSetup<Dim>& setup_;
    std::vector<std::vector<sph::Vector<Dim>>> discs_;  ///< each nozzle's open lattice offsets
    std::vector<std::uint64_t> layers_;
    std::size_t emitted_ = 0;
    std::uint64_t blocked_ = 0;
    std::vector<char> warned_;
    std::vector<std::string> warnings_;
};

}  // namespace num::app
