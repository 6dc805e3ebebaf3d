// The device step of the weakly-compressible fluid: the default physics of
// sph/fluid_model.hpp on particles that stay in the memory of an execution (device/
// execution.hpp) between outputs, as structure of arrays sorted by cell at every evaluation.
//
// One evaluation at time t, as the CPU solver's (sph/solver.hpp with the fluid model's terms):
//   wrap periodic positions -> cell keys, sort, permute every array, cell ranges
//   -> viscosity pass (temperature-dependent viscosity): nu = nu(T) of every particle
//   -> fluid pass:  p = max(p(rho), p_b - T_max); the tension limit at free surfaces
//   -> wall pass:   the wall condition of Adami et al. 2012 (boundary particles, walls and
//                   bodies, gather fluid); with conduction the temperature a fixed-temperature
//                   boundary particle shows
//   -> inputs pass: V = m / rho, the pair velocity, p / rho^2, mu = rho nu, 1 / W(V^(1/Dim)),
//                   the free-surface flags of the previous kernel sum
//   -> pair pass:   each fluid particle gathers its neighbours once: continuity + delta-SPH,
//                   pressure gradient, artificial and laminar viscosity, kernel sums, the
//                   shifting sums; then the body force and Boussinesq buoyancy. Boundary
//                   particles' rates are zero.
//   -> heat pass:   conduction: every particle that is not adiabatic gathers its neighbours;
//                   then the thermal conditions (fixed temperature, heat sources)
// The leapfrog of sph/timestepping.hpp (kick-drift, evaluate, kick; Heun for the density and
// the temperature) and the post-step phase (particle shifting, containment in the box's walls
// and out of the bodies) are passes too.
// Every formula is the shared one of sph/formulas/ (host and device).
//
// Order and round-off: a particle's neighbours come in the grid's order (device/
// neighbour_grid.hpp). Each term's sum is kept apart and the rates are combined at the end in
// the CPU engine's order of terms: sums of one term (kernel sums, shifting sums, the pressure
// gradient alone) are bitwise the CPU's where the neighbour order is (particles sorted as the
// grid sorts them, no periodic wrap); the CPU adds the terms' sums one after another into one
// register, so the combined rates agree to round-off.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <type_traits>
#include <utility>
#include <vector>

#include "device/execution.hpp"
#include "device/fluid_state.hpp"
#include "device/neighbour_grid.hpp"
#include "sph/formulas/fluid_pairs.hpp"
#include "sph/formulas/fluid_particles.hpp"
#include "sph/formulas/heat_pairs.hpp"
#include "sph/formulas/pair_geometry.hpp"
#include "sph/formulas/post_step.hpp"
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
        Vector<Dim> p = x[i];
        for (int k = 0; k < Dim; ++k)  // Domain::wrap
            if (periodic[k]) {
                const double length = hi[k] - lo[k];
                p[k] = lo[k] + ::fmod(p[k] - lo[k], length);
                if (p[k] < lo[k]) p[k] += length;
                if (p[k] >= hi[k]) p[k] = lo[k];
            }
        x[i] = p;
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

/// The equation of state and the tension limit at free surfaces (fluid particles).
template <int Dim>
struct FluidPass {
    Arrays<Dim> d;
    sph::EquationOfState eos;
    Float pMin, w0, surfacePMin, surfaceRhoMin;
    bool tensionLimit;
    NUMERICS_HD void operator()(Index i) const {
        if (d.kind[i] != fluid) return;
        Float p = sph::formulas::fluidPressure(eos, d.rho[i], pMin);
        Float rho = d.rho[i];
        if (tensionLimit &&
            sph::atFreeSurface(d.kernelSum[i], sph::formulas::particleVolume(d.m[i], rho), w0))
            sph::formulas::limitSurfaceTension(p, rho, surfacePMin, surfaceRhoMin);
        d.p[i] = p, d.rho[i] = rho;
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
        if (isFluid) d.u[i] = d.v[i];
        d.pOverRho2[i] = sph::formulas::pressureOverDensity2(d.p[i], d.rho[i]);
        d.mu[i] = sph::formulas::dynamicViscosity(d.rho[i], d.nu[i]);
        d.active[i] = isFluid || d.slip[i] == noSlip;
        d.inverseWAtSpacing[i] = 1 / kernelValue.value(sph::formulas::particleSpacing<Dim>(volume));
        d.atSurface[i] = isFluid && sph::atFreeSurface(d.kernelSum[i], volume, w0);
    }
};

