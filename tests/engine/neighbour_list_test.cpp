// The Verlet neighbour lists against a brute-force oracle (every particle's neighbours, in
// increasing index, bit for bit), in 2D and 3D with periodic axes, after displacements below
// half the skin (lists kept) and above (rebuilt), after a renumbering, with candidates far apart
// in index, with a skin that adapts to the fastest particle; every particle's candidates after
// a build, for particles numbered by cell or at random; and a short fluid run that is bitwise
// the same for any skin (fixed or adapting) and any number of threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <numeric>
#include <random>
#include <thread>
#include <vector>

#include "numerics.hpp"
#include "spatial/neighbour_list.hpp"
#include "sph/fluid_model.hpp"

namespace {

template <int Dim>
using V = num::Vec<double, Dim>;

struct Pair {
    std::uint32_t j;
    V<3> dx;  // padded to 3 components, so that one type serves every Dim
    bool operator==(const Pair&) const = default;
};

template <int Dim>
V<3> pad(const V<Dim>& v) {
    V<3> p{};
    for (int k = 0; k < Dim; ++k) p[k] = v[k];
    return p;
}

/// Every j with |x_i - x_j| < radius (nearest image on periodic axes), in increasing j.
template <int Dim>
std::vector<Pair> oracle(const std::vector<V<Dim>>& x, std::uint32_t i, double radius,
                         const num::Domain<Dim>& d) {
    std::vector<Pair> out;
    for (std::uint32_t j = 0; j < x.size(); ++j) {
        V<Dim> dx = x[i] - x[j];
        for (int k = 0; k < Dim; ++k)
            if (d.periodic[k]) dx[k] -= d.length(k) * std::round(dx[k] / d.length(k));
        if (normSqr(dx) < radius * radius) out.push_back({j, pad<Dim>(dx)});
    }
    return out;
}

/// Right after a build, every particle's candidates are the oracle's particles within the
/// lists' radius, in strictly increasing index (the build sorts the candidates the cell grid
/// returns cell by cell). Pairs within 1e-9 of that radius may go either way (the grid rounds
/// its distances otherwise).
template <int Dim>
void expectCandidates(const num::VerletList<Dim>& list, const std::vector<V<Dim>>& x,
                      const num::Domain<Dim>& d) {
    const double outer = list.listRadius() * (1 + 1e-9), inner = list.listRadius() * (1 - 1e-9);
    for (std::uint32_t i = 0; i < x.size(); ++i) {
        const std::vector<std::uint32_t> found = list.candidates(i);
        ASSERT_EQ(std::adjacent_find(found.begin(), found.end(), std::greater_equal<>()),
                  found.end())
            << "particle " << i << ": candidates not in strictly increasing order";
        std::vector<std::uint32_t> expected, allowed;
        for (const Pair& p : oracle(x, i, outer, d)) allowed.push_back(p.j);
        for (const Pair& p : oracle(x, i, inner, d)) expected.push_back(p.j);
        ASSERT_TRUE(std::includes(found.begin(), found.end(), expected.begin(), expected.end()))
            << "particle " << i << ": a particle within the lists' radius is missing";
        ASSERT_TRUE(std::includes(allowed.begin(), allowed.end(), found.begin(), found.end()))
            << "particle " << i << ": a candidate beyond the lists' radius";
    }
}

/// Every query of the lists (forEachNeighbourOf, collect, collectAfter) gives the oracle's
/// neighbours, in its order, with its pair vectors bit for bit.
template <int Dim>
void expectOracle(const num::VerletList<Dim>& list, const std::vector<V<Dim>>& x, double radius,
                  const num::Domain<Dim>& d) {
    typename num::VerletList<Dim>::Neighbours flat;
    std::size_t pairs = 0;
    for (std::uint32_t i = 0; i < x.size(); ++i) {
        const std::vector<Pair> expected = oracle(x, i, radius, d);
        pairs += expected.size();
        std::vector<Pair> found, others, after;
        list.forEachNeighbourOf(i, [&](std::uint32_t j, const V<Dim>& dx, double r2) {
            EXPECT_EQ(r2, normSqr(dx));
            found.push_back({j, pad<Dim>(dx)});
        });
        ASSERT_EQ(found, expected) << "particle " << i;
        std::vector<Pair> even, expectedEven;  // with a predicate on j: the others are skipped
        list.forEachNeighbourOf(
            i, [](std::uint32_t j) { return j % 2 == 0; },
            [&](std::uint32_t j, const V<Dim>& dx, double) {
                even.push_back({j, pad<Dim>(dx)});
            });
        for (const Pair& p : expected)
            if (p.j % 2 == 0) expectedEven.push_back(p);
        ASSERT_EQ(even, expectedEven) << "particle " << i;
        for (std::uint32_t k = 0, n = list.collect(i, flat); k < n; ++k)
            others.push_back({flat.j[k], pad<Dim>(flat.dx[k])});
        for (std::uint32_t k = 0, n = list.collectAfter(i, flat); k < n; ++k)
            after.push_back({flat.j[k], pad<Dim>(flat.dx[k])});
        std::vector<Pair> expectedOthers, expectedAfter;
        for (const Pair& p : expected) {
            if (p.j != i) expectedOthers.push_back(p);
            if (p.j > i) expectedAfter.push_back(p);
        }
        ASSERT_EQ(others, expectedOthers) << "collect, particle " << i;
        ASSERT_EQ(after, expectedAfter) << "collectAfter, particle " << i;
    }
    EXPECT_GT(pairs, 8 * x.size()) << "a meaningful number of neighbours";
}

/// forEachNeighbourOf gives the oracle's neighbours, for a handful of particles.
template <int Dim>
void expectOracleOfFew(const num::VerletList<Dim>& list, const std::vector<V<Dim>>& x,
                       double radius, const num::Domain<Dim>& d) {
    for (std::uint32_t i = 0; i < x.size(); ++i) {
        std::vector<Pair> found;
        list.forEachNeighbourOf(i, [&](std::uint32_t j, const V<Dim>& dx, double) {
            found.push_back({j, pad<Dim>(dx)});
        });
        EXPECT_EQ(found, oracle(x, i, radius, d)) << "particle " << i;
    }
}

template <int Dim>
num::Domain<Dim> unitDomain(unsigned periodicMask) {
    num::Domain<Dim> d;
    d.min = V<Dim>::filled(0.0), d.max = V<Dim>::filled(1.0);
    for (int k = 0; k < Dim; ++k) d.periodic[k] = (periodicMask >> k) & 1;
    return d;
}

template <int Dim>
std::vector<V<Dim>> randomPositions(std::size_t n, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<V<Dim>> x(n);
    for (auto& p : x)
        for (int k = 0; k < Dim; ++k) p[k] = unit(rng);
    return x;
}

/// Moves every particle by a random displacement of length below `maxStep` (wrapped into the
/// domain on periodic axes: a particle may jump by a period).
template <int Dim>
void displace(std::vector<V<Dim>>& x, double maxStep, const num::Domain<Dim>& d,
              std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1, 1);
    for (auto& p : x) {
        V<Dim> s;
        for (int k = 0; k < Dim; ++k) s[k] = u(rng);
        p = d.wrap(p + s * (maxStep / std::sqrt(double(Dim))));
    }
}

