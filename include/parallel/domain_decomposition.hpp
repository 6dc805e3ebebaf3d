// Domain decomposition over the processes of a run (parallel/communicator.hpp).
//
// Ownership: each process has a box (parallel/subdomains.hpp: recursive coordinate bisection of
// the fluid particles, whose pair sums are most of the work); a particle belongs to the process
// whose box holds it. The boxes follow the fluid: they are recomputed when the most loaded
// process holds more than 10 % above the mean.
//
// Halos: a process holds, besides its own particles, a copy of every other particle within the
// halo radius (the kernel's support radius times 1 + kHaloSkin) of its box, sent by the owner.
// While no particle has moved more than half the skin since, every neighbour of an owned
// particle is among them (triangle inequality). Copies are refreshed from their owners where the
// solver asks (sph/decomposition.hpp); particles migrate to their new owners and the halos are
// rebuilt before a step once a particle moved a quarter of the skin, or particles were added,
// removed or reordered. A displacement beyond half the skin (a step longer than the skin can
// cover) stops the run: neighbours could have been missed.
//
// Identity with one process: every storage is kept in the order of sph/particle_order.hpp, a
// per-particle key, so each owned particle sees its neighbours in the single-process order and
// its sums are bitwise the same; the reductions (time step, counts) are exact.
#pragma once

#include <algorithm>
#include <array>
#include <cstring>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "parallel/particle_records.hpp"
#include "parallel/subdomains.hpp"
#include "sph/decomposition.hpp"
#include "sph/particle_order.hpp"

namespace num::parallel {

template <int Dim>
class DomainDecomposition final : public sph::IDecomposition<Dim> {
  public:
    using Vec = sph::Vector<Dim>;
    using Size = sph::Size;
    /// The halo's width beyond the support radius, as a fraction of it.
    static constexpr double kHaloSkin = 0.4;
    /// Boxes are recomputed when the most loaded process exceeds the mean by this fraction.
    static constexpr double kImbalanceLimit = 0.10;

    DomainDecomposition(const Communicator& comm, const Domain<Dim>& domain, double radius)
        : comm_(comm),
          domain_(domain),
          radius_(radius),
          haloRadius_(radius * (1 + kHaloSkin)),
          boxes_(domain) {}

    /// Keeps this process's share of `all`, which every process holds alike (the initial state
    /// or a checkpoint), and its halo. The particles' OWNER is added where missing.
    void distribute(sph::Storage<Dim>& all) {
        if (!all.has(sph::QuantityId::OWNER))
            all.template insert<int>(sph::QuantityId::OWNER, sph::OrderEnum::ZERO, -1);
        partition(loadPoints(all));
        if (comm_.size() == 1) {  // every particle stays and there is no halo: nothing to copy
            ownEveryParticle(all);
            sph::sortByOrderKey(all);
            return;
        }
        const auto x = all.template getValue<Vec>(sph::QuantityId::POSITION);
        auto owner = all.template getValue<int>(sph::QuantityId::OWNER);
        std::vector<Size> mine;
        for (Size i = 0; i < all.size(); ++i)
            if (boxOwner(domain_.wrap(x[i])) == comm_.rank()) mine.push_back(i);
        for (Size i : mine) owner[i] = comm_.rank();
        all.gather(mine);
        sph::sortByOrderKey(all);
        buildHalo(all);
    }

    /// Every process's own particles on the root, in the single-process order (OWNER set to 0,
    /// as one process has it); an empty storage elsewhere. Particles not yet assigned (added
    /// since the last step, alike on every process) are taken from the root.
    sph::Storage<Dim> gatherToRoot(const sph::Storage<Dim>& s) const {
        const auto owner = s.template getValue<int>(sph::QuantityId::OWNER);
        std::vector<Size> mine;
        for (Size i = 0; i < s.size(); ++i)
            if (owner[i] == comm_.rank() || (owner[i] < 0 && comm_.isRoot())) mine.push_back(i);
        Bytes packed;
        packParticles(s, mine, packed);
        const std::vector<Bytes> all = comm_.gatherToRoot(packed);
        sph::Storage<Dim> out = s.emptyCopy();
        if (!comm_.isRoot()) return out;
        for (const Bytes& b : all) appendParticles(out, b);
        auto o = out.template getValue<int>(sph::QuantityId::OWNER);
        std::fill(o.begin(), o.end(), 0);
        sph::sortByOrderKey(out);
        return out;
    }

