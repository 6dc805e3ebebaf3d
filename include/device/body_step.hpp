// The moving bodies in the device step (device/fluid_step.hpp), as the CPU's RigidBodyCoupling
// (sph/bodies/body_coupling.hpp) runs them:
//   each evaluation, last: every moving particle j gathers its neighbours once, the fluid's
//     force F_j = sum_{fluid i} -m_i a_ij (formulas/boundary_pair.hpp) and, for a free body, the
//     contacts with the particles of other solids not hinged to it (formulas/contact_law.hpp),
//     written with x_j to the particle's slot (its rank among the moving particles in the
//     storage's order), so that the host sums each body's force and torque in the CPU's order;
//   each post-step phase, before the containment: the moving particles placed rigidly from
//     their bodies' frames, x = X + R r0, v = V + omega x (R r0) (sph/bodies/body_frame.hpp),
//     the wall velocity the same.
#pragma once

#include "device/body_state.hpp"
#include "device/execution.hpp"
#include "device/fluid_passes.hpp"
#include "device/fluid_state.hpp"
#include "device/neighbour_grid.hpp"
#include "sph/formulas/boundary_pair.hpp"

namespace num::device {

namespace passes {

/// The per-body data the body passes read.
template <int Dim>
struct BodyTables {
    const int *body, *slot;     // per particle: body index (-1: none), load slot (-1: not moving)
    const Vector<Dim>* offset;  // per particle: body-frame offset r0
    const sph::BodyFrame<Dim>* frames;  // per body
    const sph::ContactLaw<Dim>* laws;   // per body
    const char *moves, *hinged;         // per body; per pair of bodies
    int count;                          // bodies
    NUMERICS_HD bool hingedTogether(int a, int b) const {
        return a >= 0 && b >= 0 && hinged[a * count + b];
    }
};

/// The loads on the moving particles (the file comment), in increasing neighbour order of the
/// grid (the CPU's: of increasing index).
template <int Dim, class Kernel>
struct BodyLoadPass {
    using Vec = Vector<Dim>;
    Arrays<Dim> d;
    BodyTables<Dim> t;
    GridShape<Dim> grid;
    const Index *start, *end;
    sph::formulas::BoundaryPairTerms terms;  // laminar: set per particle (no-slip)
    Float h;
    Vec *x, *force, *contact;  // per slot
    NUMERICS_HD sph::formulas::PairSide<Dim> side(Index i) const {
        return {d.m[i], d.rho[i], d.p[i], d.nu[i], d.u[i]};
    }
    NUMERICS_HD void operator()(Index j) const {
        const int slot = t.slot[j];
        if (slot < 0) return;
        const int bj = t.body[j];
        const sph::ContactLaw<Dim> law = t.laws[bj];
        const bool contacts = law.kn > 0;
        sph::formulas::BoundaryPairTerms onJ = terms;
        onJ.laminar = d.slip[j] == noSlip;  // nu is always known (makeFluidStorage holds it)
        const sph::formulas::PairSide<Dim> sj = side(j);
        Vec f{}, c{};
        forEachNeighbour<Dim>(grid, d.x, start, end, j, [&](Index k, const Vec& dx, double r2) {
            const bool fluidk = sph::isFluid(d.kind[k]);
            if (!fluidk && !(contacts && t.body[k] != bj && !t.hingedTogether(bj, t.body[k])))
                return;
            if (!(r2 > 0)) return;
            if (!fluidk) {
                c += law.force(dx, r2, d.v[j] - d.v[k]);
                return;
            }
            const Float r = hd::sqrt(r2);
            f += sph::formulas::boundaryPairForce<Dim>(side(k), sj, onJ, -dx, r,
                                                       Kernel::dW_dr(r, h));
        });
        x[slot] = d.x[j], force[slot] = f, contact[slot] = c;
    }
};

/// The moving particles placed rigidly by their bodies' frames.
template <int Dim>
struct PlaceBodyParticles {
    Arrays<Dim> d;
    BodyTables<Dim> t;
    NUMERICS_HD void operator()(Index i) const {
        const int b = t.body[i];
        if (b < 0 || !t.moves[b]) return;
        sph::placeBodyParticle<Dim>(t.frames[b], t.offset[i], d.x[i], d.v[i]);
        if (d.wallVelocity) d.wallVelocity[i] = d.v[i];
    }
};

}  // namespace passes

/// The moving bodies' arrays in an execution's memory and their passes.
template <int Dim, class Exec>
class BodyParticles {
  public:
    using Vec = Vector<Dim>;
    explicit BodyParticles(Exec& exec)
        : exec_(exec),
          body_(exec),
          slot_(exec),
          offset_(exec),
          frames_(exec),
          laws_(exec),
          moves_(exec),
          hinged_(exec),
          x_(exec),
          force_(exec),
          contact_(exec) {}