/// Every pair sum of a fluid particle, in one gather over its neighbours.
template <int Dim, class Kernel>
struct PairPass {
    using Vec = Vector<Dim>;
    Arrays<Dim> d;
    GridShape<Dim> grid;
    const Index *start, *end;
    sph::GradientFactor<Kernel> gradient;
    sph::KernelValue<Kernel> kernelValue;
    Float laplacianEta2, inverseR2Eta2;
    Float deltaCoefficient, alphaC0h;
    bool laminar;
    Vec gravityTerm;  // rho0 g / c0^2 of delta-SPH's hydrostatic part (or zero)
    Vec g;            // the body force
    bool buoyancy;    // Boussinesq buoyancy -beta (T - T0) g
    NUMERICS_HD void operator()(Index i) const {
        if (d.kind[i] != fluid) {
            d.a[i] = Vec{}, d.drho[i] = 0, d.kernelSum[i] = 0, d.surfaceNeighbours[i] = 0;
            d.gradC[i] = Vec{}, d.gradRho[i] = Vec{}, d.wallDirection[i] = Vec{};
            for (int b = 0; b < Dim; ++b) d.gradV[b][i] = Vec{};
            return;
        }
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
            // Continuity (+ delta-SPH between fluid particles).
            continuity += f::continuityRate(
                rhoi, vj, f::continuityDivergence<Dim>(vi, fluidj ? d.v[j] : Vec{}, grad));
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
        d.drho[i] = continuity + diffusion;
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
/// fixed temperature holds, a heat source adds s / c.
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
        if (condA == fixedTemperature)
            sum = 0;
        else if (d.heatSource[a] != 0)
            sum += d.heatSource[a] / ma.heatCapacity;
        d.dT[a] = sum;
    }
};

/// The first half of the leapfrog: v += a dt/2, x += v dt; rho += drho dt (Heun's predictor).
template <int Dim>
struct KickDrift {
    Arrays<Dim> d;
    Float dt;
    NUMERICS_HD void operator()(Index i) const {
        d.v[i] += d.a[i] * (0.5 * dt);
        d.x[i] += d.v[i] * dt;
        d.drhoOld[i] = d.drho[i];
        d.rho[i] += d.drho[i] * dt;
        if (d.T) {
            d.dTOld[i] = d.dT[i];
            d.T[i] += d.dT[i] * dt;
        }
    }
};

/// The second half: v += a dt/2 with the new accelerations; Heun's corrector for the density.
template <int Dim>
struct Kick {
    Arrays<Dim> d;
    Float dt;
    NUMERICS_HD void operator()(Index i) const {
        d.v[i] += d.a[i] * (0.5 * dt);
        d.rho[i] += (d.drho[i] - d.drhoOld[i]) * (0.5 * dt);
        if (d.T) d.T[i] += (d.dT[i] - d.dTOld[i]) * (0.5 * dt);
    }
};

/// The post-step phase: particle shifting, then containment in the box's walls and out of the
/// solid bodies.
template <int Dim>
struct PostStep {
    Arrays<Dim> d;
    bool shifting, normalToWalls, continuity, contain;
    Float diffusion, cap, w0;  // A h c0 dt, 0.1 h, W(0)
    Vector<Dim> lo, hi;
    bool wallLow[Dim], wallHigh[Dim];
    const sph::Shape<Dim>* bodies;
    int bodyCount;
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
                sph::formulas::containInWalls(d.x[i][k], d.v[i][k], lo[k], hi[k], wallLow[k],
                                              wallHigh[k]);
            for (int b = 0; b < bodyCount; ++b)
                sph::formulas::containOutsideBody<Dim>(d.x[i], d.v[i], bodies[b]);
        }
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

