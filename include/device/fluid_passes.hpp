// The passes of the device step (device/fluid_step.hpp): one functor per pass, each with
// `NUMERICS_HD void operator()(Index i) const` over plain pointers into the step's arrays, run
// by an execution's forEach (a CUDA kernel or a host loop). Every formula is the shared one of
// sph/formulas/.
#pragma once

#include <cmath>
#include <type_traits>

#include "device/execution.hpp"
#include "device/fluid_state.hpp"
#include "device/neighbour_grid.hpp"
#include "spatial/cell_grid.hpp"
#include "sph/formulas/fluid_pairs.hpp"
#include "sph/formulas/fluid_particles.hpp"
#include "sph/formulas/heat_pairs.hpp"
#include "sph/formulas/pair_geometry.hpp"
#include "sph/formulas/wall_condition.hpp"

namespace num::device {

namespace passes {
constexpr int fluid = int(sph::ParticleKind::FLUID);
constexpr int noSlip = 0;  // sph::WallSlip::NO_SLIP
constexpr int fixedTemperature = int(sph::ThermalCondition::FIXED_TEMPERATURE);
constexpr int adiabatic = int(sph::ThermalCondition::ADIABATIC);

/// Every per-particle array of the device step. Persistent ones carry state between
/// evaluations and are permuted with the cell sort; the others are rebuilt by each evaluation.
template <int Dim>
struct Arrays {
    using Vec = Vector<Dim>;
    // Persistent.
    Vec *x, *v, *a, *wallVelocity;  // wallVelocity: nullptr when every boundary is held
    Float *m, *rho, *drho, *drhoOld, *p, *nu, *kernelSum, *surfaceNeighbours;
    int *kind, *slip;
    Index* origin;  // the particle's index in the storage
    // Heat (nullptr without): temperature, its rate (and the rate at the step's start), the
    // temperature shown to conduction, heat source, material index, thermal condition.
    Float *T, *dT, *dTOld, *Tb, *heatSource;
    int *material, *condition;
    const DeviceMaterial* materials;  // the material table
    // The heat books' powers of each particle [W]: a fixed temperature's -m c dT/dt, m s.
    Float *fixedPower, *sourcePower;
    // Rebuilt by each evaluation.
    Float *volume, *pOverRho2, *mu, *inverseWAtSpacing;
    char *active, *atSurface;
    Vec *u, *gradC, *gradRho, *wallDirection;
    Vec* gradV[Dim];
};

template <int Dim>
struct Wrap {
    Vector<Dim>* x;
    Vector<Dim> lo, hi;
    bool periodic[Dim];
    NUMERICS_HD void operator()(Index i) const {
        for (int k = 0; k < Dim; ++k)
            if (periodic[k]) x[i][k] = wrapIntoPeriod(x[i][k], lo[k], hi[k]);
    }
};

template <class T>
struct Gather {  // to[k] = from[order[k]]
    const T* from;
    T* to;
    const Index* order;
    NUMERICS_HD void operator()(Index k) const { to[k] = from[order[k]]; }
};

template <class T>
struct Scatter {  // to[origin[k]] = from[k]: back to the storage's order
    const T* from;
    T* to;
    const Index* origin;
    NUMERICS_HD void operator()(Index k) const { to[origin[k]] = from[k]; }
};

/// The density floor at free surfaces (fluid particles), a constraint on the state before
/// every evaluation (sph::FreeSurfaceTensionLimit::constrain).
template <int Dim>
struct DensityFloorPass {
    Arrays<Dim> d;
    Float w0, surfaceRhoMin;
    NUMERICS_HD void operator()(Index i) const {
        if (d.kind[i] != fluid ||
            !sph::atFreeSurface(d.kernelSum[i], sph::formulas::particleVolume(d.m[i], d.rho[i]),
                                w0))
            return;
        d.rho[i] = sph::formulas::surfaceDensityFloor(d.rho[i], surfaceRhoMin);
    }
};

/// Density by summation (terms/summation_density.hpp): rho_i = sum_j m_j W_ij over every
/// neighbour and i itself, fluid particles only, before the equation of state reads it. i's own
/// term comes before its first neighbour of a higher index: in the CPU's order of increasing j
/// where the grid visits the sorted particles in increasing order (no periodic wrap).
template <int Dim, class Kernel>
struct SummationDensityPass {
    Arrays<Dim> d;
    GridShape<Dim> grid;
    const Index *start, *end;
    sph::KernelValue<Kernel> kernelValue;
    NUMERICS_HD void operator()(Index i) const {
        if (d.kind[i] != fluid) return;
        const Float self = sph::formulas::summationDensityTerm(d.m[i], kernelValue.value(0.0));
        Float sum = 0;
        bool selfAdded = false;
        forEachNeighbour<Dim>(
            grid, d.x, start, end, i, [&](Index j, const Vector<Dim>&, double r2) {
                if (!selfAdded && j > i) sum += self, selfAdded = true;
                sum += sph::formulas::summationDensityTerm(d.m[j], kernelValue.value(hd::sqrt(r2)));
            });
        d.rho[i] = selfAdded ? sum : sum + self;
    }
};

/// The equation of state and the pressure floor at free surfaces (fluid particles); with density
/// by summation the density floor there too (FreeSurfaceTensionLimit::initialize).
template <int Dim>
struct FluidPass {
    Arrays<Dim> d;
    sph::EquationOfState eos;
    Float pMin, w0, surfacePMin, surfaceRhoMin;
    bool tensionLimit, densityFloor;
    NUMERICS_HD void operator()(Index i) const {
        if (d.kind[i] != fluid) return;
        Float p = sph::formulas::fluidPressure(eos, d.rho[i], pMin);
        if (tensionLimit &&
            sph::atFreeSurface(d.kernelSum[i], sph::formulas::particleVolume(d.m[i], d.rho[i]),
                               w0)) {
            p = sph::formulas::surfacePressureFloor(p, surfacePMin);
            if (densityFloor)
                d.rho[i] = sph::formulas::surfaceDensityFloor(d.rho[i], surfaceRhoMin);
        }
        d.p[i] = p;
    }
};

/// The wall condition (Adami et al. 2012): boundary particles from their fluid neighbours.
template <int Dim, class Kernel>
struct WallPass {
    Arrays<Dim> d;
    GridShape<Dim> grid;
    const Index *start, *end;
    sph::KernelValue<Kernel> kernelValue;
    sph::EquationOfState eos;
    Vector<Dim> g;
    bool heat;  // the temperature a fixed-temperature wall shows to conduction
    NUMERICS_HD void operator()(Index w) const {
        if (d.kind[w] == fluid) return;
        sph::formulas::WallSums<Dim> sums;
        forEachNeighbour<Dim>(
            grid, d.x, start, end, w, [&](Index f, const Vector<Dim>& dx, double r2) {
                if (d.kind[f] != fluid) return;
                const Float W = kernelValue.value(hd::sqrt(r2));
                sums.add(d.p[f], d.rho[f], d.v[f], heat ? d.T[f] : 0.0, heat, dx, W);
            });
        const Vector<Dim> wall = d.wallVelocity ? d.wallVelocity[w] : Vector<Dim>{};
        if (!sums.any()) {
            d.p[w] = eos.backgroundPressure;
            d.u[w] = wall;
            if (heat) d.Tb[w] = d.T[w];
        } else {
            d.p[w] = sph::formulas::wallPressure(sums, g);
            d.u[w] = sph::formulas::wallVelocity(sums, wall, d.slip[w] == noSlip);
            if (heat)
                d.Tb[w] = sph::formulas::wallTemperature(sums, d.T[w],
                                                         d.condition[w] == fixedTemperature);
        }
        d.rho[w] = eos.density(d.p[w]);
    }
};

/// Temperature-dependent viscosity (terms/temperature_viscosity.hpp): every particle's nu from
/// its temperature and its material, before the pair pass reads it.
template <int Dim>
struct TemperatureViscosityPass {
    Arrays<Dim> d;
    sph::ViscosityOfTemperature law;
    NUMERICS_HD void operator()(Index i) const {
        const DeviceMaterial& m = d.materials[d.material[i]];
        d.nu[i] = law(d.T[i], m.viscosity, m.referenceTemperature, m.density);
    }
};

/// The per-particle values the pair pass reads (PairInputs, the terms' initialize).
template <int Dim, class Kernel>
struct InputsPass {
    Arrays<Dim> d;
    sph::KernelValue<Kernel> kernelValue;
    Float w0;
    NUMERICS_HD void operator()(Index i) const {
        const bool isFluid = d.kind[i] == fluid;
        const Float volume = sph::formulas::particleVolume(d.m[i], d.rho[i]);
        d.volume[i] = volume;
        if (isFluid || sph::isBuffer(d.kind[i])) d.u[i] = d.v[i];  // a buffer: its own
        d.pOverRho2[i] = sph::formulas::pressureOverDensity2(d.p[i], d.rho[i]);
        d.mu[i] = sph::formulas::dynamicViscosity(d.rho[i], d.nu[i]);
        d.active[i] = isFluid || d.slip[i] == noSlip;
        d.inverseWAtSpacing[i] = 1 / kernelValue.value(sph::formulas::particleSpacing<Dim>(volume));
        d.atSurface[i] = isFluid && sph::atFreeSurface(d.kernelSum[i], volume, w0);
    }
};

/// Every pair sum of a fluid particle, in one gather over its neighbours.
template <int Dim, class Kernel>
struct FluidGather {
    using Vec = Vector<Dim>;
    Arrays<Dim> d;
    GridShape<Dim> grid;
    const Index *start, *end;
    sph::GradientFactor<Kernel> gradient;
    sph::KernelValue<Kernel> kernelValue;
    Float laplacianEta2, inverseR2Eta2;
    Float deltaCoefficient, alphaC0h;
    bool continuityOn;  // false: density by summation, no rate
    bool laminar;
    Vec gravityTerm;  // rho0 g / c0^2 of delta-SPH's hydrostatic part (or zero)
    Vec g;            // the body force
    bool buoyancy;    // Boussinesq buoyancy -beta (T - T0) g
    /// A boundary particle's rates and sums: zero.
    NUMERICS_HD void clear(Index i) const {
        d.a[i] = Vec{}, d.drho[i] = 0, d.kernelSum[i] = 0, d.surfaceNeighbours[i] = 0;
        d.gradC[i] = Vec{}, d.gradRho[i] = Vec{}, d.wallDirection[i] = Vec{};
        for (int b = 0; b < Dim; ++b) d.gradV[b][i] = Vec{};
    }
    NUMERICS_HD void operator()(Index i) const {
        if (d.kind[i] != fluid) return clear(i);
        namespace f = sph::formulas;
        const Vec vi = d.v[i], ui = d.u[i];
        const Float rhoi = d.rho[i], pr2i = d.pOverRho2[i], mui = d.mu[i];
        const Float invRhoi = 1.0 / rhoi, invWi = d.inverseWAtSpacing[i];
        const bool activei = d.active[i];
        Float continuity = 0, diffusion = 0, c = 0, near = 0;
        Vec pressure{}, artificial{}, viscous{}, gradC{}, gradRho{}, wallDirection{};
        Vec gradV[Dim];
        for (int b = 0; b < Dim; ++b) gradV[b] = Vec{};
        forEachNeighbour<Dim>(grid, d.x, start, end, i, [&](Index j, const Vec& dx, double r2) {
            const Float r = hd::sqrt(r2);
            const Vec grad = dx * gradient.factor(r);
            const Float laplacian = f::pairLaplacian<Dim>(dx, grad, r, laplacianEta2);
            const Float inverseR2 = f::pairInverseR2(r, inverseR2Eta2);
            const Float w = kernelValue.value(r);
            const bool fluidj = d.kind[j] == fluid;
            const Float vj = d.volume[j], rhoj = d.rho[j];
            // Continuity with every neighbour's own velocity (a held wall's is zero; a buffer's
            // and a moving body's are not), delta-SPH between fluid particles.
            continuity +=
                f::continuityRate(rhoi, vj, f::continuityDivergence<Dim>(vi, d.v[j], grad));
            if (deltaCoefficient != 0 && fluidj)
                diffusion += f::deltaSphFlux<Dim>(deltaCoefficient, rhoi, rhoj, gravityTerm, dx,
                                                  grad, inverseR2) *
                             vj;
            // Pressure gradient, artificial and laminar viscosity.
            pressure -= f::pressureGradientForce<Dim>(grad, pr2i, d.pOverRho2[j]) * d.m[j];
            if (alphaC0h != 0) {
                const Float vr = hd::min(f::approachRate<Dim>(ui, d.u[j], dx), Float(0));
                artificial -=
                    grad * f::artificialViscosityPi(alphaC0h, vr, inverseR2, rhoi, rhoj) * d.m[j];
            }
            if (laminar && activei && d.active[j])
                viscous += f::laminarViscosityAcceleration<Dim>(
                    ui - d.u[j], f::laminarViscosityFactor(mui, d.mu[j], laplacian), vj, invRhoi);
            // Kernel sums (free surfaces) and the shifting sums.
            const Float weight = f::kernelSumWeight(vj, w);
            c += weight;
            if (d.atSurface[j]) near += weight;
            const Vec dv = d.u[j] - ui;
            gradC += grad * f::shiftingTensileFactor(w, invWi, d.inverseWAtSpacing[j]) * vj;
            gradRho += f::densityGradientTerm<Dim>(grad, vj, rhoj - rhoi);
            if (!fluidj) wallDirection += grad * vj;
            for (int b = 0; b < Dim; ++b) gradV[b] += f::velocityGradientTerm<Dim>(dv, vj, grad[b]);
        });
        d.drho[i] = continuityOn ? continuity + diffusion : 0.0;
        Vec a = pressure + artificial + viscous;
        f::addBodyForce<Dim>(a, g);
        if (buoyancy) {
            const DeviceMaterial& m = d.materials[d.material[i]];
            a += f::boussinesqAcceleration<Dim>(g, m.expansion, d.T[i], m.referenceTemperature);
        }
        d.a[i] = a;
        d.kernelSum[i] = c, d.surfaceNeighbours[i] = near;
        d.gradC[i] = gradC, d.gradRho[i] = gradRho, d.wallDirection[i] = wallDirection;
        for (int b = 0; b < Dim; ++b) d.gradV[b][i] = gradV[b];
    }
};

/// Heat conduction (terms/heat_conduction.hpp) of every particle that is not adiabatic, in one
/// gather over its neighbours, then the thermal conditions (boundary/thermal_walls.hpp): a
/// fixed temperature holds, a heat source adds s / c; each particle's power for the books.
template <int Dim, class Kernel>
struct HeatPass {
    Arrays<Dim> d;
    GridShape<Dim> grid;
    const Index *start, *end;
    sph::GradientFactor<Kernel> gradient;
    Float laplacianEta2;
    NUMERICS_HD void operator()(Index a) const {
        namespace f = sph::formulas;
        const int condA = d.condition[a];
        const DeviceMaterial& ma = d.materials[d.material[a]];
        Float sum = 0;
        if (condA != adiabatic) {
            const Float ka = ma.conductivity, rhoA = d.rho[a], invCa = 1.0 / ma.heatCapacity;
            const Float Ta = f::conductionTemperature(condA, d.T[a], d.Tb[a]);
            forEachNeighbour<Dim>(
                grid, d.x, start, end, a, [&](Index b, const Vector<Dim>& dx, double r2) {
                    const int condB = d.condition[b];
                    if (!sph::conductsHeat(condA, condB)) return;
                    const Float kb = d.materials[d.material[b]].conductivity;
                    if (!(ka + kb > 0)) return;
                    const Float r = hd::sqrt(r2);
                    const Float laplacian =
                        f::pairLaplacian<Dim>(dx, dx * gradient.factor(r), r, laplacianEta2);
                    const Float Tb = f::conductionTemperature(condB, d.T[b], d.Tb[b]);
                    sum += f::heatRate(
                        d.m[b], f::heatExchange(ka, kb, rhoA, d.rho[b], Ta, Tb, laplacian), invCa);
                });
        }
        const bool fixed = condA == fixedTemperature;
        d.fixedPower[a] = fixed ? -(d.m[a] * ma.heatCapacity * sum) : 0.0;
        d.sourcePower[a] = fixed ? 0.0 : d.m[a] * d.heatSource[a];
        if (fixed)
            sum = 0;
        else if (d.heatSource[a] != 0)
            sum += d.heatSource[a] / ma.heatCapacity;
        d.dT[a] = sum;
    }
};

}  // namespace passes

}  // namespace num::device
