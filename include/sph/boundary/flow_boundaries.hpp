// Inlets and outlets: open boundaries with buffer zones (Tafuni, Dominguez, Vacondio & Crespo
// 2018, Comput. Methods Appl. Mech. Engrg. 342, 604; the approach of DualSPHysics, PySPH's
// inlet/outlet manager and SPHinXsys's buffers).
//
// An inlet or outlet is a side of the box whose layers (as deep as a wall's: the kernel
// support) are a buffer of particles of kind INLET or OUTLET instead of a wall:
//   inlet   buffer particles move with the imposed velocity u_in(x, t) and carry the imposed
//           temperature T_in(x, t); their pressure and density come from the fluid through the
//           wall condition (Adami et al. 2012, eq. 27-28: p extrapolated, hydrostatic part
//           included). One that crosses the side becomes fluid, and a new buffer particle takes
//           its place one buffer depth behind it, so the buffer stays full.
//   outlet  fluid that crosses the side becomes an outlet particle: its pressure is the imposed
//           p_out(x, t) (density from the equation of state), its velocity the Shepard mean of
//           its fluid and outlet neighbours' (zeroth-order extrapolation, Tafuni et al. sec. 3.2
//           use first order); past the buffer's depth it is removed. An outlet particle carried
//           back into the domain (an eddy crossing the side) becomes fluid again.
// The fluid sees buffer particles as neighbours with their own velocity (continuity, viscosity:
// PairInputs); heat conduction skips them (adiabatic: the heat crossing is the heat carried).
// Books (FlowBooks): the mass and the heat (sum m c T) that became fluid at inlets and stopped
// being fluid at outlets, so that the fluid's mass at the end is start + in - out exactly.
// Several processes: each exchanges every particle it holds, owned or halo copy, alike (a halo
// copy equals its owner between steps), books those it owns and makes the buffer particles that
// replace them, which every process then receives; the books' additions and the new particles'
// ids follow a single process's storage order (ORDER_KEY, then PARTICLE_ID), so the books and ids
// are bitwise those of one process.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "sph/boundary/thermal_condition.hpp"
#include "sph/decomposition.hpp"
#include "sph/particle_order.hpp"
#include "sph/terms/equation_of_state.hpp"
#include "sph/terms/neighbour_gather.hpp"

namespace num::sph {

template <int Dim>
using PointFunction = std::function<Float(const Vector<Dim>& x, Float t)>;
template <int Dim>
using VectorFunction = std::function<Vector<Dim>(const Vector<Dim>& x, Float t)>;

/// An inlet or an outlet on one side of the box.
template <int Dim>
struct FlowSide {
    ParticleKind kind = ParticleKind::INLET;  ///< INLET or OUTLET
    int axis = 0, high = 0;                   ///< the side: its axis, 0 at min, 1 at max
    Float plane = 0;                          ///< the side's coordinate on its axis [m]
    Float depth = 0;                          ///< the buffer's depth beyond the side [m]
    VectorFunction<Dim> velocity;             ///< inlet: the velocity it imposes [m/s]
    PointFunction<Dim> temperature;  ///< inlet: the temperature it imposes; empty: the set-up's
    PointFunction<Dim> pressure;     ///< outlet: the pressure it imposes [Pa]
    /// The opening: the box [openFrom, openTo] on the side (its own axis ignored); the rest of
    /// the side is a wall. The default: the whole side.
    Vector<Dim> openFrom = Vector<Dim>::filled(-1e300), openTo = Vector<Dim>::filled(1e300);

    /// How far x lies beyond the side [m] (< 0: inside the domain).
    Float beyond(const Vector<Dim>& x) const { return high ? x[axis] - plane : plane - x[axis]; }
    /// The unit normal out of the domain.
    Vector<Dim> outward() const {
        Vector<Dim> n{};
        n[axis] = high ? 1.0 : -1.0;
        return n;
    }
};

/// What crossed the open boundaries since t = 0: mass [kg] and heat sum m c T [J] (T in degC)
/// into the fluid at inlets and out of it at outlets (net: an outlet particle carried back in
/// counts against `out`).
struct FlowBooks {
    double massIn = 0, massOut = 0, heatIn = 0, heatOut = 0;
    std::uint64_t created = 0;  ///< buffer particles made at inlets (each took a new id)
    std::uint64_t dropped = 0;  ///< outlet particles removed past the buffer