template <int Dim>
void checkAgainstOracle(unsigned periodicMask) {
    SCOPED_TRACE(::testing::Message() << Dim << "D, periodic axes mask " << periodicMask);
    const num::Domain<Dim> d = unitDomain<Dim>(periodicMask);
    const double radius = Dim == 2 ? 0.06 : 0.12, skin = 0.25;
    std::mt19937_64 rng(17 + periodicMask);
    std::vector<V<Dim>> x = randomPositions<Dim>(Dim == 2 ? 1500 : 2000, rng);
    num::VerletList<Dim> list;
    list.configure(radius, skin, d);
    ASSERT_TRUE(list.update(x));
    expectCandidates(list, x, d);
    expectOracle(list, x, radius, d);

    // Below half the skin: the lists are kept and still give the oracle's neighbours.
    for (int round = 0; round < 3; ++round) {
        displace(x, 0.16 * skin * radius, d, rng);
        EXPECT_FALSE(list.update(x)) << "round " << round;
        expectOracle(list, x, radius, d);
    }
    EXPECT_EQ(list.builds(), 1u);
    // Above half the skin (one particle is enough): rebuilt.
    x[x.size() / 2] = d.wrap(x[x.size() / 2] + V<Dim>::filled(0.6 * skin * radius));
    EXPECT_TRUE(list.update(x));
    expectOracle(list, x, radius, d);
    displace(x, 2 * skin * radius, d, rng);
    EXPECT_TRUE(list.update(x));
    expectOracle(list, x, radius, d);
    EXPECT_EQ(list.builds(), 3u);

    // A renumbering: invalidate() rebuilds; the displacement test alone would too.
    std::vector<V<Dim>> shuffled = x;
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    EXPECT_TRUE(list.update(shuffled));
    expectCandidates(list, shuffled, d);  // neighbours far apart in index: many runs to merge
    expectOracle(list, shuffled, radius, d);
    list.invalidate();
    EXPECT_TRUE(list.update(shuffled));
    expectOracle(list, shuffled, radius, d);
    // Fewer particles: rebuilt.
    shuffled.resize(shuffled.size() - 100);
    EXPECT_TRUE(list.update(shuffled));
    expectOracle(list, shuffled, radius, d);

    // Skin 0: rebuilt at every update, same neighbours.
    list.configure(radius, 0, d);
    EXPECT_TRUE(list.update(shuffled));
    EXPECT_TRUE(list.update(shuffled));
    expectOracle(list, shuffled, radius, d);
}