/// The device step in the memory of an execution (see the top of this file).
template <int Dim, class Exec>
class DeviceFluidStep final : public IDeviceFluid<Dim> {
  public:
    using Vec = Vector<Dim>;

    explicit DeviceFluidStep(FluidStepConfig<Dim> config, Exec& exec)
        : c_(std::move(config)),
          exec_(exec),
          grid_(exec, c_.supportRadius, c_.domainMin, c_.domainMax, c_.periodic),
          x_(exec),
          v_(exec),
          a_(exec),
          wallVelocity_(exec),
          u_(exec),
          gradC_(exec),
          gradRho_(exec),
          wallDirection_(exec),
          m_(exec),
          rho_(exec),
          drho_(exec),
          drhoOld_(exec),
          p_(exec),
          nu_(exec),
          kernelSum_(exec),
          surfaceNeighbours_(exec),
          volume_(exec),
          pOverRho2_(exec),
          mu_(exec),
          inverseWAtSpacing_(exec),
          maxima_{Buffer<double, Exec>(exec), Buffer<double, Exec>(exec),
                  Buffer<double, Exec>(exec), Buffer<double, Exec>(exec)},
          kind_(exec),
          slip_(exec),
          origin_(exec),
          active_(exec),
          atSurface_(exec),
          tempVec_(exec),
          tempFloat_(exec),
          tempInt_(exec),
          tempIndex_(exec),
          bodies_(exec),
          T_(exec),
          dT_(exec),
          dTOld_(exec),
          Tb_(exec),
          heatSource_(exec),
          material_(exec),
          condition_(exec),
          materials_(exec) {
        for (int b = 0; b < Dim; ++b) gradV_.emplace_back(exec);
        if (!c_.bodies.empty()) bodies_.upload(c_.bodies);
        if (c_.heat() && !c_.materials.empty()) materials_.upload(c_.materials);
    }

    void upload(const ParticleArrays<Dim>& s) override {
        n_ = Index(s.size());
        sliding_ = !s.wallVelocity.empty();
        x_.upload(s.x), v_.upload(s.v), a_.upload(s.a), m_.upload(s.m), rho_.upload(s.rho);
        drho_.upload(s.drho), p_.upload(s.p), nu_.upload(s.nu), kernelSum_.upload(s.kernelSum);
        surfaceNeighbours_.upload(s.surfaceNeighbours), kind_.upload(s.kind), slip_.upload(s.slip);
        if (sliding_) wallVelocity_.upload(s.wallVelocity);
        u_.upload(s.pairVelocity);
        std::vector<Index> origin(n_);
        std::iota(origin.begin(), origin.end(), Index(0));
        origin_.upload(origin);
        for (auto* b : {&gradC_, &gradRho_, &wallDirection_}) b->resize(n_);
        for (auto& b : gradV_) b.resize(n_);
        for (auto* b : {&drhoOld_, &volume_, &pOverRho2_, &mu_, &inverseWAtSpacing_}) b->resize(n_);
        for (int k = 0; k < 3; ++k) maxima_[k].resize(n_);
        active_.resize(n_), atSurface_.resize(n_);
        heat_ = c_.heat() && !s.T.empty();
        if (heat_) {
            T_.upload(s.T), dT_.upload(s.dT), Tb_.upload(s.Tb), heatSource_.upload(s.heatSource);
            material_.upload(s.material), condition_.upload(s.condition), dTOld_.resize(n_);
        }
        if (heat_ && c_.conduction) maxima_[3].resize(n_);
    }

