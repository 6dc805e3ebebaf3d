// The host side of the moving bodies on the device (plain C++; device/fluid_run.hpp's DeviceRun):
// the run's sph::MovingBodies, shared with the outputs and checkpoints, advanced on the host as
// the CPU's RigidBodyCoupling advances them (sph/bodies/body_coupling.hpp), from the loads the
// device step leaves on the moving particles (device/body_step.hpp), summed here in the
// storage's order as the CPU sums them; the bodies' frames sent back for the particles' placing
// and the containment.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "device/fluid_state.hpp"
#include "sph/bodies/body_coupling.hpp"
#include "sph/storage.hpp"

namespace num::device {

template <int Dim>
class DeviceBodyRun {
  public:
    using Vec = Vector<Dim>;
    DeviceBodyRun(std::shared_ptr<sph::MovingBodies<Dim>> bodies, std::function<Vec(Float)> gravity,
                  Float c0, Float dx)
        : bodies_(std::move(bodies)), gravity_(std::move(gravity)), c0_(c0), dx_(dx) {}

    /// The particles' bodies, offsets and load slots (the moving particles in the storage's
    /// order); each body's particle count at the first upload (the CPU's, for the contacts).
    void addParticles(const sph::Storage<Dim>& s, ParticleArrays<Dim>& p) {
        const auto body = s.template getValue<int>(sph::QuantityId::BODY_INDEX);
        const auto offset = s.template getValue<Vec>(sph::QuantityId::BODY_OFFSET);
        p.body.assign(body.begin(), body.end()), p.bodyOffset.assign(offset.begin(), offset.end());
        p.bodySlot.assign(p.body.size(), -1);
        slotBody_.clear();
        for (std::size_t i = 0; i < p.body.size(); ++i)
            if (bodies_->moves(p.body[i]))
                p.bodySlot[i] = int(slotBody_.size()), slotBody_.push_back(p.body[i]);
        if (!counts_.empty()) return;
        counts_.assign(bodies_->bodies.size(), 0);
        for (const int b : p.body)
            if (b >= 0) ++counts_[std::size_t(b)];
    }

    /// The bodies as the device step needs them, at their present states.
    DeviceBodies<Dim> deviceBodies() const {
        DeviceBodies<Dim> d;
        const std::size_t n = bodies_->bodies.size();
        for (std::size_t b = 0; b < n; ++b) {
            const sph::MovingBody<Dim>& m = bodies_->bodies[b];
            d.frames.push_back(sph::BodyFrame<Dim>::of(m.state, m.initialPosition));
            d.laws.push_back(sph::bodyContactLaw(m, counts_[b], c0_, dx_));
            d.moves.push_back(char(bodies_->moves(int(b))));
            for (std::size_t a = 0; a < n; ++a)
                d.hinged.push_back(char(bodies_->hingedTogether(int(b), int(a))));
        }
        return d;
    }

    /// Each body's force and torque from the loads of an evaluation (RigidBodyCoupling's
    /// sumBodyLoads: in the storage's order).
    void takeLoads(const BodyLoads<Dim>& loads) {
        sph::clearLoads(*bodies_);
        for (std::size_t k = 0; k < slotBody_.size(); ++k) {
            sph::MovingBody<Dim>& b = bodies_->bodies[std::size_t(slotBody_[k])];
            sph::addParticleLoads(b, loads.x[k] - b.state.position, loads.force[k],
                                  loads.contact[k]);
        }
    }

    /// One step of the bodies, from t - dt to t (RigidBodyCoupling::postStep, t the new time).
    void advance(Float t, Float dt) { bodies_->advance(gravity_ ? gravity_(t) : Vec{}, t, dt); }

  private:
    std::shared_ptr<sph::MovingBodies<Dim>> bodies_;
    std::function<Vec(Float)> gravity_;
    Float c0_, dx_;
    std::vector<int> slotBody_;        ///< the body of each load slot
    std::vector<std::size_t> counts_;  ///< each body's particles
};

}  // namespace num::device