TEST(VerletList, MatchesTheOracle2D) {
    for (unsigned mask = 0; mask < 4; ++mask) checkAgainstOracle<2>(mask);
}
TEST(VerletList, MatchesTheOracle3D) {
    for (unsigned mask : {0u, 1u, 6u, 7u}) checkAgainstOracle<3>(mask);
}

/// A build sorts each particle's candidates through a bitmap of their index range where that
/// range is short (particles numbered by cell, as a reordering leaves them) and by merging the
/// cell grid's runs where it is long (numbered at random; particles appended after a reordering,
/// as emitters add them): both give every particle's candidates in strictly increasing index.
template <int Dim>
void checkCandidatesForAnyNumbering() {
    SCOPED_TRACE(::testing::Message() << Dim << "D");
    const num::Domain<Dim> d = unitDomain<Dim>(0);
    const double radius = Dim == 2 ? 0.03 : 0.1;
    std::mt19937_64 rng(29);
    std::vector<V<Dim>> x = randomPositions<Dim>(6000, rng);
    // Numbered by cells of the radius, x fastest: a particle's candidates span a few rows.
    const auto cellKey = [&](const V<Dim>& p) {
        long key = 0;
        for (int k = Dim - 1; k >= 0; --k) key = key * 1000 + long(p[k] / radius);
        return key;
    };
    std::sort(x.begin(), x.end(),
              [&](const V<Dim>& a, const V<Dim>& b) { return cellKey(a) < cellKey(b); });
    num::VerletList<Dim> list;
    list.configure(radius, 0.25, d);
    ASSERT_TRUE(list.update(x));
    expectCandidates(list, x, d);
    // 60 particles moved to the end, as if added since the reordering.
    std::vector<V<Dim>> appended(x.begin() + 60, x.end());
    appended.insert(appended.end(), x.begin(), x.begin() + 60);
    ASSERT_TRUE(list.update(appended));
    expectCandidates(list, appended, d);
    expectOracleOfFew(list, appended, radius, d);
    // Numbered at random: ranges of about the particle count, each of tens of candidates.
    std::shuffle(x.begin(), x.end(), rng);
    ASSERT_TRUE(list.update(x));
    expectCandidates(list, x, d);
}

TEST(VerletList, CandidatesAreSortedForAnyNumbering) {
    checkCandidatesForAnyNumbering<2>();
    checkCandidatesForAnyNumbering<3>();
}