    /// Gives each halo copy its owner's values. Owner and receiver both keep a record of what was
    /// last sent, block by block (a quantity's value, dt or d2t for the particles sent to one
    /// process); only the blocks that changed travel, and the receiver rewrites the others from
    /// its record (its own work may have changed its copies): constants such as masses, kinds,
    /// normals and ids travel with the halo's build alone.
    void exchangeHalo(sph::Storage<Dim>& s, QuantityIds only = {}) override;

    std::span<const char> owned() const override { return owned_; }

    void combine(sph::TimeStepLimits& limits) const override {
        if (comm_.size() == 1) return;
        const double dt = limits.dt();
        const std::string& name = limits.criterion();
        Bytes mine(sizeof dt + name.size());
        std::memcpy(mine.data(), &dt, sizeof dt);
        std::copy(name.begin(), name.end(), mine.begin() + sizeof dt);
        sph::TimeStepLimits all(limits.scheduler());
        for (const Bytes& b : comm_.allGather(mine)) {
            double v;
            std::memcpy(&v, b.data(), sizeof v);
            all.offer(std::string(b.begin() + sizeof v, b.end()), v);
        }
        limits = all;
    }

    std::int64_t sum(std::int64_t local) const override { return comm_.sum(local); }

    void shareAdded(sph::Storage<Dim>& s, Size first) const override {
        std::vector<Size> mine(s.size() - first);
        std::iota(mine.begin(), mine.end(), first);
        Bytes packed;
        packParticles(s, mine, packed);
        std::vector<Size> before(first);
        std::iota(before.begin(), before.end(), Size(0));
        s.gather(before);
        for (const Bytes& b : comm_.allGather(packed)) appendParticles(s, b);
    }

    std::vector<std::vector<double>> allGather(std::span<const double> local) const override {
        Bytes mine(local.size_bytes());
        std::memcpy(mine.data(), local.data(), mine.size());
        std::vector<std::vector<double>> all;
        for (const Bytes& b : comm_.allGather(mine)) {
            all.emplace_back(b.size() / sizeof(double));
            std::memcpy(all.back().data(), b.data(), b.size());
        }
        return all;
    }

    bool beforeStep(sph::Storage<Dim>& s, bool reorder, bool particlesChanged) override {
        if (comm_.size() == 1) {
            ownEveryParticle(s);
            if (reorder) sph::reorderByKey(s, domain_, radius_);
            return reorder;
        }
        if (comm_.any(tooFar_))
            throw std::logic_error(
                "domain decomposition: a particle moved more than half the halo skin within one "
                "step, so neighbours across processes may have been missed; lower time.cfl");
        bool changed = false;
        // Particles only added (emitters): each process keeps its own and its halo's, in place.
        if (particlesChanged && !comm_.any(!onlyAdded(s))) {
            adoptAdded(s);
            particlesChanged = false, changed = true;
        }
        double moved = 0;
        if (!particlesChanged) moved = comm_.maximum(maxDisplacement(s));
        if (!reorder && !particlesChanged && moved <= 0.25 * (haloRadius_ - radius_))
            return changed;
        if (reorder) {
            const sph::OrderGrid<Dim> grid(domain_, radius_);
            const auto x = s.template getValue<Vec>(sph::QuantityId::POSITION);
            auto key = s.template getValue<int>(sph::QuantityId::ORDER_KEY);
            for (Size i = 0; i < s.size(); ++i) key[i] = grid.key(x[i]);
        }
        redistribute(s);
        return true;
    }

