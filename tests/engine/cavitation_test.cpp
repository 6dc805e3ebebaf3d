// The cavitation limit of the equation of state term (sph/terms/equation_of_state.hpp): a fluid
// particle's pressure is p(rho) but never below p_b - T_max; its density is left as it is, and
// boundary particles (whose pressure the wall condition sets) are not touched.
#include <gtest/gtest.h>

#include <vector>

#include "numerics.hpp"
#include "sph/defaults.hpp"
#include "sph/fluid_model.hpp"
#include "sph/terms/equation_of_state.hpp"
#include "test_physics.hpp"

namespace {

using namespace num::sph;

struct Particle {
    ParticleKind kind;
    Float density;
};

/// (density, pressure) of each particle after `term`; boundary particles start at pressure -1.
std::vector<std::pair<Float, Float>> applied(const std::vector<Particle>& particles,
                                             EquationOfStateTerm<2> term) {
    Storage<2> s;
    std::vector<Vector<2>> x(particles.size());
    std::vector<int> kind;
    std::vector<Float> rho, p;
    for (const Particle& q : particles)
        kind.push_back(int(q.kind)), rho.push_back(q.density), p.push_back(-1);
    s.insert<Vector<2>>(QuantityId::POSITION, OrderEnum::SECOND, x);
    s.insert<int>(QuantityId::KIND, OrderEnum::ZERO, kind);
    s.insert<Float>(QuantityId::DENSITY, OrderEnum::FIRST, rho);
    s.insert<Float>(QuantityId::PRESSURE, OrderEnum::ZERO, p);
    SequentialScheduler scheduler;
    term.initialize(scheduler, s, 0.0);
    return enginetest::densityAndPressure(s);
}

// The default 2D scene's equation of state: c0 = 56 m/s, B = rho0 c0^2 / 7 = 448 kPa, so that
// water stretched by 3.5 % reaches the default limit, 98,986 Pa below ambient.
EquationOfState fastWater() {
    EquationOfState eos;
    eos.c0 = 56;
    eos.backgroundPressure = 2000;
    return eos;
}

TEST(Cavitation, HoldsStretchedWaterAtTheTensionLimit) {
    const EquationOfState eos = fastWater();
    const Float limit = defaults::maxTension;
    const std::vector<Particle> particles = {
        {ParticleKind::FLUID, 900},   // stretched 10 %: p(rho) = -234 kPa, held at -98,986 Pa
        {ParticleKind::FLUID, 990},   // stretched 1 %: -30 kPa, within the limit
        {ParticleKind::FLUID, 1010},  // compressed: as the equation of state says
        {ParticleKind::WALL, 900},    // a boundary particle: its pressure is the wall's to set
    };
    ASSERT_LT(eos.pressure(900), eos.backgroundPressure - limit);
    const auto out = applied(particles, EquationOfStateTerm<2>(eos, limit));
    EXPECT_DOUBLE_EQ(out[0].second, eos.backgroundPressure - limit);
    EXPECT_EQ(out[1].second, eos.pressure(990));
    EXPECT_EQ(out[2].second, eos.pressure(1010));
    EXPECT_EQ(out[3].second, -1);
    for (Size i = 0; i < particles.size(); ++i) EXPECT_EQ(out[i].first, particles[i].density) << i;
}

TEST(Cavitation, NoLimitByDefaultOfTheTerm) {
    // The term alone (as the engine examples build it) applies the equation of state unlimited;
    // FluidModel passes the default limit.
    const EquationOfState eos = fastWater();
    const auto out = applied({{ParticleKind::FLUID, 900}}, EquationOfStateTerm<2>(eos));
    EXPECT_EQ(out[0].second, eos.pressure(900));
    EXPECT_EQ(FluidModel<2>().maxTension, defaults::maxTension);
}

}  // namespace