    std::vector<double> save() const {
        return {massIn, massOut, heatIn, heatOut, double(created), double(dropped)};
    }
    /// Throws std::invalid_argument on a vector that save() did not make.
    void restore(const std::vector<double>& v) {
        if (v.size() != 6) throw std::invalid_argument("holds no books of inlets and outlets");
        massIn = v[0], massOut = v[1], heatIn = v[2], heatOut = v[3];
        created = std::uint64_t(v[4]), dropped = std::uint64_t(v[5]);
    }
};

/// The inlets and outlets of a run and their books; the fluid model's term and the run's
/// post-step exchange share it.
template <int Dim>
class FlowBoundaries {
  public:
    using Vec = Vector<Dim>;
    std::vector<FlowSide<Dim>> sides;
    FlowBooks books;

    /// The side of the given kind that x lies furthest beyond (the buffer it belongs to, or
    /// the side it just crossed); -1 if there is none of that kind.
    int sideOf(const Vec& x, ParticleKind kind) const {
        int best = -1;
        for (std::size_t k = 0; k < sides.size(); ++k)
            if (sides[k].kind == kind && (best < 0 || sides[k].beyond(x) > sides[best].beyond(x)))
                best = int(k);
        return best;
    }

    /// Set-up at time t: inlet particles take their side's velocity and temperature; buffer
    /// particles exchange no heat.
    void prepare(Storage<Dim>& s, Float t) const {
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        for (Size i = 0; i < s.size(); ++i)
            if (isBuffer(kind[i])) setBuffer(s, i, t);
    }

    /// After a step that ended at time t: inlet particles past their side become fluid and are
    /// replaced one buffer depth behind (new ids from nextId on, the order of the particles they
    /// replace), the others take the velocity and temperature of time t; fluid past an outlet
    /// becomes an outlet particle, one back inside becomes fluid; outlet particles past the
    /// buffer are removed. With several processes (decomposition), see the top of the file.
    /// Returns whether any particle of this process changed kind or number.
    bool exchange(Storage<Dim>& s, Float t, std::int64_t nextId,
                  const IDecomposition<Dim>* decomposition = nullptr) {
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        const auto x = s.template getValue<Vec>(QuantityId::POSITION);
        const auto heat = heatContent(s);
        std::vector<Size> keep, replaced;
        std::vector<double> entries;  // the books' additions (BookEntry)
        std::int64_t dropped = 0;
        bool changed = false;
        keep.reserve(s.size());
        for (Size i = 0; i < s.size(); ++i) {
            const int before = kind[i];
            const bool owned = !decomposition || decomposition->owned()[i];
            BookEntry e{};
            const Fate fate = update(s, kind, x, i, t, heat, e);
            if (fate == Fate::REMOVED) {
                dropped += owned, changed = true;
                continue;
            }
            if (fate == Fate::CROSSED_INLET && owned)
                replaced.push_back(i);  // the owner replaces it
            if (kind[i] != before) {
                if (owned) e.append(s, i, entries);
                changed = true;
            }
            keep.push_back(i);
        }
        addToBooks(entries, dropped, decomposition);
        const std::uint64_t created = books.created;
        const std::vector<std::int64_t> ids = newIds(s, replaced, nextId, decomposition);
        // Every process takes part in sharing the new particles, any process's.
        const bool share = decomposition && books.created > created;
        if (!changed && !share) return false;
        if (replaced.empty() && keep.size() == s.size() && !share)
            return true;  // kinds changed only
        const Size kept = Size(keep.size());
        keep.insert(keep.end(), replaced.begin(), replaced.end());
        s.gather(keep);  // the kept particles, then copies of the crossed inlet particles
        refill(s, kept, t, ids);
        if (share) shareNew(s, kept, *decomposition);
        return true;
    }