/// The positions of a build are kept in float: far from the origin their rounding (2^-24 of a
/// coordinate) takes a share of the skin, so the lists are rebuilt sooner, never missing a
/// neighbour.
TEST(VerletList, FloatPositionsOfTheBuildFarFromTheOrigin) {
    const double radius = 0.06, skin = 0.25;  // half the skin: 0.0075
    {
        // At 1e5 a float's spacing is u = 2^-7. Two particles 6 u + 0.0076 apart in x and y
        // (0.0770 > 0.075, the candidates' radius), each 0.0038 from a float: moved 0.0076
        // towards each other in x and y (0.0107 each, more than half the skin), each is
        // 0.0038 from its stored float in x and y (0.0054, less than half the skin), and they
        // are 0.0555 < radius apart. A test on the floats alone would keep the lists and miss
        // the pair.
        const double u = 0x1p-7, q = 1e5, off = 0.0038;
        num::Domain<2> d = unitDomain<2>(0);
        d.min = V<2>::filled(q - 1), d.max = V<2>::filled(q + 1);
        std::vector<V<2>> x = {V<2>::filled(q - off), V<2>::filled(q + 6 * u + off)};
        num::VerletList<2> list;
        list.configure(radius, skin, d);
        ASSERT_TRUE(list.update(x));
        ASSERT_TRUE(list.candidates(0) == std::vector<std::uint32_t>{0});
        x = {V<2>::filled(q + off), V<2>::filled(q + 6 * u - off)};
        ASSERT_LT(norm(x[1] - x[0]), radius);
        EXPECT_TRUE(list.update(x)) << "rebuilt: the particles moved more than half the skin";
        expectOracleOfFew(list, x, radius, d);
    }
    {
        // At 1e4 the rounding is up to 6e-4 per coordinate: small moves keep the lists.
        const double offset = 1e4;
        num::Domain<2> d = unitDomain<2>(0);
        d.min = V<2>::filled(offset), d.max = V<2>::filled(offset + 1);
        std::mt19937_64 rng(5);
        std::vector<V<2>> x = randomPositions<2>(1500, rng);
        for (auto& p : x) p += V<2>::filled(offset);
        num::VerletList<2> list;
        list.configure(radius, skin, d);
        ASSERT_TRUE(list.update(x));
        int kept = 0;
        for (int round = 0; round < 8; ++round) {
            displace(x, 0.05 * skin * radius, d, rng);
            kept += !list.update(x);
            expectOracle(list, x, radius, d);
        }
        EXPECT_GT(kept, 0) << "small moves keep the lists";
    }
}

/// An adaptive skin: each build takes the skin with which the lists would last kListUpdates
/// updates at the fastest particle's speed since the build before, within its range, and the
/// lists still give the oracle's neighbours.
template <int Dim>
void checkAdaptiveSkin() {
    SCOPED_TRACE(::testing::Message() << Dim << "D");
    const num::Domain<Dim> d = unitDomain<Dim>(0);
    const double radius = 0.1, minSkin = 0.1, maxSkin = 0.5;
    const double updates = num::VerletList<Dim>::kListUpdates;
    std::mt19937_64 rng(23);
    std::vector<V<Dim>> x = randomPositions<Dim>(Dim == 2 ? 1500 : 2000, rng);
    const std::size_t fast = x.size() / 3;
    x[fast] = V<Dim>::filled(0.5);  // it moves by 0.086 in x below, staying inside
    num::VerletList<Dim> list;
    list.configure(radius, minSkin, d, maxSkin);
    ASSERT_TRUE(list.update(x));
    EXPECT_DOUBLE_EQ(list.listRadius(), radius * (1 + minSkin)) << "no speed known: the least";

    // One particle at u = 0.002 per update, the rest at rest: half the skin (0.005, less the
    // margin for the build's float positions) is crossed at the third update, which rebuilds
    // with the skin for that speed: 2 u updates / radius = 0.32.
    const double u = 0.002;
    V<Dim> step{};
    step[0] = u;
    const V<Dim> start = x[fast];
    for (int k = 1; k <= 3; ++k) {
        x[fast] = start + step * double(k);
        EXPECT_EQ(list.update(x), k == 3) << "update " << k;
        expectOracle(list, x, radius, d);
    }
    // The displacement is measured from the build's float positions (2^-24 of a coordinate
    // off): the skin to 1e-5 of the radius.
    const double expected = radius * (1 + 2 * u * updates / radius);
    EXPECT_NEAR(list.listRadius(), expected, 1e-6) << "the skin for the speed";

    // Faster than the largest skin allows: rebuilt at once, with the largest.
    x[fast] = x[fast] + step * 20.0;
    EXPECT_TRUE(list.update(x));
    EXPECT_DOUBLE_EQ(list.listRadius(), radius * (1 + maxSkin));
    expectOracle(list, x, radius, d);

    // At rest, the next build (a renumbering) takes the least skin again.
    EXPECT_FALSE(list.update(x));
    list.invalidate();
    EXPECT_TRUE(list.update(x));
    EXPECT_DOUBLE_EQ(list.listRadius(), radius * (1 + minSkin));
    expectOracle(list, x, radius, d);

    // A range of one value is a fixed skin, whatever the speed.
    list.configure(radius, minSkin, d, minSkin / 2);
    ASSERT_TRUE(list.update(x));
    x[fast] = x[fast] + step * 20.0;
    EXPECT_TRUE(list.update(x));
    EXPECT_DOUBLE_EQ(list.listRadius(), radius * (1 + minSkin));
}

