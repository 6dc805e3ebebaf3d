// Inlets and outlets (sph/boundary/flow_boundaries.hpp): the exchange of particles between the
// buffers and the fluid after a step, its books and ids, and the buffers the set-up makes.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "sph/boundary/flow_boundaries.hpp"
#include "sph/setup/particle_generation.hpp"

using namespace num;
using namespace num::sph;

namespace {

using V2 = Vector<2>;
constexpr double kMass = 0.25, kDepth = 0.3;

/// An inlet at x = 0 (velocity (2, 0), temperature 60) and an outlet at x = 1 (pressure 5).
FlowBoundaries<2> channel() {
    FlowBoundaries<2> flow;
    FlowSide<2> in;
    in.kind = ParticleKind::INLET, in.axis = 0, in.high = 0, in.plane = 0, in.depth = kDepth;
    in.velocity = [](const V2&, Float) { return V2{{2.0, 0.0}}; };
    in.temperature = [](const V2&, Float) { return 60.0; };
    FlowSide<2> out;
    out.kind = ParticleKind::OUTLET, out.axis = 0, out.high = 1, out.plane = 1, out.depth = kDepth;
    out.pressure = [](const V2&, Float) { return 5.0; };
    flow.sides = {in, out};
    return flow;
}

/// Particles at the given x (y = 0.5) of the given kinds, ids 0, 1, ..., at rest, T = 20.
Storage<2> particles(const std::vector<double>& xs, const std::vector<ParticleKind>& kinds) {
    Storage<2> s;
    std::vector<V2> x;
    std::vector<int> kind;
    for (std::size_t i = 0; i < xs.size(); ++i)
        x.push_back(V2{{xs[i], 0.5}}), kind.push_back(int(kinds[i]));
    s.insert<V2>(QuantityId::POSITION, OrderEnum::SECOND, x);
    s.insert<Float>(QuantityId::MASS, OrderEnum::ZERO, kMass);
    s.insert<Float>(QuantityId::TEMPERATURE, OrderEnum::FIRST, 20.0);
    s.insert<int>(QuantityId::KIND, OrderEnum::ZERO, kind);
    ensureParticleIds(s);
    auto water = std::make_shared<Material>("water");
    water->params().set("heat_capacity", 4000.0);
    s.materials() = {water};
    return s;
}

}  // namespace

// An inlet particle past the side becomes fluid; a copy takes its place one buffer depth behind,
// with the next id and the inlet's velocity and temperature; one still in the buffer takes the
// inlet's values of the new time.
TEST(FlowBoundaries, AnInletParticlePastItsSideIsReplacedBehindIt) {
    FlowBoundaries<2> flow = channel();
    Storage<2> s = particles({0.01, -0.15, 0.5},
                             {ParticleKind::INLET, ParticleKind::INLET, ParticleKind::FLUID});
    ASSERT_TRUE(flow.exchange(s, 0.1, 100));
    ASSERT_EQ(s.size(), 4u);
    const auto kind = s.getValue<int>(QuantityId::KIND);
    const auto x = s.getValue<V2>(QuantityId::POSITION);
    const auto v = s.getDt<V2>(QuantityId::POSITION);
    const auto id = s.getValue<int>(QuantityId::PARTICLE_ID);
    const auto T = s.getValue<Float>(QuantityId::TEMPERATURE);
    EXPECT_EQ(kind[0], int(ParticleKind::FLUID));
    EXPECT_EQ(kind[1], int(ParticleKind::INLET));
    EXPECT_EQ(v[1][0], 2.0);
    EXPECT_EQ(T[1], 60.0);
    EXPECT_EQ(kind[3], int(ParticleKind::INLET));
    EXPECT_DOUBLE_EQ(x[3][0], 0.01 - kDepth);
    EXPECT_EQ(x[3][1], 0.5);
    EXPECT_EQ(id[3], 100);
    EXPECT_EQ(s.getValue<int>(QuantityId::ORDER_KEY)[3], kNewParticleKey);
    EXPECT_EQ(flow.books.massIn, kMass);
    EXPECT_EQ(flow.books.heatIn, kMass * 4000 * 20);
    EXPECT_EQ(flow.books.created, 1u);
}