  private:
    /// What one particle's change of kind adds to the books, and the particle's place in a
    /// single process's order (key, id).
    struct BookEntry {
        double massIn = 0, heatIn = 0, massOut = 0, heatOut = 0;
        static constexpr std::size_t kSize = 6;
        void append(const Storage<Dim>& s, Size i, std::vector<double>& out) const {
            out.insert(out.end(), {double(s.template getValue<int>(QuantityId::ORDER_KEY)[i]),
                                   double(s.template getValue<int>(QuantityId::PARTICLE_ID)[i]),
                                   massIn, heatIn, massOut, heatOut});
        }
    };

    enum class Fate { KEPT, CROSSED_INLET, REMOVED };

    /// One particle after the step (exchange): its new kind and imposed values, and what it
    /// adds to the books (e). kind and x: the storage's.
    template <class Heat>
    Fate update(Storage<Dim>& s, ArrayView<int> kind, ArrayView<const Vec> x, Size i, Float t,
                const Heat& heat, BookEntry& e) {
        if (kind[i] == int(ParticleKind::INLET)) {
            if (sides[sideOf(x[i], ParticleKind::INLET)].beyond(x[i]) <= 0) {
                becomeFluid(s, i);
                e.massIn = massOf(s, i), e.heatIn = heat(i);
                return Fate::CROSSED_INLET;
            }
            setBuffer(s, i, t);  // the profile at the new time and place
            return Fate::KEPT;
        }
        if (kind[i] == int(ParticleKind::OUTLET)) {
            const FlowSide<Dim>& side = sides[sideOf(x[i], ParticleKind::OUTLET)];
            if (side.beyond(x[i]) > side.depth) return Fate::REMOVED;
            if (side.beyond(x[i]) <= 0) {
                becomeFluid(s, i);
                e.massOut = -massOf(s, i), e.heatOut = -heat(i);
            }
            return Fate::KEPT;
        }
        if (!isFluid(kind[i])) return Fate::KEPT;
        const int o = sideOf(x[i], ParticleKind::OUTLET);
        if (o >= 0 && sides[o].beyond(x[i]) > 0) {
            e.massOut = massOf(s, i), e.heatOut = heat(i);
            kind[i] = int(ParticleKind::OUTLET);
            setBuffer(s, i, t);
        }
        return Fate::KEPT;
    }

    /// Adds the entries (BookEntry records) of every process to the books, in a single
    /// process's order, and the particles dropped by every process.
    void addToBooks(std::vector<double> entries, std::int64_t dropped,
                    const IDecomposition<Dim>* decomposition) {
        constexpr std::size_t n = BookEntry::kSize;
        entries = inSingleProcessOrder<Dim>(std::move(entries), n, decomposition);
        for (std::size_t r = 0; r < entries.size(); r += n) {
            books.massIn += entries[r + 2], books.heatIn += entries[r + 3];
            books.massOut += entries[r + 4], books.heatOut += entries[r + 5];
        }
        books.dropped += std::uint64_t(decomposition ? decomposition->sum(dropped) : dropped);
    }

    /// The ids of the buffer particles that replace `replaced` (this process's, in its storage
    /// order): nextId on, in a single process's order of every process's replaced particles.
    std::vector<std::int64_t> newIds(const Storage<Dim>& s, const std::vector<Size>& replaced,
                                     std::int64_t nextId,
                                     const IDecomposition<Dim>* decomposition) {
        const auto key = s.template getValue<int>(QuantityId::ORDER_KEY);
        const auto id = s.template getValue<int>(QuantityId::PARTICLE_ID);
        std::vector<double> mine;
        for (Size i : replaced) mine.insert(mine.end(), {double(key[i]), double(id[i])});
        const std::vector<double> all = inSingleProcessOrder<Dim>(mine, 2, decomposition);
        std::vector<std::int64_t> ids;
        std::size_t r = 0;  // this process's records come in the same order as in `all`
        for (std::size_t k = 0; k < mine.size(); k += 2) {
            while (all[r] != mine[k] || all[r + 1] != mine[k + 1]) r += 2;
            ids.push_back(nextId + std::int64_t(r / 2));
        }
        books.created += all.size() / 2;
        return ids;
    }