    void download(ParticleArrays<Dim>& s) override {
        s.x.resize(n_), s.v.resize(n_), s.a.resize(n_), s.rho.resize(n_), s.drho.resize(n_);
        s.p.resize(n_), s.kernelSum.resize(n_), s.surfaceNeighbours.resize(n_);
        s.volume.resize(n_), s.pairVelocity.resize(n_), s.kernelSumGradient.resize(n_);
        s.densityGradient.resize(n_), s.wallDirection.resize(n_);
        for (auto& g : s.velocityGradient) g.resize(n_);
        fetch(x_, s.x), fetch(v_, s.v), fetch(a_, s.a), fetch(rho_, s.rho), fetch(drho_, s.drho);
        fetch(p_, s.p), fetch(kernelSum_, s.kernelSum);
        fetch(surfaceNeighbours_, s.surfaceNeighbours), fetch(volume_, s.volume);
        fetch(u_, s.pairVelocity), fetch(gradC_, s.kernelSumGradient);
        fetch(gradRho_, s.densityGradient), fetch(wallDirection_, s.wallDirection);
        for (int b = 0; b < Dim; ++b) fetch(gradV_[b], s.velocityGradient[b]);
        s.nu.resize(n_), fetch(nu_, s.nu);
        if (heat_) {
            s.T.resize(n_), s.dT.resize(n_), s.Tb.resize(n_);
            fetch(T_, s.T), fetch(dT_, s.dT), fetch(Tb_, s.Tb);
        }
    }

    void evaluate(Float t) override {
        passes::Arrays<Dim> d = arrays();
        if (anyPeriodic()) {
            passes::Wrap<Dim> wrap{d.x, c_.domainMin, c_.domainMax, {}};
            for (int k = 0; k < Dim; ++k) wrap.periodic[k] = c_.periodic[k];
            exec_.forEach(n_, wrap);
        }
        sortByCell();
        d = arrays();
        if (heat_ && c_.temperatureViscosity)
            exec_.forEach(n_, passes::TemperatureViscosityPass<Dim>{d, c_.viscosityLaw});
        const Vec g = c_.bodyForce ? c_.bodyForce(t) : Vec{};
        const Vec gravityTerm =
            c_.deltaHydrostatic && c_.bodyForce
                ? sph::formulas::deltaSphGravityTerm<Dim>(g, c_.eos.rho0, c_.eos.c0)
                : Vec{};
        exec_.forEach(n_, passes::FluidPass<Dim>{d, c_.eos, c_.pMin, c_.w0, c_.surfacePMin,
                                                 c_.surfaceRhoMin, c_.tensionLimit});
        sph::withKernel<Dim>(c_.kernel, [&](auto kernel) {
            using K = decltype(kernel);
            const sph::KernelValue<K> value(c_.h);
            if (c_.walls)
                exec_.forEach(
                    n_, passes::WallPass<Dim, K>{d, grid_.grid(), grid_.start(), grid_.end(), value,
                                                 c_.eos, g, heat_ && c_.conduction});
            exec_.forEach(n_, passes::InputsPass<Dim, K>{d, value, c_.w0});
            exec_.forEach(
                n_, passes::PairPass<Dim, K>{d, grid_.grid(), grid_.start(), grid_.end(),
                                             sph::GradientFactor<K>(c_.h), value, c_.laplacianEta2,
                                             c_.inverseR2Eta2, c_.deltaCoefficient, c_.alphaC0h,
                                             c_.laminar, gravityTerm, g, heat_ && c_.buoyancy});
            if (heat_ && c_.conduction)
                exec_.forEach(
                    n_, passes::HeatPass<Dim, K>{d, grid_.grid(), grid_.start(), grid_.end(),
                                                 sph::GradientFactor<K>(c_.h), c_.laplacianEta2});
        });
    }

