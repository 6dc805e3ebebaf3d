// Two-way coupling of moving rigid bodies with the fluid.
//
// Each evaluation (finalize, in the last pass) sums the fluid's force on every particle j of a
// moving body, F_j = -sum_{fluid i} m_i a_ij (sph/formulas/boundary_force.hpp), and from them
// each body's force and torque about its reference point X:
//   F_b = sum_{j in b} F_j,   tau_b = sum_{j in b} (x_j - X) x F_j
// in storage order, on one thread, so the sums are the same for any number of threads. On
// several processes each sums the particles it owns, and every process adds all of them in the
// order of a single process's storage (ORDER_KEY, then PARTICLE_ID: sph/particle_order.hpp), so
// that every process integrates the same bodies, bitwise those of one process.
// Once per step (postStep, before containment) each body advances by its motion
// (rigid_body.hpp) and its particles follow rigidly: x_j = X + R r_j and
// v_j = V + omega x (R r_j), the velocity the wall condition (Adami et al. 2012, eq. 22-23)
// and the continuity equation see (WALL_VELOCITY and the particles' velocity). The force lags
// the body by one step (a staggered, explicit coupling, as in DualSPHysics' floating bodies,
// Dominguez et al. 2022, sec. 3.4).
// Contacts: a particle j of a free body closer than the spacing dx to a particle k of another
// solid (a wall, the box's walls, another body not hinged to it) is pushed back by a damped spring
// and held by Coulomb friction (a linear spring-dashpot, Cundall & Strack 1979;
// sph/formulas/contact_law.hpp):
//   F_n = max(0, k_n (dx - r) - c_n (v_jk . n)),  n = (x_j - x_k) / r,  v_jk = v_j - v_k,
//   F_jk = F_n n - min(mu F_n, c_n |v_t|) v_t / |v_t|,  v_t = v_jk - (v_jk . n) n,
//   k_n = m (c0 / dx)^2, c_n = sqrt(k_n m) (damping ratio 1/2), m = M / N the body's mass over
//   its particle count, so that the body on n contacts rings at sqrt(n / N) c0 / dx, within
//   what a step of dt ~ 0.3 dx / c0 integrates; mu the body's friction coefficient. On the
//   body, F and its torque, as the fluid's.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "sph/bodies/body_frame.hpp"
#include "sph/bodies/moving_bodies.hpp"
#include "sph/decomposition.hpp"
#include "sph/equation_term.hpp"
#include "sph/formulas/boundary_force.hpp"
#include "sph/formulas/contact_law.hpp"
#include "sph/setup/fluid_geometry.hpp"

namespace num::sph {

/// The contact law of a body's particles (the file comment; none for a body that is not free):
/// particles, the body's count of them; c0 the sound speed, dx the spacing.
template <int Dim>
ContactLaw<Dim> bodyContactLaw(const MovingBody<Dim>& owner, std::size_t particles, Float c0,
                               Float dx) {
    if (owner.motion.type != MotionType::FREE) return {};
    const Float m = owner.motion.mass / Float(particles);
    const Float kn = m * (c0 / dx) * (c0 / dx);
    return {kn, std::sqrt(kn * m), owner.motion.friction, dx};
}

/// Adds a particle's loads to its body's (the file comment): the fluid's force F_j and the
/// contacts' C_j at the arm x_j - X, F_b += F_j, tau_b += (x_j - X) x F_j (the same for C_j).
template <int Dim>
void addParticleLoads(MovingBody<Dim>& b, const Vector<Dim>& arm, const Vector<Dim>& force,
                      const Vector<Dim>& contact) {
    b.fluidForce += force;
    b.fluidTorque += cross(arm, force);
    b.contactForce += contact;
    b.contactTorque += cross(arm, contact);
}

template <int Dim>
void clearLoads(MovingBodies<Dim>& bodies) {
    for (MovingBody<Dim>& b : bodies.bodies)
        b.fluidForce = b.contactForce = Vector<Dim>{}, b.fluidTorque = b.contactTorque = {};
}

template <int Dim>
class RigidBodyCoupling : public IEquationTerm<Dim> {
  public:
    using Vec = Vector<Dim>;

    /// shapes: the bodies at t = 0 (which particles are whose); gravity: g(t); alpha, c0: the
    /// artificial viscosity's.
    /// dx: the particle spacing.
    RigidBodyCoupling(std::shared_ptr<MovingBodies<Dim>> bodies, std::vector<SolidBody<Dim>> shapes,
                      std::function<Vec(Float)> gravity, Float alpha, Float c0, Float dx)
        : bodies_(std::move(bodies)),
          shapes_(std::move(shapes)),
          gravity_(std::move(gravity)),
          alpha_(alpha),
          c0_(c0),
          dx_(dx) {}

