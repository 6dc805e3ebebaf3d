// Validation: a warm blob in cold water rises (Boussinesq buoyancy in the full fluid model).
//
// Set-up: 2D, water at rest in a periodic square box of side L, a disc of radius R at
// T0 + dT, the rest at T0; buoyancy -beta (T - T0) g alone (reduced gravity: the hydrostatic
// part rho0 g is balanced and left out), ramped in over t_r. Nothing has moved yet at early
// times, so the force density is f = rho0 beta dT g_up inside the disc and 0 outside.
//
// Estimate (derived here). For incompressible, inviscid flow started from rest, the
// acceleration is the divergence-free part of f / rho0 (the pressure takes the rest):
// a = P[f] / rho0. In free space, a uniform force on a disc projects to a uniform acceleration
// f / 2 inside it: the pressure solves lap p = div f = f . n delta(surface), whose interior
// solution is p = f . x / 2 (a disc "polarised" by a cos(theta) source); equivalently the disc
// accelerates like a cylinder with its added mass, 1 / (1 + C_a), C_a = 1. In the periodic box,
// write f = f phi + f (chi - phi) with phi = pi R^2 / L^2: the uniform part has no divergence
// and is kept whole; the zero-mean part projects to (1 - phi) f / 2 inside the disc, because
// on a square lattice the images' dipole fields cancel at the disc to O(phi^4) (Rayleigh 1892;
// checked by a spectral projection on a 1024^2 grid: 0.4843 for R / L = 0.1, against
// (1 - phi) / 2 = 0.4843). So the disc's mean acceleration is
//     a_blob = beta dT g (1 + phi) / 2,
// and with the ramp s(t) = (1 - cos(pi t / t_r)) / 2, v_blob(t) = a_blob int_0^t s.
// It holds while (i) the fluid is effectively incompressible: acoustic time R / c0 << t_r;
// (ii) viscosity is negligible: sqrt(nu t) << R; (iii) the blob has not moved: a t^2 / 2 << R.
// Here R / c0 = 0.02 s against t_r = 0.2 s, sqrt(nu t) = 1e-3 m = R / 100, displacement
// 5e-3 m = R / 20: each leaves an error of a few per cent at most, hence the 10 % gate.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sph/fluid_model.hpp"
#include "test_heat_common.hpp"

using namespace num;
using namespace num::sph;
using namespace num::sph::heat_test;