    /// The most loaded process's fluid particles over the mean, less one (0: perfect balance),
    /// at the last redistribution.
    double imbalance() const { return imbalance_; }
    /// How often the boxes were recomputed.
    std::size_t repartitions() const { return repartitions_; }
    /// Bytes received in halo exchanges by this process, and the number of exchanges.
    std::uint64_t haloBytes() const { return haloBytes_; }
    std::uint64_t exchanges() const { return exchanges_; }
    /// Halo copies this process holds now.
    Size haloParticles() const { return Size(std::count(owned_.begin(), owned_.end(), 0)); }
    double haloRadius() const { return haloRadius_; }

  private:
    /// One process: it owns every particle and holds no halo.
    void ownEveryParticle(sph::Storage<Dim>& s) {
        auto owner = s.template getValue<int>(sph::QuantityId::OWNER);
        std::fill(owner.begin(), owner.end(), 0);
        owned_.assign(s.size(), 1);
    }
    /// The process whose box holds x (wrapped on periodic axes); this one for a position no box
    /// holds (not finite: the health check reports it).
    int boxOwner(const Vec& x) const {
        const int r = boxes_.owner(x);
        return r >= 0 ? r : comm_.rank();
    }
    /// Whether x lies within the halo radius of process r's box.
    bool nearBox(const Vec& x, int r) const { return boxes_.distance(x, r) < haloRadius_; }
    void partition(std::vector<Vec> points) {
        boxes_.bisect(std::move(points), comm_.size());
        ++repartitions_;
    }

    /// Drops the halo, assigns particles added since (every process holds them alike), moves
    /// particles to the owners of the boxes they are in (recomputed first if the load is
    /// unbalanced), sorts and rebuilds the halo.
    void redistribute(sph::Storage<Dim>& s) {
        const int me = comm_.rank();
        {
            const auto x = s.template getValue<Vec>(sph::QuantityId::POSITION);
            const auto owner = s.template getValue<int>(sph::QuantityId::OWNER);
            std::vector<Size> keep;
            for (Size i = 0; i < s.size(); ++i)
                if (owner[i] == me || (owner[i] < 0 && boxOwner(domain_.wrap(x[i])) == me))
                    keep.push_back(i);
            s.gather(keep);
        }
        if (measureImbalance(s) > kImbalanceLimit) {
            const std::vector<Vec> mine = loadPoints(s);
            Bytes bytes(mine.size() * sizeof(Vec));
            std::memcpy(bytes.data(), static_cast<const void*>(mine.data()), bytes.size());
            std::vector<Vec> points;
            for (const Bytes& b : comm_.allGather(bytes)) {
                const std::size_t at = points.size();
                points.resize(at + b.size() / sizeof(Vec));
                std::memcpy(static_cast<void*>(points.data() + at), b.data(), b.size());
            }
            partition(std::move(points));
        }
        // Migration to the owners of the boxes.
        std::vector<std::vector<Size>> leaving(comm_.size());
        std::vector<Size> staying;
        {
            const auto x = s.template getValue<Vec>(sph::QuantityId::POSITION);
            for (Size i = 0; i < s.size(); ++i) {
                const int r = boxOwner(domain_.wrap(x[i]));
                (r == me ? staying : leaving[r]).push_back(i);
            }
        }
        std::vector<Bytes> out(comm_.size());
        for (int r = 0; r < comm_.size(); ++r) packParticles(s, leaving[r], out[r]);
        const std::vector<Bytes> in = comm_.exchange(out);
        s.gather(staying);
        for (const Bytes& b : in) appendParticles(s, b);
        auto owner = s.template getValue<int>(sph::QuantityId::OWNER);
        std::fill(owner.begin(), owner.end(), me);
        sph::sortByOrderKey(s);
        measureImbalance(s);  // its own particles only: before the halo joins
        buildHalo(s);
    }