    StepMaxima maxima() override {
        const bool conduction = heat_ && c_.conduction;
        exec_.forEach(n_,
                      passes::StepCriteria<Dim>{arrays(), maxima_[0].data(), maxima_[1].data(),
                                                maxima_[2].data(), maxima_[3].data(), conduction});
        StepMaxima m;
        m.acceleration2 = std::max(0.0, exec_.maxOf(maxima_[0].data(), n_));
        m.fluidSpeed2 = std::max(0.0, exec_.maxOf(maxima_[1].data(), n_));
        m.viscosity = c_.laminar ? std::max(0.0, exec_.maxOf(maxima_[2].data(), n_)) : 0.0;
        m.diffusivity = conduction ? std::max(0.0, exec_.maxOf(maxima_[3].data(), n_)) : 0.0;
        return m;
    }

    void advance(Float t, Float dt) override {
        exec_.forEach(n_, passes::KickDrift<Dim>{arrays(), dt});
        evaluate(t + dt);
        exec_.forEach(n_, passes::Kick<Dim>{arrays(), dt});
    }

    void postStep(Float dt) override {
        if (!c_.shifting && !c_.contain) return;
        passes::PostStep<Dim> post{arrays(),
                                   c_.shifting,
                                   c_.shiftingNormalToWalls,
                                   true,
                                   c_.contain,
                                   c_.shiftingCoefficient * c_.h * c_.eos.c0 * dt,
                                   0.1 * c_.h,
                                   c_.w0,
                                   c_.domainMin,
                                   c_.domainMax,
                                   {},
                                   {},
                                   bodies_.data(),
                                   int(c_.bodies.size())};
        for (int k = 0; k < Dim; ++k)
            post.wallLow[k] = c_.wallLow[k], post.wallHigh[k] = c_.wallHigh[k];
        exec_.forEach(n_, post);
    }

    std::size_t size() const override { return n_; }
    std::size_t bytes() const override {
        std::size_t b = grid_.bytes();
        for (const auto* v :
             {&x_, &v_, &a_, &wallVelocity_, &u_, &gradC_, &gradRho_, &wallDirection_, &tempVec_})
            b += v->bytes();
        for (const auto& v : gradV_) b += v.bytes();
        for (const auto* f :
             {&m_, &rho_, &drho_, &drhoOld_, &p_, &nu_, &kernelSum_, &surfaceNeighbours_, &volume_,
              &pOverRho2_, &mu_, &inverseWAtSpacing_, &tempFloat_})
            b += f->bytes();
        for (const auto& f : maxima_) b += f.bytes();
        b += kind_.bytes() + slip_.bytes() + tempInt_.bytes() + origin_.bytes() +
             tempIndex_.bytes() + active_.bytes() + atSurface_.bytes() + bodies_.bytes();
        for (const auto* f : {&T_, &dT_, &dTOld_, &Tb_, &heatSource_}) b += f->bytes();
        b += material_.bytes() + condition_.bytes() + materials_.bytes();
        return b;
    }
    const char* execution() const override { return Exec::name(); }

  private:
    bool anyPeriodic() const {
        for (int k = 0; k < Dim; ++k)
            if (c_.periodic[k]) return true;
        return false;
    }

    passes::Arrays<Dim> arrays() {
        passes::Arrays<Dim> d;
        d.x = x_.data(), d.v = v_.data(), d.a = a_.data();
        d.wallVelocity = sliding_ ? wallVelocity_.data() : nullptr;
        d.m = m_.data(), d.rho = rho_.data(), d.drho = drho_.data(), d.drhoOld = drhoOld_.data();
        d.p = p_.data(), d.nu = nu_.data(), d.kernelSum = kernelSum_.data();
        d.surfaceNeighbours = surfaceNeighbours_.data(), d.kind = kind_.data();
        d.slip = slip_.data(), d.origin = origin_.data(), d.volume = volume_.data();
        d.pOverRho2 = pOverRho2_.data(), d.mu = mu_.data();
        d.inverseWAtSpacing = inverseWAtSpacing_.data(), d.active = active_.data();
        d.atSurface = atSurface_.data(), d.u = u_.data(), d.gradC = gradC_.data();
        d.gradRho = gradRho_.data(), d.wallDirection = wallDirection_.data();
        for (int b = 0; b < Dim; ++b) d.gradV[b] = gradV_[b].data();
        d.T = heat_ ? T_.data() : nullptr, d.dT = dT_.data(), d.dTOld = dTOld_.data();
        d.Tb = Tb_.data(), d.heatSource = heatSource_.data();
        d.material = material_.data(), d.condition = condition_.data();
        d.materials = materials_.data();
        return d;
    }

