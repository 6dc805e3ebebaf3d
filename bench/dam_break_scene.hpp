// The benchmark scenes: a dam break mirroring PySPH's dam_break_2d example (and its 3D
// extension), built with the fluid model API. Shared by the end-to-end program and the
// micro-benchmarks.
//
// 2D: a water column 1 m wide and 2 m high at the left of a 4 m x 4 m tank (walls left, right
// and bottom, open top). 3D: the same column 0.8 m deep in a tank 2 m x 2.2 m x 0.8 m with walls
// on every side but the top. Both: h = 1.3 dx, Wendland C2, Tait EOS (gamma = 7) with
// c0 = 10 sqrt(2 g H), artificial viscosity alpha = 0.1, delta-SPH density diffusion
// (delta = 0.1), gravity 9.81 m/s^2. Heat: conduction between all particles (adiabatic walls).
#pragma once

#include <cmath>
#include <memory>
#include <string>

#include "numerics.hpp"
#include "sph/fluid_model.hpp"

namespace bench {

using namespace num::sph;

struct SceneOptions {
    double dx = 0.01;
    bool heat = false;
    int threads = 1;
    std::string evaluation = "asymmetric";
    std::string backend =
        "omp";  ///< makeScheduler name: omp (OpenMP) or threads (std::thread pool)
};

template <int Dim>
struct Scene {
    FluidModel<Dim> model;
    FluidGeometry<Dim> geometry;
    RunSettings settings;
    Storage<Dim> storage;
    std::unique_ptr<IScheduler> scheduler;
    std::unique_ptr<Solver<Dim>> solver;
    LeapfrogKDK<Dim> integrator;
    std::unique_ptr<Run<Dim>> run;

    Size fluidParticles() const {
        Size n = 0;
        for (int k : storage.template getValue<int>(QuantityId::KIND)) n += isFluid(k);
        return n;
    }
};

/// Builds the scene (storage, solver, run loop) without evaluating anything yet.
template <int Dim>
std::unique_ptr<Scene<Dim>> makeDamBreak(const SceneOptions& o) {
    using Vec = Vector<Dim>;
    constexpr double g = 9.81, column = 2.0;
    auto s = std::make_unique<Scene<Dim>>();
    FluidModel<Dim>& m = s->model;
    m.restDensity = 1000;
    m.soundSpeed = 10 * std::sqrt(2 * g * column);
    m.artificialViscosity = 0.1;
    m.deltaSph = 0.1;
    Vec gravity{};
    gravity[1] = -g;
    m.bodyForce = constantForce<Dim>(gravity);
    m.heat.conduction = o.heat;

    FluidGeometry<Dim>& geo = s->geometry;
    geo.spacing = o.dx;
    Vec lo{}, hi{}, columnHi{};
    if constexpr (Dim == 2) {
        hi = Vec{{4.0, 4.0}};
        columnHi = Vec{{1.0, column}};
    } else {
        hi = Vec{{2.0, 2.2, 0.8}};
        columnHi = Vec{{1.0, column, 0.8}};
    }
    geo.domain.min = lo;
    geo.domain.max = hi;
    geo.walls[1][1].present = false;  // open top
    geo.fluid.push_back(FluidRegion<Dim>::filling(BoxOrBall<Dim>::box(lo, columnHi)));

    s->settings.set("smoothing_length", 1.3 * o.dx)
        .set("kernel", std::string("wendland_c2"))
        .set("threads", std::int64_t(o.threads))
        .set("evaluation", o.evaluation);
    s->storage = makeFluidStorage(m, geo, s->settings);
    s->scheduler = makeScheduler(o.backend, Size(o.threads));
    s->solver = std::make_unique<Solver<Dim>>(*s->scheduler, s->settings,
                                              makeFluidEquations(m, geo), geo.domain);
    s->run = std::make_unique<Run<Dim>>(s->storage, *s->solver, s->integrator);
    return s;
}

/// The spacing that gives about n fluid particles in the 2D column (1 m x 2 m).
inline double spacingFor2D(double n) { return std::sqrt(2.0 / n); }

}  // namespace bench
