// The tension limit at free surfaces (sph/terms/free_surface.hpp): where a fluid particle's
// kernel support is cut (kernel sum C_i < 0.9), density below f rho0 is raised to f rho0 and
// pressure to p(f rho0); compressed surface particles, particles inside the fluid and boundary
// particles are left as they are.
#include <gtest/gtest.h>

#include <vector>

#include "numerics.hpp"
#include "sph/terms/free_surface.hpp"
#include "test_physics.hpp"

namespace {

using namespace num::sph;

struct Particle {
    ParticleKind kind;
    Float kernelSum;  ///< C_i of the previous evaluation less the particle's own term
    Float density;
};

/// The particles' storage, pressures from the equation of state, density of order `order`.
Storage<2> surfaceParticles(const std::vector<Particle>& particles, const EquationOfState& eos,
                            OrderEnum order) {
    Storage<2> s;
    std::vector<Vector<2>> x(particles.size());
    std::vector<int> kind;
    std::vector<Float> c, rho, p, m;
    for (const Particle& q : particles) {
        kind.push_back(int(q.kind)), c.push_back(q.kernelSum), rho.push_back(q.density);
        p.push_back(eos.pressure(q.density)), m.push_back(1e-9);  // tiny volume: C_i = the sum
    }
    s.insert<Vector<2>>(QuantityId::POSITION, OrderEnum::SECOND, x);
    s.insert<int>(QuantityId::KIND, OrderEnum::ZERO, kind);
    s.insert<Float>(QuantityId::MASS, OrderEnum::ZERO, m);
    s.insert<Float>(QuantityId::DENSITY, order, rho);
    s.insert<Float>(QuantityId::PRESSURE, OrderEnum::ZERO, p);
    s.insert<Float>(FluidId::KERNEL_SUM, OrderEnum::ZERO, c);
    return s;
}

FreeSurfaceTensionLimit<2> limitWithFloor(Float floor, const EquationOfState& eos) {
    FreeSurfaceTensionLimit<2> limit(eos, floor);
    DerivativeHolder<2> derivatives;
    RunSettings settings;
    settings.set("smoothing_length", 0.01);
    limit.setDerivatives(derivatives, settings);
    return limit;
}

/// The particles after the limit with density floor `floor` (the constraint on the evolved
/// density, then the term's initialize), as (density, pressure) pairs.
std::vector<std::pair<Float, Float>> limited(const std::vector<Particle>& particles, Float floor,
                                             const EquationOfState& eos) {
    Storage<2> s = surfaceParticles(particles, eos, OrderEnum::FIRST);
    FreeSurfaceTensionLimit<2> limit = limitWithFloor(floor, eos);
    SequentialScheduler scheduler;
    limit.constrain(scheduler, s);
    limit.initialize(scheduler, s, 0.0);
    return enginetest::densityAndPressure(s);
}

TEST(FreeSurfaceTensionLimit, RaisesOnlyThinnedSurfaceParticlesToTheFloor) {
    EquationOfState eos;  // Tait, rho0 1000, c0 10
    eos.backgroundPressure = 50;
    const std::vector<Particle> particles = {
        {ParticleKind::FLUID, 0.5, 950},   // at the surface, thinned: raised to the floor
        {ParticleKind::FLUID, 0.5, 995},   // at the surface, above the floor: kept
        {ParticleKind::FLUID, 0.5, 1020},  // at the surface, compressed: kept
        {ParticleKind::FLUID, 1.0, 950},   // inside the fluid: kept (closed flows' tension)
        {ParticleKind::WALL, 0.5, 950},    // a boundary particle: kept
    };
    const auto out = limited(particles, 0.99, eos);
    EXPECT_DOUBLE_EQ(out[0].first, 990);
    EXPECT_DOUBLE_EQ(out[0].second, eos.pressure(990));
    // The tension allowed: p(0.99 rho0) - p_b = -(1 - 0.99^7) rho0 c0^2 / 7, about -0.01 rho0 c0^2.
    EXPECT_NEAR(out[0].second - 50, -0.0097 * 1000 * 100, 0.0001 * 1000 * 100);
    for (Size i = 1; i < particles.size(); ++i) {
        EXPECT_EQ(out[i].first, particles[i].density) << i;
        EXPECT_EQ(out[i].second, eos.pressure(particles[i].density)) << i;
    }
}

TEST(FreeSurfaceTensionLimit, FloorOneAllowsNoTension) {
    EquationOfState eos;
    eos.backgroundPressure = 50;
    const auto out = limited({{ParticleKind::FLUID, 0.5, 995}}, 1.0, eos);
    EXPECT_DOUBLE_EQ(out[0].first, 1000);
    EXPECT_DOUBLE_EQ(out[0].second, 50);  // the background (ambient) pressure
}

/// An evolved density (continuity) is floored by the constraint before each evaluation, never in
/// the evaluation; a density computed in each evaluation (summation) is floored in initialize.
TEST(FreeSurfaceTensionLimit, FloorsAnEvolvedDensityOnlyAsAConstraint) {
    EquationOfState eos;
    const std::vector<Particle> thinned = {{ParticleKind::FLUID, 0.5, 950}};
    const FreeSurfaceTensionLimit<2> limit = limitWithFloor(0.99, eos);
    SequentialScheduler scheduler;

    Storage<2> evolved = surfaceParticles(thinned, eos, OrderEnum::FIRST);
    FreeSurfaceTensionLimit<2>(limit).initialize(scheduler, evolved, 0.0);
    EXPECT_EQ(enginetest::densityAndPressure(evolved)[0].first, 950) << "initialize kept it";
    EXPECT_EQ(enginetest::densityAndPressure(evolved)[0].second, eos.pressure(990));
    Storage<2> constrained = surfaceParticles(thinned, eos, OrderEnum::FIRST);
    FreeSurfaceTensionLimit<2>(limit).constrain(scheduler, constrained);
    EXPECT_EQ(enginetest::densityAndPressure(constrained)[0].first, 990);
    EXPECT_EQ(enginetest::densityAndPressure(constrained)[0].second, eos.pressure(950))
        << "the constraint leaves the pressure to the evaluation";

    Storage<2> computed = surfaceParticles(thinned, eos, OrderEnum::ZERO);
    FreeSurfaceTensionLimit<2>(limit).constrain(scheduler, computed);
    EXPECT_EQ(enginetest::densityAndPressure(computed)[0].first, 950) << "not a constraint";
    FreeSurfaceTensionLimit<2>(limit).initialize(scheduler, computed, 0.0);
    EXPECT_EQ(enginetest::densityAndPressure(computed)[0].first, 990);
    EXPECT_EQ(enginetest::densityAndPressure(computed)[0].second, eos.pressure(990));
}

}  // namespace