    /// Whether a particle is part of the load the boxes balance: the fluid particles, whose
    /// pair sums are most of a step's work (a wall particle only mirrors its fluid neighbours);
    /// every particle of a storage without fluid.
    static std::vector<char> carriesLoad(const sph::Storage<Dim>& s) {
        std::vector<char> load(s.size(), 1);
        if (!s.has(sph::QuantityId::KIND)) return load;
        const auto kind = s.template getValue<int>(sph::QuantityId::KIND);
        if (std::find(kind.begin(), kind.end(), int(sph::ParticleKind::FLUID)) == kind.end())
            return load;
        for (Size i = 0; i < s.size(); ++i) load[i] = kind[i] == int(sph::ParticleKind::FLUID);
        return load;
    }
    /// The wrapped positions of the particles of s that carry the load.
    std::vector<Vec> loadPoints(const sph::Storage<Dim>& s) const {
        const auto x = s.template getValue<Vec>(sph::QuantityId::POSITION);
        const std::vector<char> load = carriesLoad(s);
        std::vector<Vec> points;
        for (Size i = 0; i < s.size(); ++i)
            if (load[i]) points.push_back(domain_.wrap(x[i]));
        return points;
    }
    /// The imbalance of the load over the processes, each holding its particles in s.
    double measureImbalance(const sph::Storage<Dim>& s) {
        const std::vector<char> load = carriesLoad(s);
        const auto mine = std::int64_t(std::count(load.begin(), load.end(), char(1)));
        const double mean = double(comm_.sum(mine)) / comm_.size();
        return imbalance_ = mean > 0 ? comm_.maximum(double(mine)) / mean - 1 : 0;
    }

    /// s holds the owned particles, sorted: sends each to the processes whose boxes are within
    /// the halo radius, appends what the others send, sorts, and records who sends what where.
    void buildHalo(sph::Storage<Dim>& s);

    /// Whether s holds the particles of the last halo build, in order, and new ones after them.
    bool onlyAdded(const sph::Storage<Dim>& s) const;

    /// The particles after the last halo build's (every process holds them alike; last in the
    /// particle order already): keeps those of its box, sent to the processes whose boxes are
    /// within the halo radius, and the copies of others' within the halo radius of its own box.
    void adoptAdded(sph::Storage<Dim>& s);

    /// Where each of `blocks` lies in a record of n particles, which holds every quantity.
    static std::vector<std::size_t> offsets(const sph::Storage<Dim>& s,
                                            const std::vector<Block>& blocks, std::size_t n);

    /// The message to process r: a flag per block of `blocks`, then the blocks whose values
    /// differ from those last sent to r (all of them while there is no record of what was
    /// sent), which become the record.
    Bytes changedBlocks(const sph::Storage<Dim>& s, int r, const std::vector<Block>& blocks,
                        QuantityIds only);

    /// The largest displacement of a particle of s since the halo was built.
    double maxDisplacement(const sph::Storage<Dim>& s) const;

    void checkDisplacement(const sph::Storage<Dim>& s);

    const Communicator& comm_;
    Domain<Dim> domain_;
    double radius_, haloRadius_;
    Subdomains<Dim> boxes_;
    std::vector<std::vector<Size>> sendTo_, receiveAt_;  // by process
    std::vector<Bytes> lastSent_;      // by process: the values its copies hold, as packed
    std::vector<Bytes> lastReceived_;  // by process: the values of the copies it sent
    std::vector<char> owned_;
    std::vector<Vec> reference_;  // positions when the halo was built
    std::vector<int> ids_;        // the particles' ids then
    bool tooFar_ = false;
    double imbalance_ = 0;
    std::size_t repartitions_ = 0;
    std::uint64_t haloBytes_ = 0, exchanges_ = 0;
};

}  // namespace num::parallel

#include "parallel/domain_decomposition_halo.hpp"  // the halo's member functions
