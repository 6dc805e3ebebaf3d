// The device step of the weakly-compressible fluid: the default physics of
// sph/fluid_model.hpp on particles that stay in the memory of an execution (device/
// execution.hpp) between outputs, as structure of arrays sorted by cell at every evaluation.
//
// One evaluation at time t, as the CPU solver's (sph/solver.hpp with the fluid model's terms):
//   the constraints: wrap periodic positions; the density floor at free surfaces (continuity)
//   -> cell keys, sort, permute every array, cell ranges
//   -> viscosity pass (temperature-dependent viscosity): nu = nu(T) of every particle
//   -> summation pass (density by summation): rho = sum_j m_j W_ij of the fluid particles
//   -> fluid pass:  p = max(p(rho), p_b - T_max); the pressure floor at free surfaces (with
//                   summation the density floor too)
//   -> wall pass:   the wall condition of Adami et al. 2012 (boundary particles, walls and
//                   bodies, gather fluid); with conduction the temperature a fixed-temperature
//                   boundary particle shows
//   -> outlet pass (outlets): p = p_out(x, t) (an expression, evaluated on the host), rho(p),
//                   v the Shepard mean of the fluid's and outlets' (device/outlet_pass.hpp)
//   -> inputs pass: V = m / rho, the pair velocity (a buffer particle's own velocity), p / rho^2,
//                   mu = rho nu, 1 / W(V^(1/Dim)), the free-surface flags of the previous
//                   kernel sum
//   -> pair pass:   each fluid particle gathers its neighbours once: continuity + delta-SPH,
//                   pressure gradient, artificial and laminar viscosity, kernel sums, the
//                   shifting sums; then the body force and Boussinesq buoyancy. Boundary
//                   particles' rates are zero.
//   -> heat pass:   conduction: every particle that is not adiabatic gathers its neighbours;
//                   then the thermal conditions (fixed temperature, heat sources)
//   -> body pass:   moving bodies (the coupling's finalize, last): each moving body particle
//                   gathers the fluid's force on it and its contacts (device/body_step.hpp);
//                   the host sums them into each body's force and torque (device/body_run.hpp)
// The leapfrog of sph/timestepping.hpp (kick-drift, evaluate, kick; Heun for the density and
// the temperature) and the post-step phase (particle shifting; the moving bodies advanced on the
// host, their particles placed from their frames; containment in the box's walls and out of the
// bodies, a moving one in its frame, and interior walls, of any shape but a mesh, letting fluid
// through an outlet's opening) are passes too. Inlets and outlets exchange particles with the
// fluid on the host after each step (FlowBoundaries::exchange).
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

#include "device/body_step.hpp"
#include "device/execution.hpp"
#include "device/fluid_passes.hpp"
#include "device/fluid_state.hpp"
#include "device/neighbour_grid.hpp"
#include "device/outlet_pass.hpp"
#include "device/step_passes.hpp"
#include "sph/formulas/fluid_pairs.hpp"
#include "sph/formulas/fluid_particles.hpp"
#include "sph/formulas/heat_pairs.hpp"
#include "sph/formulas/pair_geometry.hpp"
#include "sph/formulas/post_step.hpp"
#include "sph/formulas/wall_condition.hpp"

namespace num::device {

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
          solids_(exec),
          flatNodes_(exec),
          flatValues_(exec),
          T_(exec),
          dT_(exec),
          dTOld_(exec),
          Tb_(exec),
          heatSource_(exec),
          material_(exec),
          condition_(exec),
          materials_(exec),
          fixedPower_(exec),
          sourcePower_(exec),
          outletP_(exec),
          bodies_(exec) {
        for (int b = 0; b < Dim; ++b) gradV_.emplace_back(exec);
        if (!c_.solids.solids.empty()) solids_.upload(c_.solids.solids);
        if (!c_.solids.nodes.empty()) flatNodes_.upload(c_.solids.nodes);
        if (!c_.solids.values.empty()) flatValues_.upload(c_.solids.values);
        if (c_.heat() && !c_.materials.empty()) materials_.upload(c_.materials);
    }

    void upload(const ParticleArrays<Dim>& s) override {
        n_ = Index(s.size());
        sliding_ = !s.wallVelocity.empty();
        x_.upload(s.x), v_.upload(s.v), a_.upload(s.a), m_.upload(s.m), rho_.upload(s.rho);
        drho_.upload(s.drho), p_.upload(s.p), nu_.upload(s.nu), kernelSum_.upload(s.kernelSum);
        surfaceNeighbours_.upload(s.surfaceNeighbours), kind_.upload(s.kind), slip_.upload(s.slip);
        if (sliding_) wallVelocity_.upload(s.wallVelocity);
        bodies_.upload(s);
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
        // The powers: written by every evaluation's heat pass before heatPowers() reads them.
        if (heat_ && c_.conduction)
            maxima_[3].resize(n_), fixedPower_.resize(n_), sourcePower_.resize(n_);
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
        if (sliding_) s.wallVelocity.resize(n_), fetch(wallVelocity_, s.wallVelocity);
        if (heat_) {
            s.T.resize(n_), s.dT.resize(n_), s.Tb.resize(n_);
            fetch(T_, s.T), fetch(dT_, s.dT), fetch(Tb_, s.Tb);
        }
    }