// Fluid past the outlet becomes an outlet particle, one carried back in becomes fluid again (and
// comes off the books), one past the buffer is removed.
TEST(FlowBoundaries, OutletParticlesComeGoAndLeave) {
    FlowBoundaries<2> flow = channel();
    Storage<2> s = particles(
        {1.02, 0.99, 1.0 + kDepth + 0.01, 0.5},
        {ParticleKind::FLUID, ParticleKind::OUTLET, ParticleKind::OUTLET, ParticleKind::FLUID});
    ASSERT_TRUE(flow.exchange(s, 0.1, 100));
    ASSERT_EQ(s.size(), 3u);
    const auto kind = s.getValue<int>(QuantityId::KIND);
    const auto id = s.getValue<int>(QuantityId::PARTICLE_ID);
    EXPECT_EQ(std::vector<int>(id.begin(), id.end()), (std::vector<int>{0, 1, 3}));
    EXPECT_EQ(kind[0], int(ParticleKind::OUTLET));
    EXPECT_EQ(kind[1], int(ParticleKind::FLUID));
    EXPECT_EQ(kind[2], int(ParticleKind::FLUID));
    EXPECT_EQ(flow.books.massOut, 0.0);  // one out, one back in
    EXPECT_EQ(flow.books.dropped, 1u);
    EXPECT_FALSE(flow.exchange(s, 0.2, 100));  // nothing crossed since
}

// Over many steps of steady flow the fluid's mass is start + in - out exactly, and every id is
// used once.
TEST(FlowBoundaries, TheBooksCloseAndIdsAreUnique) {
    FlowBoundaries<2> flow = channel();
    std::vector<double> xs;
    std::vector<ParticleKind> kinds;
    for (int k = 0; k < 30; ++k)  // a buffer 0.3 deep, a channel 1 long, an outlet 0.3 deep
        xs.push_back(-0.3 + 0.05 + 0.1 * k), kinds.push_back(k < 3    ? ParticleKind::INLET
                                                             : k < 13 ? ParticleKind::FLUID
                                                                      : ParticleKind::OUTLET);
    xs.resize(16), kinds.resize(16);
    Storage<2> s = particles(xs, kinds);
    auto fluidMass = [&] {
        const auto kind = s.getValue<int>(QuantityId::KIND);
        return kMass * double(std::count(kind.begin(), kind.end(), int(ParticleKind::FLUID)));
    };
    const double start = fluidMass();
    std::int64_t next = std::int64_t(s.size());
    for (int step = 1; step <= 100; ++step) {
        auto x = s.getValue<V2>(QuantityId::POSITION);
        for (Size i = 0; i < s.size(); ++i) x[i][0] += 0.037;  // the flow moves every particle
        flow.exchange(s, 0.01 * step, next);
        next = 16 + std::int64_t(flow.books.created);
    }
    EXPECT_NEAR(fluidMass(), start + flow.books.massIn - flow.books.massOut, 1e-12);
    EXPECT_GT(flow.books.created, 30u);
    const auto id = s.getValue<int>(QuantityId::PARTICLE_ID);
    EXPECT_EQ(std::set<int>(id.begin(), id.end()).size(), s.size());
}

// The layers beyond an inlet's side are its buffer across the opening and wall beside it, and
// wall where a pipe's wall meets the side.
TEST(FlowBoundaries, TheBufferFillsTheOpeningWhereWaterReachesTheSide) {
    FluidGeometry<2> g;
    g.spacing = 0.1;
    g.domain.min = V2{{0, 0}}, g.domain.max = V2{{1, 1}};
    g.walls[0][0].layers = ParticleKind::INLET;
    g.walls[0][0].openFrom = V2{{0, 0.2}}, g.walls[0][0].openTo = V2{{0, 0.8}};
    InteriorWall<2> plate;
    plate.shape = BoxOrBall<2>::box(V2{{0, 0.6}}, V2{{1, 0.8}});
    g.interiorWalls.push_back(plate);
    int inlet = 0, wallBeyond = 0;
    for (const auto& p : generateParticles(g, 2)) {
        if (p.x[0] > 0 || p.x[1] < 0 || p.x[1] > 1) continue;  // beyond x_min only
        const bool open = p.x[1] > 0.2 && p.x[1] < 0.6;
        EXPECT_EQ(p.kind, open ? ParticleKind::INLET : ParticleKind::WALL) << p.x[1];
        (open ? inlet : wallBeyond)++;
    }
    EXPECT_EQ(inlet, 2 * 4);
    EXPECT_EQ(wallBeyond, 2 * 6);
}
