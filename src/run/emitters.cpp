#include "app/emitters.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "app/formatted.hpp"
#include "app/nozzle.hpp"

namespace num::app {

using sph::QuantityId;
using sph::Size;

std::vector<char> WaterAt::occupied() const {
    std::vector<char> taken(near.size());
    for (std::size_t p = 0; p < near.size(); ++p)
        taken[p] = near[p] || fraction[p] > kOccupiedFraction;
    return taken;
}

template <int Dim>
WaterAt waterAt(const sph::Storage<Dim>& storage, const Domain<Dim>& domain,
                const sph::RunKernel<Dim>& kernel, const std::vector<sph::Vector<Dim>>& points,
                double radius, const std::function<bool(Size)>& counts) {
    WaterAt water{std::vector<double>(points.size(), 0.0), std::vector<char>(points.size(), 0)};
    const double reach = std::max(radius, kernel.supportRadius());
    // Consecutive points (one nozzle's layer) lie close together: test a particle against the
    // box around each run of 32 (centre, half-widths widened by the reach) before the points.
    constexpr std::size_t run = 32;
    std::vector<std::pair<sph::Vector<Dim>, sph::Vector<Dim>>> boxes;
    for (std::size_t first = 0; first < points.size(); first += run) {
        sph::Vector<Dim> lo = points[first], hi = points[first];
        for (std::size_t p = first; p < std::min(points.size(), first + run); ++p)
            for (int k = 0; k < Dim; ++k)
                lo[k] = std::min(lo[k], points[p][k]), hi[k] = std::max(hi[k], points[p][k]);
        boxes.emplace_back((lo + hi) * 0.5, (hi - lo) * 0.5);
    }
    const auto x = storage.template getValue<sph::Vector<Dim>>(QuantityId::POSITION);
    const auto m = storage.template getValue<sph::Float>(QuantityId::MASS);
    const auto rho = storage.template getValue<sph::Float>(QuantityId::DENSITY);
    const auto kind = storage.template getValue<int>(QuantityId::KIND);
    for (Size i = 0; i < storage.size(); ++i) {
        if (kind[i] != int(sph::ParticleKind::FLUID)) continue;
        const bool counted = counts(i);
        for (std::size_t b = 0; b < boxes.size(); ++b) {
            const sph::Vector<Dim> d = domain.minimumImage(x[i] - boxes[b].first);
            bool inBox = true;
            for (int k = 0; k < Dim; ++k) inBox &= std::abs(d[k]) < boxes[b].second[k] + reach;
            if (!inBox) continue;
            for (std::size_t p = b * run; p < std::min(points.size(), (b + 1) * run); ++p) {
                const double r = norm(domain.minimumImage(x[i] - points[p]));
                if (r < radius) water.near[p] = 1;
                if (counted) water.fraction[p] += m[i] / rho[i] * kernel.W(r);
            }
        }
    }
    return water;
}

template <int Dim>
std::vector<char> occupiedPoints(const sph::Storage<Dim>& storage, const Domain<Dim>& domain,
                                 const sph::RunKernel<Dim>& kernel,
                                 const std::vector<sph::Vector<Dim>>& points, double spacing,
                                 const parallel::Communicator& comm) {
    // Without owners (one process, before any distribution) the root counts every particle.
    const bool owners = storage.has(QuantityId::OWNER);
    const auto owner =
        owners ? storage.template getValue<int>(QuantityId::OWNER) : sph::ArrayView<const int>();
    WaterAt water = waterAt(storage, domain, kernel, points, 0.5 * spacing, [&](Size i) {
        const int o = owners ? owner[i] : -1;
        return o == comm.rank() || (o < 0 && comm.isRoot());
    });
    if (comm.size() == 1) return water.occupied();
    const auto* sums = reinterpret_cast<const char*>(water.fraction.data());
    const parallel::Bytes mine(sums, sums + water.fraction.size() * sizeof(double));
    std::vector<double> part(points.size());
    std::fill(water.fraction.begin(), water.fraction.end(), 0.0);
    for (const parallel::Bytes& other : comm.allGather(mine)) {  // by rank: the same order
        std::memcpy(part.data(), other.data(), other.size());
        for (std::size_t p = 0; p < points.size(); ++p) water.fraction[p] += part[p];
    }
    for (const parallel::Bytes& other : comm.allGather(water.near))
        for (std::size_t p = 0; p < points.size(); ++p) water.near[p] |= other[p];
    return water.occupied();
}

template <int Dim>
Emitters<Dim>::Emitters(const Scene<Dim>& scene, const SceneSetup<Dim>& setup)
    : scene_(scene),
      setup_(setup),
      layers_(scene.emitters.size(), 0),
      warned_(scene.emitters.size(), 0) {
    for (std::size_t e = 0; e < scene.emitters.size(); ++e)
        discs_.push_back(openNozzle(scene, e).open);
}

template <int Dim>
std::uint64_t Emitters<Dim>::layersDue(std::size_t e, double t) const {
    const Emitter<Dim>& em = scene_.emitters[e];
    if (t < em.start) return 0;
    const double te = std::min(t, em.end);
    return std::uint64_t(std::floor((te - em.start) * em.speed / scene_.spacing)) + 1;
}

template <int Dim>
bool Emitters<Dim>::anyDue(double t) const {
    for (std::size_t e = 0; e < scene_.emitters.size(); ++e)
        if (layersDue(e, t) > layers_[e]) return true;
    return false;
}

template <int Dim>
std::size_t Emitters<Dim>::emit(sph::Storage<Dim>& storage, double t, const Occupied& occupied) {
    const double dx = scene_.spacing;
    // The lattice points of every layer due, emitter by emitter.
    std::vector<sph::Vector<Dim>> points;
    std::vector<std::size_t> firstPoint(scene_.emitters.size() + 1, 0);
    for (std::size_t e = 0; e < scene_.emitters.size(); ++e) {
        firstPoint[e] = points.size();
        const Emitter<Dim>& em = scene_.emitters[e];
        if (t < em.start) continue;
        const std::uint64_t due = layersDue(e, t);
        for (std::uint64_t k = layers_[e]; k < due; ++k) {
            const double travelled = (t - (em.start + double(k) * dx / em.speed)) * em.speed;
            for (const auto& off : discs_[e])
                points.push_back(em.position + off + em.direction * travelled);
        }
        layers_[e] = std::max(layers_[e], due);
    }
    firstPoint.back() = points.size();
    if (points.empty()) return 0;
    const std::vector<char> taken = occupied(points);
    std::size_t added = 0;
    for (std::size_t e = 0; e < scene_.emitters.size(); ++e) {
        std::size_t count = 0;
        for (std::size_t p = firstPoint[e]; p < firstPoint[e + 1]; ++p) count += !taken[p];
        const std::size_t due = firstPoint[e + 1] - firstPoint[e];
        blocked_ += due - count;
        if (count < due && !warned_[e]) {
            warned_[e] = 1;
            warnings_.push_back(
                formatted("at t = %.3g s emitter \"", t) + scene_.emitters[e].name +
                "\" left out " + std::to_string(due - count) + " of " + std::to_string(due) +
                " nozzle points: water was there (a splash on the nozzle, or the nozzle in "
                "water); a nozzle in water injects less than speed x area, so keep nozzles above "
                "the water (summary.json counts the points left out)");
        }
        if (count == 0) continue;
        sph::Storage<Dim> batch;
        setup_.emitterTemplates[e].forEach([&](QuantityId id, const sph::Quantity<Dim>& q) {
            q.visit([&](const auto& b) {
                using T = typename std::decay_t<decltype(b.value)>::value_type;
                batch.template insert<T>(id, q.order(), std::vector<T>(count, b.value[0]));
            });
        });
        auto x = batch.template getValue<sph::Vector<Dim>>(QuantityId::POSITION);
        auto v = batch.template getDt<sph::Vector<Dim>>(QuantityId::POSITION);
        const Emitter<Dim>& em = scene_.emitters[e];
        std::size_t n = 0;
        for (std::size_t p = firstPoint[e]; p < firstPoint[e + 1]; ++p)
            if (!taken[p]) x[n] = points[p], v[n] = em.direction * em.speed, ++n;
        storage.append(batch);
        added += count;
    }
    emitted_ += added;
    return added;
}

template WaterAt waterAt<2>(const sph::Storage<2>&, const Domain<2>&, const sph::RunKernel<2>&,
                            const std::vector<sph::Vector<2>>&, double,
                            const std::function<bool(Size)>&);
template WaterAt waterAt<3>(const sph::Storage<3>&, const Domain<3>&, const sph::RunKernel<3>&,
                            const std::vector<sph::Vector<3>>&, double,
                            const std::function<bool(Size)>&);
template std::vector<char> occupiedPoints<2>(const sph::Storage<2>&, const Domain<2>&,
                                             const sph::RunKernel<2>&,
                                             const std::vector<sph::Vector<2>>&, double,
                                             const parallel::Communicator&);
template std::vector<char> occupiedPoints<3>(const sph::Storage<3>&, const Domain<3>&,
                                             const sph::RunKernel<3>&,
                                             const std::vector<sph::Vector<3>>&, double,
                                             const parallel::Communicator&);
template class Emitters<2>;
template class Emitters<3>;

}  // namespace num::app