    /// Every process's new buffer particles (from `first` on) on every process, by id: last in
    /// the particle order, as a single process holds them, and held alike (OWNER -1: the
    /// decomposition gives each to the process whose box it is in).
    static void shareNew(Storage<Dim>& s, Size first, const IDecomposition<Dim>& decomposition) {
        decomposition.shareAdded(s, first);
        const auto id = s.template getValue<int>(QuantityId::PARTICLE_ID);
        std::vector<Size> order(s.size());
        std::iota(order.begin(), order.end(), Size(0));
        std::sort(order.begin() + first, order.end(),
                  [&](Size a, Size b) { return id[a] < id[b]; });
        s.gather(order);
        auto owner = s.template getValue<int>(QuantityId::OWNER);
        std::fill(owner.begin() + first, owner.end(), -1);
    }

    /// The copies from `first` on, of inlet particles that crossed: back into the buffer, with
    /// the given ids.
    void refill(Storage<Dim>& s, Size first, Float t, const std::vector<std::int64_t>& ids) {
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        const auto x = s.template getValue<Vec>(QuantityId::POSITION);
        const auto id = s.template getValue<int>(QuantityId::PARTICLE_ID);
        const auto key = s.template getValue<int>(QuantityId::ORDER_KEY);
        for (Size i = first; i < s.size(); ++i) {
            const FlowSide<Dim>& side = sides[sideOf(x[i], ParticleKind::INLET)];
            kind[i] = int(ParticleKind::INLET);
            x[i] += side.outward() * side.depth;
            id[i] = int(ids[i - first]), key[i] = kNewParticleKey;
            setBuffer(s, i, t);
        }
    }

    /// A buffer particle's imposed values at time t: an inlet's velocity and temperature; no
    /// heat exchange, and no temperature rate left from its last evaluation as fluid.
    void setBuffer(Storage<Dim>& s, Size i, Float t) const {
        const auto x = s.template getValue<Vec>(QuantityId::POSITION);
        if (s.template getValue<int>(QuantityId::KIND)[i] == int(ParticleKind::INLET)) {
            const FlowSide<Dim>& side = sides[sideOf(x[i], ParticleKind::INLET)];
            s.template getDt<Vec>(QuantityId::POSITION)[i] = side.velocity(x[i], t);
            if (side.temperature && s.has(QuantityId::TEMPERATURE))
                s.template getValue<Float>(QuantityId::TEMPERATURE)[i] = side.temperature(x[i], t);
        }
        if (s.has(heat_ids::THERMAL_CONDITION))
            s.template getValue<int>(heat_ids::THERMAL_CONDITION)[i] =
                int(ThermalCondition::ADIABATIC);
        if (s.has(QuantityId::TEMPERATURE) && s.order(QuantityId::TEMPERATURE) >= OrderEnum::FIRST)
            s.template getDt<Float>(QuantityId::TEMPERATURE)[i] = 0;  // as booked, from now on
    }
    static void becomeFluid(Storage<Dim>& s, Size i) {
        s.template getValue<int>(QuantityId::KIND)[i] = int(ParticleKind::FLUID);
        if (s.has(heat_ids::THERMAL_CONDITION))
            s.template getValue<int>(heat_ids::THERMAL_CONDITION)[i] =
                int(ThermalCondition::CONDUCTING);
    }
    static Float massOf(const Storage<Dim>& s, Size i) {
        return s.template getValue<Float>(QuantityId::MASS)[i];
    }
    /// m c T of particle i (T in degC; 0 without temperatures or heat capacities).
    static std::function<Float(Size)> heatContent(const Storage<Dim>& s) {
        if (!s.has(QuantityId::TEMPERATURE) || s.materials().empty())
            return [](Size) { return 0.0; };
        std::vector<Float> c;
        for (const auto& material : s.materials())
            c.push_back(material->params().template get<double>("heat_capacity"));
        const auto m = s.template getValue<Float>(QuantityId::MASS);
        const auto T = s.template getValue<Float>(QuantityId::TEMPERATURE);
        const bool has = s.has(QuantityId::MATERIAL);
        const auto mat =
            has ? s.template getValue<int>(QuantityId::MATERIAL) : ArrayView<const int>();
        return [=](Size i) { return m[i] * c[has ? mat[i] : 0] * T[i]; };
    }
};

/// The outlets' pressure and velocity, each evaluation, after the wall condition: an outlet
/// particle's pressure is its side's p_out(x, t) and its density rho(p_out); its velocity is the
/// Shepard mean of its fluid and outlet neighbours' velocities (v_o = sum_j v_j W_oj / sum_j
/// W_oj), or stays as it is without such a neighbour.
template <int Dim>
class OutletCondition : public IEquationTerm<Dim> {
  public:
    using Vec = Vector<Dim>;
    OutletCondition(std::shared_ptr<const FlowBoundaries<Dim>> flow,
                    std::shared_ptr<const NeighbourGather<Dim>> gather, EquationOfState eos)
        : flow_(std::move(flow)), gather_(std::move(gather)), eos_(eos) {}