    /// The particles' bodies, offsets and load slots (none: no body moves).
    void upload(const ParticleArrays<Dim>& p) {
        moving_ = 0;
        if (p.bodySlot.empty()) return;
        body_.upload(p.body), offset_.upload(p.bodyOffset), slot_.upload(p.bodySlot);
        for (const int s : p.bodySlot) moving_ = s >= moving_ ? s + 1 : moving_;
        for (auto* b : {&x_, &force_, &contact_}) b->resize(std::size_t(moving_));
    }
    void set(const DeviceBodies<Dim>& b) {
        frames_.upload(b.frames), laws_.upload(b.laws), moves_.upload(b.moves);
        hinged_.upload(b.hinged), count_ = int(b.frames.size());
    }
    bool any() const { return moving_ > 0; }
    /// Sorts the per-particle arrays with the step's permute(buffer, temp).
    template <class Permute, class Ints, class Vecs>
    void permute(Permute&& permute, Ints& tempInt, Vecs& tempVec) {
        if (!any()) return;
        permute(body_, tempInt), permute(slot_, tempInt), permute(offset_, tempVec);
    }
    template <class Kernel>
    void sumLoads(const passes::Arrays<Dim>& d, const GridShape<Dim>& grid, const Index* start,
                  const Index* end, const sph::formulas::BoundaryPairTerms& terms, Float h,
                  Index n) {
        if (!any()) return;
        exec_.forEach(
            n, passes::BodyLoadPass<Dim, Kernel>{d, tables(), grid, start, end, terms, h, x_.data(),
                                                 force_.data(), contact_.data()});
    }
    void place(const passes::Arrays<Dim>& d, Index n) {
        if (any()) exec_.forEach(n, passes::PlaceBodyParticles<Dim>{d, tables()});
    }
    void loads(BodyLoads<Dim>& out) const {
        x_.download(out.x), force_.download(out.force), contact_.download(out.contact);
    }
    const sph::BodyFrame<Dim>* frames() const { return any() ? frames_.data() : nullptr; }
    std::size_t bytes() const {
        return body_.bytes() + slot_.bytes() + offset_.bytes() + frames_.bytes() + laws_.bytes() +
               moves_.bytes() + hinged_.bytes() + x_.bytes() + force_.bytes() + contact_.bytes();
    }

  private:
    passes::BodyTables<Dim> tables() const {
        return {body_.data(), slot_.data(),  offset_.data(), frames_.data(),
                laws_.data(), moves_.data(), hinged_.data(), count_};
    }

    Exec& exec_;
    Buffer<int, Exec> body_, slot_;
    Buffer<Vec, Exec> offset_;
    Buffer<sph::BodyFrame<Dim>, Exec> frames_;
    Buffer<sph::ContactLaw<Dim>, Exec> laws_;
    Buffer<char, Exec> moves_, hinged_;
    Buffer<Vec, Exec> x_, force_, contact_;  // per load slot
    int moving_ = 0, count_ = 0;             // moving particles, bodies
};

}  // namespace num::device