namespace {

const double L = 1, R = 0.1, T0 = 20, dT = 10, beta = 2e-4, g = 9.81;
const double rampTime = 0.2, tEnd = 1.0, c0 = 5, nu = 1e-6;
const Vector<2> centre{{0.5 * L, 0.5 * L}};
// Marks the blob's particles (reordering by cell carries the tag along).
const QuantityId tagId = QuantityId(-401);

/// Water with conduction and the ramped Boussinesq force alone.
FluidModel<2> blobModel() {
    FluidModel<2> model;
    model.restDensity = 1000;
    model.soundSpeed = c0;
    model.viscosity = nu;
    auto water = std::make_shared<Material>("water");
    water->params()
        .set("density", 1000.0)
        .set("viscosity", nu)
        .set("thermal_expansion", beta)
        .set("reference_temperature", T0);
    model.materials = {water};
    model.heat.conduction = true;  // water's alpha = 1.4e-7 m^2/s: the blob stays sharp
    const BodyForce<2> gravity = rampedForce(Vector<2>{{0, -g}}, rampTime);
    model.extraTerms += makeTerm<BoussinesqBuoyancy<2>>(gravity);
    return model;
}

/// The periodic box: the warm disc first, the cold water around it.
FluidGeometry<2> blobGeometry(double dx) {
    FluidGeometry<2> geo;
    geo.domain.min = {{0, 0}};
    geo.domain.max = {{L, L}};
    geo.domain.periodic = {true, true};
    geo.spacing = dx;
    geo.fluid.push_back(FluidRegion<2>::filling(BoxOrBall<2>::ball(centre, R), T0 + dT));
    geo.fluid.push_back(
        FluidRegion<2>::filling(BoxOrBall<2>::box(geo.domain.min, geo.domain.max), T0));
    return geo;
}

/// Tags the warm particles with tagId; returns the tags.
std::vector<int> tagBlob(Storage<2>& s) {
    std::vector<int> tag(s.size());
    const auto T = s.getValue<double>(QuantityId::TEMPERATURE);
    for (Size i = 0; i < s.size(); ++i) tag[i] = T[i] > T0 + 0.5 * dT;
    s.insert<int>(tagId, OrderEnum::ZERO, tag);
    return tag;
}

/// int_0^t s, with the ramp s(t) = (1 - cos(pi t / t_r)) / 2.
double rampIntegral(double t) {
    if (t >= rampTime) return t - rampTime / 2;
    return t / 2 - rampTime / (2 * std::numbers::pi) * std::sin(std::numbers::pi * t / rampTime);
}

/// The mean vertical velocity of the tagged particles.
double blobVelocity(const Storage<2>& s, double blobCount) {
    const auto v = s.getDt<Vector<2>>(QuantityId::POSITION);
    const auto tg = s.getValue<int>(tagId);
    double sum = 0;
    for (Size i = 0; i < s.size(); ++i)
        if (tg[i]) sum += v[i][1];
    return sum / blobCount;
}

/// The largest deviation over the samples after the ramp (early: all small velocities).
double largestAfterRamp(const std::vector<ProfileRow>& profile) {
    double maxLate = 0;
    for (const ProfileRow& r : profile)
        if (r.coordinate >= rampTime)
            maxLate = std::max(maxLate, std::abs(r.numeric - r.analytic) / r.analytic);
    return maxLate;
}

}  // namespace

TEST(HeatBuoyancy, WarmBlobRisesAtBoussinesqRate) {
    const double dx = fullResolution() ? 0.01 : 0.02;
    const FluidModel<2> model = blobModel();
    const FluidGeometry<2> geo = blobGeometry(dx);
    RunSettings settings;
    settings.set("kernel", "cubic_spline").set("smoothing_length", 1.3 * dx);
    Storage<2> s = makeFluidStorage(model, geo, settings);
    const std::vector<int> tag = tagBlob(s);

    SequentialScheduler scheduler;
    Solver<2> solver(scheduler, settings, makeFluidEquations(model, geo), geo.domain);
    LeapfrogKDK<2> integrator;
    sph::Run<2> run(s, solver, integrator);

    const double blobCount = std::count(tag.begin(), tag.end(), 1);
    const double phi = blobCount / double(s.size());
    const double aBlob = beta * dT * g * (1 + phi) / 2;
    ValidationResult result;
    result.name = "heat_buoyancy_blob";
    const int samples = 20;
    for (int k = 1; k <= samples; ++k) {
        const double t = tEnd * k / samples;
        run.advanceTo(t);
        result.profile.push_back({t, blobVelocity(s, blobCount), aBlob * rampIntegral(t), t});
    }
    const double vNum = result.profile.back().numeric, vEst = result.profile.back().analytic;
    const double relErr = std::abs(vNum - vEst) / vEst;
    const double maxLate = largestAfterRamp(result.profile);

    result.resolution = std::to_string(int(std::lround(L / dx))) +
                        "^2 (R = " + std::to_string(int(std::lround(R / dx))) + " dx)";
    result.error = relErr;
    result.tolerance = 0.1;
    result.passed = relErr < 0.1 && maxLate < 0.1;
    std::ostringstream notes;
    notes << "relative error of the blob's mean vertical velocity at t = " << tEnd
          << " s against beta dT g (1 + phi) / 2 int s dt (phi = " << phi
          << "); largest after the ramp " << maxLate << "; " << run.steps() << " steps";
    result.notes = notes.str();
    result.write();

    EXPECT_GT(vNum, 0) << "the warm blob must rise";
    // Gate: the Boussinesq estimate above within 10 % (its own error is a few per cent).
    EXPECT_LT(relErr, 0.1);
    EXPECT_LT(maxLate, 0.1);
}