    void setDerivatives(DerivativeHolder<Dim>&, const RunSettings&) override {}
    void initialize(IScheduler& scheduler, Storage<Dim>& s, Float t) override {
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        const auto x = s.template getValue<Vec>(QuantityId::POSITION);
        auto v = s.template getDt<Vec>(QuantityId::POSITION);
        auto p = s.template getValue<Float>(QuantityId::PRESSURE);
        auto rho = s.template getValue<Float>(QuantityId::DENSITY);
        outlets_.clear();
        for (Size i = 0; i < s.size(); ++i)
            if (kind[i] == int(ParticleKind::OUTLET)) outlets_.push_back(i);
        mean_.assign(outlets_.size(), Vec{});
        const auto seen = [&](Size j) {
            return isFluid(kind[j]) || kind[j] == int(ParticleKind::OUTLET);
        };
        // outlets_ is in increasing order: an outlet particle's slot by bisection.
        const auto slot = [&](Size o) {
            return std::lower_bound(outlets_.begin(), outlets_.end(), o) - outlets_.begin();
        };
        gather_->forEachWhere(scheduler, outlets_, seen, [&](Size o, auto&& visit) {
            Vec sum{};
            Float weight = 0;
            visit([&](Size j, const Vec&, Float, Float W) {
                if (j != o) sum += v[j] * W, weight += W;
            });
            const FlowSide<Dim>& side = flow_->sides[flow_->sideOf(x[o], ParticleKind::OUTLET)];
            p[o] = side.pressure(x[o], t), rho[o] = eos_.density(p[o]);
            mean_[slot(o)] = weight > 0 ? sum / weight : v[o];
        });
        for (std::size_t k = 0; k < outlets_.size(); ++k) v[outlets_[k]] = mean_[k];
    }
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}
    TermAccess access() const override {
        return {.reads = {QuantityId::PRESSURE, QuantityId::DENSITY},
                .prepares = {QuantityId::PRESSURE, QuantityId::DENSITY}};
    }
    void create(Storage<Dim>&, IMaterial&) const override {}

  private:
    std::shared_ptr<const FlowBoundaries<Dim>> flow_;
    std::shared_ptr<const NeighbourGather<Dim>> gather_;
    EquationOfState eos_;
    std::vector<Size> outlets_;
    std::vector<Vec> mean_;
};

}  // namespace num::sph