    void setDerivatives(DerivativeHolder<Dim>&, const RunSettings& settings) override {
        kernel_.emplace(settings);
    }
    void beginEvaluation(const EvaluationContext<Dim>& context) override {
        lists_ = &context.neighbours;
        decomposition_ = context.decomposition;
    }
    void initialize(IScheduler&, Storage<Dim>&, Float) override {}
    void finalize(IScheduler& scheduler, Storage<Dim>& s, Float) override {
        sumParticleForces(scheduler, s);
        sumBodyLoads(s);
    }
    void postStep(IScheduler& scheduler, Storage<Dim>& s, Float t, Float dt) override {
        bodies_->advance(gravity_ ? gravity_(t) : Vec{}, t, dt);
        placeParticles(scheduler, s);
    }
    void create(Storage<Dim>& s, IMaterial&) const override;
    /// The last pass: the wall condition has set the body particles' pressure and velocity.
    TermAccess access() const override { return {.placement = PassPlacement::LAST}; }
    std::string name() const override { return "rigid body coupling"; }

    /// Puts every moving body's particles where its state says, with its velocity.
    void placeParticles(IScheduler& scheduler, Storage<Dim>& s) const;

  private:
    void sumParticleForces(IScheduler& scheduler, const Storage<Dim>& s);
    /// The contact law of body b's particles (none for a prescribed body).
    ContactLaw<Dim> contactLaw(int b) const;
    /// Each body's number of particles over every process (they keep their particles for the
    /// whole run).
    void countParticles(const Storage<Dim>& s) {
        if (!particleCount_.empty()) return;
        particleCount_.assign(bodies_->bodies.size(), 0);
        const auto body = s.template getValue<int>(QuantityId::BODY_INDEX);
        for (Size j = 0; j < s.size(); ++j)
            if (body[j] >= 0 && owns(j)) ++particleCount_[std::size_t(body[j])];
        if (decomposition_)
            for (std::size_t& n : particleCount_)
                n = std::size_t(decomposition_->sum(std::int64_t(n)));
    }
    /// Whether this process owns particle j (a halo copy's owner sums it).
    bool owns(Size j) const { return !decomposition_ || decomposition_->owned()[j]; }
    void sumBodyLoads(const Storage<Dim>& s);
    /// The moving particles' loads, one record each: order key, id, body, the arm x_j - X,
    /// the fluid's force, the contacts' force; every process's, in a single process's storage
    /// order.
    std::vector<double> loadRecords(const Storage<Dim>& s) const;
    static constexpr std::size_t kRecord = 3 + 3 * Dim;

