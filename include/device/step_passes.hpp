// The passes of the device step (device/fluid_step.hpp) that advance it: the leapfrog's two
// halves, the post-step phase (shifting, containment) and the values that limit the time step.
#pragma once

#include <cmath>

#include "device/fluid_passes.hpp"
#include "sph/formulas/leapfrog.hpp"
#include "sph/formulas/post_step.hpp"

namespace num::device {

namespace passes {

/// The first half of the leapfrog: v += a dt/2, x += v dt; rho += drho dt (Heun's predictor).
template <int Dim>
struct KickDrift {
    Arrays<Dim> d;
    Float dt;
    NUMERICS_HD void operator()(Index i) const {
        sph::formulas::kickDrift(d.x[i], d.v[i], d.a[i], 0.5 * dt, dt);
        sph::formulas::heunPredict(d.rho[i], d.drhoOld[i], d.drho[i], dt);
        if (d.T) sph::formulas::heunPredict(d.T[i], d.dTOld[i], d.dT[i], dt);
    }
};

/// The second half: v += a dt/2 with the new accelerations; Heun's corrector for the density.
template <int Dim>
struct Kick {
    Arrays<Dim> d;
    Float dt;
    NUMERICS_HD void operator()(Index i) const {
        sph::formulas::kick(d.v[i], d.a[i], 0.5 * dt);
        sph::formulas::heunCorrect(d.rho[i], d.drho[i], d.drhoOld[i], 0.5 * dt);
        if (d.T) sph::formulas::heunCorrect(d.T[i], d.dT[i], d.dTOld[i], 0.5 * dt);
    }
};

/// The post-step phase: particle shifting, then containment in the box's walls and out of the
/// solid bodies and the walls inside the domain.
template <int Dim>
struct PostStep {
    Arrays<Dim> d;
    bool shifting, normalToWalls, continuity, contain;
    Float diffusion, cap, w0;  // A h c0 dt, 0.1 h, W(0)
    Vector<Dim> lo, hi;
    bool wallLow[Dim], wallHigh[Dim];
    const ContainmentSolid<Dim>* solids;  // the bodies, then the interior walls
    int solidCount;
    const geometry::FlatNode* flatNodes;
    const double* flatValues;
    sph::formulas::OutletOpening<Dim> openings[Dim][2];  // fluid passes through an outlet
    const sph::BodyFrame<Dim>* frames = nullptr;         // the bodies' (null: none moves)
    NUMERICS_HD void operator()(Index i) const {
        if (d.kind[i] != fluid) return;
        if (shifting && !sph::atFreeSurface(d.kernelSum[i], d.volume[i], w0) &&
            !(d.surfaceNeighbours[i] > 0) && diffusion > 0) {
            const Vector<Dim> dr = sph::formulas::shiftingDisplacement<Dim>(
                d.gradC[i], d.wallDirection[i], diffusion, cap, normalToWalls);
            Vector<Dim> columns[Dim];
            for (int k = 0; k < Dim; ++k) columns[k] = d.gradV[k][i];
            sph::formulas::shiftParticle<Dim>(d.x[i], d.v[i], d.rho[i], continuity, dr,
                                              d.gradRho[i], columns);
        }
        if (contain) {
            for (int k = 0; k < Dim; ++k)
                sph::formulas::containInWalls(
                    d.x[i][k], d.v[i][k], lo[k], hi[k],
                    wallLow[k] && !openings[k][0].letsThrough(d.x[i], k),
                    wallHigh[k] && !openings[k][1].letsThrough(d.x[i], k));
            containOutsideSolids<Dim>(d.x[i], d.v[i], solids, solidCount, flatNodes, flatValues,
                                      frames);
        }
    }
};

/// sign x_k of a fluid particle, -infinity for the others (the fluid's extent by a maximum).
template <int Dim>
struct FluidCoordinate {
    const Vector<Dim>* x;
    const int* kind;
    int axis;
    double sign;
    double* out;
    NUMERICS_HD void operator()(Index i) const {
        out[i] = kind[i] == fluid ? sign * x[i][axis] : -HUGE_VAL;
    }
};

/// Per-particle values whose maxima limit the time step.
template <int Dim>
struct StepCriteria {
    Arrays<Dim> d;
    double *acceleration2, *fluidSpeed2, *viscosity, *diffusivity;
    bool conduction;
    NUMERICS_HD void operator()(Index i) const {
        acceleration2[i] = normSqr(d.a[i]);
        fluidSpeed2[i] = d.kind[i] == fluid ? normSqr(d.v[i]) : 0.0;
        viscosity[i] = d.nu[i];
        // k / (rho c): rounding is monotonic, so the largest is the CPU's k / (rho_min c).
        if (conduction) {
            const DeviceMaterial& m = d.materials[d.material[i]];
            diffusivity[i] =
                d.condition[i] != adiabatic ? m.conductivity / (d.rho[i] * m.heatCapacity) : 0.0;
        }
    }
};

}  // namespace passes

}  // namespace num::device