TEST(VerletList, AdaptiveSkinFollowsTheFastestParticle2D) { checkAdaptiveSkin<2>(); }
TEST(VerletList, AdaptiveSkinFollowsTheFastestParticle3D) { checkAdaptiveSkin<3>(); }

/// The candidates' radius is capped at half a short period, which narrows the skin there.
TEST(VerletList, ShortPeriodNarrowsTheSkin) {
    num::Domain<2> d = unitDomain<2>(1);
    d.max[0] = 0.25;
    std::mt19937_64 rng(3);
    std::vector<V<2>> x = randomPositions<2>(800, rng);
    for (auto& p : x) p[0] *= 0.25;
    num::VerletList<2> list;
    list.configure(0.1, 0.5, d);
    EXPECT_EQ(list.listRadius(), 0.125);
    list.update(x);
    expectOracle(list, x, 0.1, d);
    displace(x, 0.01, d, rng);
    EXPECT_FALSE(list.update(x));
    expectOracle(list, x, 0.1, d);
}

/// Runs body over [0, n) in chunks on several threads, the chunks in reverse order.
struct ReverseThreads {
    template <class Body>
    void operator()(std::size_t n, Body&& body) const {
        std::vector<std::thread> threads;
        for (std::size_t c = n; c-- > 0;) threads.emplace_back([&body, c] { body(c, c + 1); });
        for (auto& t : threads) t.join();
    }
};

TEST(VerletList, BuildIsTheSameOnAnyThreads) {
    const num::Domain<3> d = unitDomain<3>(5);
    std::mt19937_64 rng(11);
    const std::vector<V<3>> x = randomPositions<3>(3000, rng);
    num::VerletList<3> one, many;
    one.configure(0.1, 0.2, d), many.configure(0.1, 0.2, d);
    one.update(x);
    many.update(x, ReverseThreads{});
    for (std::uint32_t i = 0; i < x.size(); ++i) {
        const auto a = one.candidates(i), b = many.candidates(i);
        ASSERT_TRUE(std::equal(a.begin(), a.end(), b.begin(), b.end())) << i;
        ASSERT_TRUE(std::is_sorted(a.begin(), a.end())) << i;
    }
}

/// Candidates far apart in index: a gap takes one byte below 2^7, two below 2^14, three below
/// 2^21, four from there on. Particles k, k + gap and k + 2 gap sit together, away from every
/// other particle.
TEST(VerletList, LargeIndexGaps) {
    for (const std::uint32_t gap : {127u, 128u, 16383u, 16384u, 70001u, 2097152u}) {
        SCOPED_TRACE(gap);
        std::vector<V<2>> x(3 * gap);
        for (std::uint32_t k = 0; k < gap; ++k)
            for (std::uint32_t m = 0; m < 3; ++m)
                x[k + m * gap] = {{double(k % 300) + 0.1 * m, double(k / 300)}};
        num::VerletList<2> list;
        list.configure(0.5, 0.2, num::Domain<2>{});
        list.update(x);
        typename num::VerletList<2>::Neighbours flat;
        const std::uint32_t stride = gap < 100000 ? 1 : 997;  // every particle, or a sample
        for (std::uint32_t i = 0; i < x.size(); i += stride) {
            const std::uint32_t k = i % gap;
            const std::vector<std::uint32_t> group = {k, k + gap, k + 2 * gap};
            ASSERT_EQ(list.candidates(i), group) << i;
            std::vector<std::uint32_t> found, others, after, expectedOthers, expectedAfter;
            list.forEachNeighbourOf(
                i, [&](std::uint32_t j, const V<2>&, double) { found.push_back(j); });
            ASSERT_EQ(found, group) << i;
            for (std::uint32_t m = 0, n = list.collect(i, flat); m < n; ++m)
                others.push_back(flat.j[m]);
            for (std::uint32_t m = 0, n = list.collectAfter(i, flat); m < n; ++m)
                after.push_back(flat.j[m]);
            for (std::uint32_t j : group) {
                if (j != i) expectedOthers.push_back(j);
                if (j > i) expectedAfter.push_back(j);
            }
            ASSERT_EQ(others, expectedOthers) << i;
            ASSERT_EQ(after, expectedAfter) << i;
        }
    }
}

