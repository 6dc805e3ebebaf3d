// A safety net that guarantees no fluid particle is ever inside a wall or a solid body. The
// wall condition's pressure normally keeps fluid away; if a particle still ends up beyond a
// wall surface (the container box side), inside a body or inside an interior wall's solid (of
// any shape: its signed distance and outward normal), it is reflected back across the surface
// and the velocity component into the solid is removed. Runs in the post-step phase
// (postStep(), once per step after the integrator and after particle shifting), so the
// velocity a step ends with has no component into the solid.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "spatial/cell_grid.hpp"
#include "sph/bodies/body_frame.hpp"
#include "sph/bodies/moving_bodies.hpp"
#include "sph/formulas/post_step.hpp"
#include "sph/setup/fluid_geometry.hpp"

namespace num::sph {

template <int Dim>
class ParticleContainment : public IEquationTerm<Dim> {
  public:
    using Vec = Vector<Dim>;
    /// moving: the bodies' motions (empty: every body fixed).
    explicit ParticleContainment(const FluidGeometry<Dim>& geometry,
                                 std::shared_ptr<const MovingBodies<Dim>> moving = nullptr)
        : geometry_(geometry), moving_(std::move(moving)) {}

    void setDerivatives(DerivativeHolder<Dim>&, const RunSettings&) override {}
    void initialize(IScheduler&, Storage<Dim>&, Float) override {}
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}
    void postStep(IScheduler& scheduler, Storage<Dim>& s, Float, Float) override {
        auto x = s.template getValue<Vec>(QuantityId::POSITION);
        auto v = s.template getDt<Vec>(QuantityId::POSITION);
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        const FluidGeometry<Dim>& g = geometry_;
        gridBodies();
        scheduler.parallelFor(s.size(), 4096, [&](Size b, Size e) {
            std::vector<int> near;
            for (Size i = b; i < e; ++i) {
                if (!isFluid(kind[i])) continue;
                for (int k = 0; k < Dim; ++k)
                    formulas::containInWalls(x[i][k], v[i][k], g.domain.min[k], g.domain.max[k],
                                             keepsOut(k, 0, x[i]), keepsOut(k, 1, x[i]));
                for (int body : bodiesNear(x[i], near)) containOutside(body, x[i], v[i]);
                for (const InteriorWall<Dim>& wall : g.interiorWalls)
                    if (wall.mayContain(x[i])) formulas::containOutsideBody<Dim>(x[i], v[i], wall);
            }
        });
    }
    void create(Storage<Dim>&, IMaterial&) const override {}

  private:
    /// Whether fluid at x is reflected at a side: a wall, an inlet (fluid never flows back
    /// through one) or the wall around an outlet's opening; an outlet lets it through.
    bool keepsOut(int axis, int side, const Vec& x) const {
        if (!geometry_.hasWall(axis, side)) return false;
        const WallSide<Dim>& w = geometry_.walls[axis][side];
        return w.layers != ParticleKind::OUTLET || !w.inOpening(x, axis);
    }
    /// From this many bodies on, a particle is checked against the bodies near it only (debris
    /// in a flood), found in a grid of the bodies' centres of radius their largest reach.
    static constexpr std::size_t kGridFrom = 16;

    /// The grid of the bodies where they are now (a fixed one: the centre of its bounds), or
    /// none (few bodies, or one without bounds).
    void gridBodies() {
        const auto& bodies = geometry_.bodies;
        grid_ = bodies.size() >= kGridFrom;
        std::vector<Vec> centres;
        Float reach = 0;
        for (std::size_t b = 0; b < bodies.size() && grid_; ++b) {
            const geometry::Bounds<Dim> box = bodies[b].bounds();
            Vec centre = (box.min + box.max) * 0.5;
            Float r = 0.5 * norm(box.max - box.min);
            if (moving_ && moving_->moves(int(b)))
                centre = moving_->bodies[b].state.position, r = moving_->bodies[b].reach;
            grid_ = std::isfinite(r);
            centres.push_back(centre), reach = std::max(reach, r);
        }
        if (grid_) bodyGrid_.build(centres, reach, geometry_.domain);
    }
    /// The bodies that may hold x, in increasing index (every body without the grid).
    const std::vector<int>& bodiesNear(const Vec& x, std::vector<int>& near) const {
        near.clear();
        if (!grid_) {
            for (std::size_t b = 0; b < geometry_.bodies.size(); ++b) near.push_back(int(b));
            return near;
        }
        bodyGrid_.forEachNeighbour(x, [&](Size k, const Vec&, double) { near.push_back(int(k)); });
        std::sort(near.begin(), near.end());
        return near;
    }

    /// Out of body b, where it is now: reflected in its initial pose, the velocity relative
    /// to the body's (Vec x_0 = X_0 + R^T (x - X), v_0 = R^T (v - v_b(x))).
    void containOutside(int b, Vec& x, Vec& v) const {
        const SolidBody<Dim>& body = geometry_.bodies[b];
        if (!moving_ || !moving_->moves(b)) {
            if (body.mayContain(x)) formulas::containOutsideBody<Dim>(x, v, body);
            return;
        }
        const MovingBody<Dim>& m = moving_->bodies[b];
        containInBodyFrame<Dim>(x, v, BodyFrame<Dim>::of(m.state, m.initialPosition),
                                InitialPose{body});
    }
    /// A body's solid at t = 0, for containInBodyFrame.
    struct InitialPose {
        const SolidBody<Dim>& body;
        bool mayContain(const Vec& x0) const { return body.mayContain(x0); }
        void contain(Vec& x0, Vec& v0) const { formulas::containOutsideBody<Dim>(x0, v0, body); }
    };

    FluidGeometry<Dim> geometry_;
    std::shared_ptr<const MovingBodies<Dim>> moving_;
    bool grid_ = false;
    CellGrid<Dim> bodyGrid_;
};

}  // namespace num::sph