    void evaluate(Float t) override {
        constrain();
        sortByCell();
        const passes::Arrays<Dim> d = arrays();
        if (heat_ && c_.temperatureViscosity)
            exec_.forEach(n_, passes::TemperatureViscosityPass<Dim>{d, c_.viscosityLaw});
        const Vec g = c_.bodyForce ? c_.bodyForce(t) : Vec{};
        const Vec gravityTerm =
            c_.deltaHydrostatic && c_.bodyForce
                ? sph::formulas::deltaSphGravityTerm<Dim>(g, c_.eos.rho0, c_.eos.c0)
                : Vec{};
        sph::withKernel<Dim>(c_.kernel, [&](auto kernel) {
            using K = decltype(kernel);
            const sph::KernelValue<K> value(c_.h);
            if (c_.summation)
                exec_.forEach(n_, passes::SummationDensityPass<Dim, K>{
                                      d, grid_.grid(), grid_.start(), grid_.end(), value});
            exec_.forEach(n_,
                          passes::FluidPass<Dim>{d, c_.eos, c_.pMin, c_.w0, c_.surfacePMin,
                                                 c_.surfaceRhoMin, c_.tensionLimit, c_.summation});
            if (c_.walls)
                exec_.forEach(
                    n_, passes::WallPass<Dim, K>{d, grid_.grid(), grid_.start(), grid_.end(), value,
                                                 c_.eos, g, heat_ && c_.conduction});
            if (c_.outletPressure) imposeOutlets(d, value, t);
            exec_.forEach(n_, passes::InputsPass<Dim, K>{d, value, c_.w0});
            exec_.forEach(
                n_, passes::FluidGather<Dim, K>{
                        d, grid_.grid(), grid_.start(), grid_.end(), sph::GradientFactor<K>(c_.h),
                        value, c_.laplacianEta2, c_.inverseR2Eta2, c_.deltaCoefficient, c_.alphaC0h,
                        !c_.summation, c_.laminar, gravityTerm, g, heat_ && c_.buoyancy});
            if (heat_ && c_.conduction)
                exec_.forEach(
                    n_, passes::HeatPass<Dim, K>{d, grid_.grid(), grid_.start(), grid_.end(),
                                                 sph::GradientFactor<K>(c_.h), c_.laplacianEta2});
            // The moving bodies' loads (RigidBodyCoupling's finalize, in the last pass).
            bodies_.template sumLoads<K>(d, grid_.grid(), grid_.start(), grid_.end(),
                                         {true, c_.alphaC0h, c_.laplacianEta2, c_.inverseR2Eta2},
                                         c_.h, n_);
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

    HeatPowers heatPowers() override {
        if (!(heat_ && c_.conduction)) return {};
        return {exec_.sumOf(fixedPower_.data(), n_), exec_.sumOf(sourcePower_.data(), n_)};
    }

    sph::FluidExtent<Dim> fluidExtent() override {
        sph::FluidExtent<Dim> extent;
        if (n_ == 0) return extent;
        tempFloat_.resize(n_);
        for (int k = 0; k < Dim; ++k)
            for (const double sign : {1.0, -1.0}) {  // the largest of x_k, then of -x_k
                exec_.forEach(n_, passes::FluidCoordinate<Dim>{x_.data(), kind_.data(), k, sign,
                                                               tempFloat_.data()});
                const double most = exec_.maxOf(tempFloat_.data(), n_);
                (sign > 0 ? extent.max[k] : extent.min[k]) = sign * most;
            }
        return extent;
    }

    void advance(Float t, Float dt) override {
        exec_.forEach(n_, passes::KickDrift<Dim>{arrays(), dt});
        evaluate(t + dt);
        exec_.forEach(n_, passes::Kick<Dim>{arrays(), dt});
    }

    void postStep(Float dt) override {
        // The moving bodies' particles placed (RigidBodyCoupling::postStep). The CPU places them
        // after shifting; the order does not matter, shifting moves fluid particles only.
        bodies_.place(arrays(), n_);
        if (!c_.shifting && !c_.contain) return;
        passes::PostStep<Dim> post{arrays(),
                                   c_.shifting,
                                   c_.shiftingNormalToWalls,
                                   !c_.summation,
                                   c_.contain,
                                   c_.shiftingCoefficient * c_.h * c_.eos.c0 * dt,
                                   0.1 * c_.h,
                                   c_.w0,
                                   c_.domainMin,
                                   c_.domainMax,
                                   {},
                                   {},
                                   solids_.data(),
                                   int(c_.solids.solids.size()),
                                   flatNodes_.data(),
                                   flatValues_.data(),
                                   {},
                                   bodies_.frames()};
        for (int k = 0; k < Dim; ++k) {
            post.wallLow[k] = c_.wallLow[k], post.wallHigh[k] = c_.wallHigh[k];
            post.openings[k][0] = c_.outlets[k][0], post.openings[k][1] = c_.outlets[k][1];
        }
        exec_.forEach(n_, post);
    }

    void setBodies(const DeviceBodies<Dim>& b) override { bodies_.set(b); }
    void bodyLoads(BodyLoads<Dim>& loads) override { bodies_.loads(loads); }

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
             tempIndex_.bytes() + active_.bytes() + atSurface_.bytes() + solids_.bytes();
        b += flatNodes_.bytes() + flatValues_.bytes();
        for (const auto* f : {&T_, &dT_, &dTOld_, &Tb_, &heatSource_}) b += f->bytes();
        b += material_.bytes() + condition_.bytes() + materials_.bytes();
        b += fixedPower_.bytes() + sourcePower_.bytes() + outletP_.bytes() + bodies_.bytes();
        return b;
    }
    const char* execution() const override { return Exec::name(); }

  private:
    /// The state constraints (sph::Solver::constrain): periodic positions wrapped into the
    /// domain, the density floor at free surfaces.
    void constrain() {
        const passes::Arrays<Dim> d = arrays();
        if (anyPeriodic()) {
            passes::Wrap<Dim> wrap{d.x, c_.domainMin, c_.domainMax, {}};
            for (int k = 0; k < Dim; ++k) wrap.periodic[k] = c_.periodic[k];
            exec_.forEach(n_, wrap);
        }
        if (c_.tensionLimit && !c_.summation)  // with summation: after it (FluidPass)
            exec_.forEach(n_, passes::DensityFloorPass<Dim>{d, c_.w0, c_.surfaceRhoMin});
    }

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
        d.fixedPower = fixedPower_.data(), d.sourcePower = sourcePower_.data();
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
        bodies_.permute(permute, tempInt_, tempVec_);
        permute(origin_, tempIndex_);
    }

    /// The outlets' condition (outlet_pass.hpp): p_out(x, t) is an expression of the scene, so
    /// the positions and kinds come to the host, which evaluates it at each outlet particle.
    template <class K>
    void imposeOutlets(const passes::Arrays<Dim>& d, const sph::KernelValue<K>& value, Float t) {
        hostX_.resize(n_), hostKind_.resize(n_), hostP_.assign(n_, 0.0);
        exec_.download(hostX_.data(), x_.data(), n_);
        exec_.download(hostKind_.data(), kind_.data(), n_);
        for (Index i = 0; i < n_; ++i)
            if (hostKind_[i] == passes::outlet) hostP_[i] = c_.outletPressure(hostX_[i], t);
        outletP_.upload(hostP_);
        tempVec_.resize(n_);
        exec_.forEach(n_,
                      passes::OutletPass<Dim, K>{d, grid_.grid(), grid_.start(), grid_.end(), value,
                                                 c_.eos, outletP_.data(), tempVec_.data()});
        exec_.copy(v_.data(), tempVec_.data(), n_);
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
    Buffer<ContainmentSolid<Dim>, Exec> solids_;
    Buffer<geometry::FlatNode, Exec> flatNodes_;
    Buffer<double, Exec> flatValues_;
    bool heat_ = false;  // temperature on the device (the config's heat and the particles')
    Buffer<Float, Exec> T_, dT_, dTOld_, Tb_, heatSource_;
    Buffer<int, Exec> material_, condition_;
    Buffer<DeviceMaterial, Exec> materials_;
    Buffer<Float, Exec> fixedPower_, sourcePower_;  // each particle's, for the heat books
    Buffer<Float, Exec> outletP_;                   // the outlets' pressure p_out (0 elsewhere)
    BodyParticles<Dim, Exec> bodies_;               // the moving bodies' (device/body_step.hpp)
    std::vector<Vec> hostX_;  // the positions and kinds the host evaluates p_out at
    std::vector<int> hostKind_;
    std::vector<Float> hostP_;
    std::vector<unsigned char> tempHost_;
    std::vector<Index> originHost_;
};

}  // namespace num::device