TEST(VerletList, NonFinitePositionIsReported) {
    std::vector<V<2>> x(10, V<2>::filled(0.5));
    num::VerletList<2> list;
    list.configure(0.1, 0.2, unitDomain<2>(0));
    list.update(x);
    x[3][1] = std::nan("");
    EXPECT_THROW(list.update(x), std::invalid_argument);
}

using namespace num::sph;

/// Every level of every quantity of a and b is bitwise the same.
bool sameState(const Storage<2>& a, const Storage<2>& b) {
    bool same = a.size() == b.size();
    a.forEach([&](QuantityId id, const Quantity<2>& qa) {
        qa.visit([&](const auto& ba) {
            using T = typename std::decay_t<decltype(ba.value)>::value_type;
            const auto& bb = b.get(id).template buffers<T>();
            for (int k = 0; k < qa.levels(); ++k)
                same &= ba.level(k).size() == bb.level(k).size() &&
                        std::memcmp(ba.level(k).data(), bb.level(k).data(),
                                    ba.level(k).size() * sizeof(T)) == 0;
        });
    });
    return same;
}

/// A dam break in a walled box (walls, free surface, shifting, reordering every 25 steps), run
/// for `steps` steps with the given skin (adapting up to maxSkin where larger), threads and
/// evaluation mode. Returns the final state and the number of list builds.
std::pair<Storage<2>, std::size_t> damBreak(double skin, Size threads, const std::string& mode,
                                            int steps, double maxSkin = 0) {
    const double dx = 0.025;
    FluidModel<2> model;
    model.maxVelocity = 2;
    model.bodyForce = [](Float) { return Vector<2>{{0.0, -9.81}}; };
    FluidGeometry<2> geometry;
    geometry.spacing = dx;
    geometry.domain.max = {{1.0, 0.6}};
    geometry.fluid.push_back(
        FluidRegion<2>::filling(BoxOrBall<2>::box({{0.0, 0.0}}, {{0.4, 0.4}})));
    RunSettings settings;
    settings.set("smoothing_length", 1.3 * dx)
        .set("neighbour_skin", skin)
        .set("neighbour_skin_max", maxSkin)
        .set("threads", threads)
        .set("evaluation", mode)
        .set("reorder_every", 25);
    Storage<2> s = makeFluidStorage(model, geometry, settings);
    // The thread pool rather than OpenMP, whose spinning threads are slow on a busy machine.
    const auto scheduler = makeScheduler(threads == 1 ? "seq" : "threads", threads);
    Solver<2> solver(*scheduler, settings, makeFluidEquations(model, geometry), geometry.domain);
    LeapfrogKDK<2> leapfrog;
    num::sph::Run<2> run(s, solver, leapfrog);
    for (int k = 0; k < steps; ++k) run.step();
    return {std::move(s), solver.neighbours().builds()};
}

TEST(VerletList, FluidRunIsBitwiseTheSameForAnySkinAndThreads) {
    const int steps = 80, reorders = 3;  // reordering every 25 steps
    for (const std::string mode : {"asymmetric", "symmetric"}) {
        SCOPED_TRACE(mode);
        const auto [reference, everyTime] = damBreak(0, 1, mode, steps);
        EXPECT_EQ(everyTime, std::size_t(steps + 1)) << "skin 0: built at every evaluation";
        const auto [thin, builds] = damBreak(0.05, 1, mode, steps);
        EXPECT_LT(builds, std::size_t(steps / 2)) << "with a skin the lists are kept a while";
        EXPECT_GT(builds, std::size_t(1 + reorders)) << "and rebuilt as particles move";
        EXPECT_TRUE(sameState(reference, thin)) << "skin 0.05 against skin 0";
        EXPECT_TRUE(sameState(reference, damBreak(0.2, 2, mode, steps).first)) << "skin 0.2";
        EXPECT_TRUE(sameState(reference, damBreak(0.5, 2, mode, steps).first)) << "skin 0.5";
        const auto [adaptive, grown] = damBreak(0, 2, mode, steps, 0.5);
        EXPECT_TRUE(sameState(reference, adaptive)) << "skin adapting from 0 to 0.5";
        EXPECT_LT(grown, std::size_t(steps / 2)) << "the skin grew from 0: lists kept a while";
    }
}

}  // namespace