    /// Sorts the particles by cell and permutes every array that carries state.
    void sortByCell() {
        grid_.build(x_.data(), n_, origin_.data());
        const Index* order = grid_.order();
        const auto permute = [&](auto& buffer, auto& temp) {
            using T = std::remove_cvref_t<decltype(*buffer.data())>;
            if (buffer.size() != n_) return;
            temp.resize(n_);
            exec_.forEach(n_, passes::Gather<T>{buffer.data(), temp.data(), order});
            buffer.swap(temp);
        };
        for (auto* b : {&x_, &v_, &a_, &u_}) permute(*b, tempVec_);
        if (sliding_) permute(wallVelocity_, tempVec_);
        for (auto* b : {&m_, &rho_, &drho_, &drhoOld_, &p_, &nu_, &kernelSum_, &surfaceNeighbours_})
            permute(*b, tempFloat_);
        permute(kind_, tempInt_), permute(slip_, tempInt_);
        if (heat_) {
            for (auto* b : {&T_, &dT_, &dTOld_, &Tb_, &heatSource_}) permute(*b, tempFloat_);
            permute(material_, tempInt_), permute(condition_, tempInt_);
        }
        permute(origin_, tempIndex_);
    }

    template <class T>
    void fetch(const Buffer<T, Exec>& buffer, std::vector<T>& out) {
        tempHost_.resize(n_ * sizeof(T));
        T* sorted = reinterpret_cast<T*>(tempHost_.data());
        exec_.download(sorted, buffer.data(), n_);
        if (origin_.size() != n_) return;
        if (originHost_.size() != n_) originHost_.resize(n_);
        exec_.download(originHost_.data(), origin_.data(), n_);
        for (Index k = 0; k < n_; ++k) out[originHost_[k]] = sorted[k];
    }

    FluidStepConfig<Dim> c_;
    Exec& exec_;
    NeighbourGrid<Dim, Exec> grid_;
    Index n_ = 0;
    bool sliding_ = false;
    Buffer<Vec, Exec> x_, v_, a_, wallVelocity_, u_, gradC_, gradRho_, wallDirection_;
    std::vector<Buffer<Vec, Exec>> gradV_;
    Buffer<Float, Exec> m_, rho_, drho_, drhoOld_, p_, nu_, kernelSum_, surfaceNeighbours_, volume_,
        pOverRho2_, mu_, inverseWAtSpacing_;
    std::array<Buffer<double, Exec>, 4> maxima_;
    Buffer<int, Exec> kind_, slip_;
    Buffer<Index, Exec> origin_;
    Buffer<char, Exec> active_, atSurface_;
    Buffer<Vec, Exec> tempVec_;
    Buffer<Float, Exec> tempFloat_;
    Buffer<int, Exec> tempInt_;
    Buffer<Index, Exec> tempIndex_;
    Buffer<sph::Shape<Dim>, Exec> bodies_;
    bool heat_ = false;  // temperature on the device (the config's heat and the particles')
    Buffer<Float, Exec> T_, dT_, dTOld_, Tb_, heatSource_;
    Buffer<int, Exec> material_, condition_;
    Buffer<DeviceMaterial, Exec> materials_;
    std::vector<unsigned char> tempHost_;
    std::vector<Index> originHost_;
};

}  // namespace num::device