    std::shared_ptr<MovingBodies<Dim>> bodies_;
    std::vector<SolidBody<Dim>> shapes_;
    std::function<Vec(Float)> gravity_;
    Float alpha_, c0_, dx_;
    std::optional<RunKernel<Dim>> kernel_;
    const VerletList<Dim>* lists_ = nullptr;
    const IDecomposition<Dim>* decomposition_ = nullptr;  ///< null on one process
    std::vector<Vec> particleForce_, particleContact_;
    std::vector<std::size_t> particleCount_;
    std::vector<Size> movingParticles_;  ///< of the evaluation
};

/// BODY_INDEX and BODY_OFFSET from the particles' places at t = 0 (a storage that has them, a
/// checkpoint's, keeps its own), and WALL_VELOCITY where it is missing.
template <int Dim>
void RigidBodyCoupling<Dim>::create(Storage<Dim>& s, IMaterial&) const {
    if (!s.has(QuantityId::WALL_VELOCITY))
        s.template insert<Vec>(QuantityId::WALL_VELOCITY, OrderEnum::ZERO, Vec{});
    if (s.has(QuantityId::BODY_INDEX)) return;
    s.template insert<int>(QuantityId::BODY_INDEX, OrderEnum::ZERO, -1);
    s.template insert<Vec>(QuantityId::BODY_OFFSET, OrderEnum::ZERO, Vec{});
    const auto x = s.template getValue<Vec>(QuantityId::POSITION);
    const auto kind = s.template getValue<int>(QuantityId::KIND);
    auto body = s.template getValue<int>(QuantityId::BODY_INDEX);
    auto offset = s.template getValue<Vec>(QuantityId::BODY_OFFSET);
    for (Size i = 0; i < s.size(); ++i) {
        if (kind[i] != int(ParticleKind::BODY)) continue;
        for (std::size_t b = 0; b < shapes_.size(); ++b)
            if (shapes_[b].signedDistance(x[i]) < 0) {
                body[i] = int(b);
                offset[i] = x[i] - bodies_->bodies[b].initialPosition;
                break;
            }
    }
}

template <int Dim>
void RigidBodyCoupling<Dim>::sumParticleForces(IScheduler& scheduler, const Storage<Dim>& s) {
    const auto kind = s.template getValue<int>(QuantityId::KIND);
    const auto body = s.template getValue<int>(QuantityId::BODY_INDEX);
    const auto v = s.template getDt<Vec>(QuantityId::POSITION);
    const formulas::BoundaryPairForce<Dim> pair(s, *kernel_, alpha_, c0_);
    particleForce_.assign(s.size(), Vec{});
    particleContact_.assign(s.size(), Vec{});
    countParticles(s);
    movingParticles_.clear();  // in increasing index: the threads share them evenly
    for (Size j = 0; j < s.size(); ++j)
        if (bodies_->moves(body[j]) && owns(j)) movingParticles_.push_back(j);
    // One pass over each moving particle's neighbours: the fluid's force, and for a free
    // body the contacts with other solids, each summed in increasing neighbour index.
    withKernel<Dim>(kernel_->type, [&](auto kernel) {
        const Float h = kernel_->h;
        scheduler.parallelFor(Size(movingParticles_.size()), 256, [&](Size b, Size e) {
            for (Size n = b; n < e; ++n) {
                const Size j = movingParticles_[n];
                const ContactLaw<Dim> law = contactLaw(body[j]);
                const bool contacts = law.kn > 0;
                const auto keep = [&](Size k) {
                    return isFluid(kind[k]) || (contacts && body[k] != body[j] &&
                                                !bodies_->hingedTogether(body[j], body[k]));
                };
                lists_->forEachNeighbourOf(j, keep, [&](Size k, const Vec& dx, Float r2) {
                    if (!(r2 > 0)) return;
                    if (!isFluid(kind[k])) {
                        particleContact_[j] += law.force(dx, r2, v[j] - v[k]);
                        return;
                    }
                    const Float r = std::sqrt(r2);
                    particleForce_[j] += pair.onBoundary(k, j, -dx, r, kernel.dW_dr(r, h));
                });
            }
        });
    });
}

template <int Dim>
ContactLaw<Dim> RigidBodyCoupling<Dim>::contactLaw(int b) const {
    return bodyContactLaw(bodies_->bodies[std::size_t(b)], particleCount_[std::size_t(b)], c0_,
                          dx_);
}

template <int Dim>
std::vector<double> RigidBodyCoupling<Dim>::loadRecords(const Storage<Dim>& s) const {
    const auto x = s.template getValue<Vec>(QuantityId::POSITION);
    const auto body = s.template getValue<int>(QuantityId::BODY_INDEX);
    // One process: the storage's order is the order, no keys needed.
    const auto key =
        decomposition_ ? s.template getValue<int>(QuantityId::ORDER_KEY) : ArrayView<const int>();
    const auto id =
        decomposition_ ? s.template getValue<int>(QuantityId::PARTICLE_ID) : ArrayView<const int>();
    std::vector<double> records;
    records.reserve(movingParticles_.size() * kRecord);
    for (const Size j : movingParticles_) {
        records.push_back(decomposition_ ? key[j] : 0);
        records.push_back(decomposition_ ? id[j] : 0);
        records.push_back(body[j]);
        for (const Vec& v : {x[j] - bodies_->bodies[body[j]].state.position, particleForce_[j],
                             particleContact_[j]})
            for (int k = 0; k < Dim; ++k) records.push_back(v[k]);
    }
    return inSingleProcessOrder<Dim>(std::move(records), kRecord, decomposition_);
}

template <int Dim>
void RigidBodyCoupling<Dim>::sumBodyLoads(const Storage<Dim>& s) {
    clearLoads(*bodies_);
    const std::vector<double> records = loadRecords(s);
    for (std::size_t r = 0; r < records.size(); r += kRecord) {
        MovingBody<Dim>& b = bodies_->bodies[std::size_t(records[r + 2])];
        Vec arm, force, contact;
        for (int k = 0; k < Dim; ++k)
            arm[k] = records[r + 3 + k], force[k] = records[r + 3 + Dim + k],
            contact[k] = records[r + 3 + 2 * Dim + k];
        addParticleLoads(b, arm, force, contact);
    }
}

template <int Dim>
void RigidBodyCoupling<Dim>::placeParticles(IScheduler& scheduler, Storage<Dim>& s) const {
    auto x = s.template getValue<Vec>(QuantityId::POSITION);
    auto v = s.template getDt<Vec>(QuantityId::POSITION);
    auto wall = s.template getValue<Vec>(QuantityId::WALL_VELOCITY);
    const auto body = s.template getValue<int>(QuantityId::BODY_INDEX);
    const auto offset = s.template getValue<Vec>(QuantityId::BODY_OFFSET);
    std::vector<BodyFrame<Dim>> frames;
    for (const MovingBody<Dim>& b : bodies_->bodies)
        frames.push_back(BodyFrame<Dim>::of(b.state, b.initialPosition));
    scheduler.parallelFor(s.size(), 4096, [&](Size b, Size e) {
        for (Size j = b; j < e; ++j) {
            if (!bodies_->moves(body[j])) continue;
            placeBodyParticle<Dim>(frames[std::size_t(body[j])], offset[j], x[j], v[j]);
            wall[j] = v[j];
        }
    });
}

}  // namespace num::sph
