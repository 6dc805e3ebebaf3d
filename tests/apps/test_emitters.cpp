// Emitters leave out the nozzle points that water already occupies (no two particles on top of
// each other); the water search against a plain loop over every particle and point.
#include <gtest/gtest.h>

#include <random>

#include "app/emitters.hpp"
#include "app/nozzle.hpp"
#include "app/scene_loader.hpp"

using namespace num;
using namespace num::app;

TEST(Emitters, WaterAtMatchesAPlainSum) {
    // Random fluid and wall particles, more points than one run of the search (32), a periodic
    // x axis (points near x = 0 see particles near x = 1), and every third particle not counted
    // in the sum (as a halo copy another process counts).
    Domain<2> domain;
    domain.min = {{0, 0}}, domain.max = {{1, 1}}, domain.periodic = {true, false};
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    const std::size_t n = 2000;
    std::vector<sph::Vector<2>> x(n);
    std::vector<int> kind(n);
    std::vector<double> mass(n), density(n);
    for (std::size_t i = 0; i < n; ++i) {
        x[i] = {{u(rng), u(rng)}};
        kind[i] = int(i % 5 ? sph::ParticleKind::FLUID : sph::ParticleKind::WALL);
        mass[i] = 1e-4 * (1 + u(rng)), density[i] = 1000 * (1 + 0.1 * u(rng));
    }
    sph::Storage<2> storage;
    storage.insert<sph::Vector<2>>(sph::QuantityId::POSITION, sph::OrderEnum::SECOND, x);
    storage.insert<int>(sph::QuantityId::KIND, sph::OrderEnum::ZERO, kind);
    storage.insert<double>(sph::QuantityId::MASS, sph::OrderEnum::ZERO, mass);
    storage.insert<double>(sph::QuantityId::DENSITY, sph::OrderEnum::FIRST, density);
    sph::RunSettings settings;
    settings.set("kernel", std::string("wendland_c2")).set("smoothing_length", 0.03);
    const sph::RunKernel<2> kernel(settings);
    std::vector<sph::Vector<2>> points;
    for (int k = 0; k < 100; ++k) points.push_back({{0.01 * k, 0.3 + 0.004 * k}});
    const double radius = 0.02;
    auto counts = [](sph::Size i) { return i % 3 != 0; };
    const WaterAt water = waterAt(storage, domain, kernel, points, radius, counts);
    int near = 0;
    for (std::size_t p = 0; p < points.size(); ++p) {
        bool plainNear = false;
        double plainSum = 0;
        for (std::size_t i = 0; i < n; ++i) {
            if (kind[i] != int(sph::ParticleKind::FLUID)) continue;
            const double r = norm(domain.minimumImage(x[i] - points[p]));
            plainNear |= r < radius;
            if (counts(i)) plainSum += mass[i] / density[i] * kernel.W(r);
        }
        EXPECT_EQ(bool(water.near[p]), plainNear) << "point " << p;
        EXPECT_NEAR(water.fraction[p], plainSum, 1e-12 * std::max(1.0, plainSum)) << "point " << p;
        near += plainNear;
    }
    EXPECT_GT(near, 10);  // the test sees both answers
    EXPECT_LT(near, 90);
}

TEST(Emitters, NozzleInsideWaterLeavesOutTheOccupiedPoints) {
    // A nozzle whose lower half lies in the tiny scene's water block (x < 0.1, y < 0.12).
    SceneDocument doc = SceneDocument::fromFile(std::string(APP_TEST_SCENES_DIR) + "/tiny_2d.json");
    doc.set(R"(emitters=[{"position": [0.05, 0.12], "direction": [1, 0], "speed": 1,
                          "radius": 0.04, "material": "water"}])");
    const Scene<2> scene = readScene<2>(doc);
    SceneSetup<2> setup = makeSceneSetup<2>(scene, 1);
    sph::Storage<2> storage = makeInitialStorage<2>(scene, setup);
    const std::size_t initial = storage.size();
    Emitters<2> emitters(scene, setup);
    const double dx = scene.spacing;
    const sph::RunKernel<2> kernel(setup.settings);
    const parallel::Communicator single;
    auto occupied = [&](const std::vector<sph::Vector<2>>& points) {
        return occupiedPoints(storage, setup.geometry.domain, kernel, points, dx, single);
    };
    // Four points across the nozzle (y = 0.09, 0.11, 0.13, 0.15): the water's top particles sit
    // at y = 0.11, so the lower two points fall on water.
    EXPECT_EQ(emitters.emit(storage, 0.0, occupied), 2u);
    EXPECT_EQ(emitters.blocked(), 2u);
    ASSERT_EQ(emitters.warnings().size(), 1u);  // once per emitter, the first time
    EXPECT_NE(emitters.warnings()[0].find("left out 2 of 4 nozzle points"), std::string::npos)
        << emitters.warnings()[0];
    const auto x = storage.getValue<sph::Vector<2>>(sph::QuantityId::POSITION);
    const auto kind = storage.getValue<int>(sph::QuantityId::KIND);
    for (std::size_t e = initial; e < storage.size(); ++e) {
        EXPECT_GT(x[e][1], 0.12);
        for (std::size_t i = 0; i < initial; ++i)
            if (kind[i] == int(sph::ParticleKind::FLUID)) {
                EXPECT_GE(norm(x[e] - x[i]), 0.5 * dx);
            }
    }
    // A layer later, with the emitted particles not moved, the new layer (0.2 dx ahead of them)
    // falls on them and on the water: nothing is added, and the layer counts as done.
    const std::size_t afterFirst = storage.size();
    EXPECT_FALSE(emitters.anyDue(0.5 * dx));  // what the GPU's engine asks before copying back
    EXPECT_EQ(emitters.emit(storage, 0.5 * dx, occupied), 0u);  // no layer due yet
    EXPECT_TRUE(emitters.anyDue(1.2 * dx));
    EXPECT_EQ(emitters.emit(storage, 1.2 * dx, occupied), 0u);
    EXPECT_FALSE(emitters.anyDue(1.2 * dx));  // the layer is done, though blocked
    EXPECT_EQ(emitters.blocked(), 6u);
    EXPECT_EQ(emitters.warnings().size(), 1u);
    // Once they have moved on by two spacings, as the flow carries them, the next layer enters.
    auto moved = storage.getValue<sph::Vector<2>>(sph::QuantityId::POSITION);
    for (std::size_t e = initial; e < afterFirst; ++e) moved[e][0] += 2 * dx;
    EXPECT_EQ(emitters.emit(storage, 2.2 * dx, occupied), 2u);
    EXPECT_EQ(emitters.layers()[0], 3u);
    EXPECT_EQ(emitters.emitted(), 4u);
}

TEST(Emitters, NozzleAgainstAWallInjectsAcrossItsOpenPart) {
    // A wall (a polygon from x = 0.145 on) takes the two right-hand points of a nozzle whose
    // four points lie at x = 0.11, 0.13, 0.15, 0.17: the scene warns once, and each layer is
    // the two open points; they are not counted as left out for water.
    SceneDocument doc = SceneDocument::fromFile(std::string(APP_TEST_SCENES_DIR) + "/tiny_2d.json");
    doc.set(R"(walls=[{"shape": "polygon",
                       "points": [[0.145, 0.13], [0.2, 0.13], [0.2, 0.19], [0.145, 0.19]]}])");
    doc.set(R"(emitters=[{"position": [0.14, 0.16], "direction": [0, -1], "speed": 1,
                          "radius": 0.04, "material": "water"}])");
    const Scene<2> scene = readScene<2>(doc);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_NE(scene.warnings[0].find("emitters[0]: 2 of 4 nozzle points are in or within half a "
                                     "spacing of walls[0]"),
              std::string::npos)
        << scene.warnings[0];
    const Nozzle<2> nozzle = openNozzle(scene, 0);
    EXPECT_EQ(nozzle.open.size(), 2u);
    EXPECT_EQ(nozzle.cut, 2u);
    SceneSetup<2> setup = makeSceneSetup<2>(scene, 1);
    sph::Storage<2> storage = makeInitialStorage<2>(scene, setup);
    const std::size_t initial = storage.size();
    Emitters<2> emitters(scene, setup);
    auto nothingThere = [](const std::vector<sph::Vector<2>>& points) {
        return std::vector<char>(points.size(), 0);
    };
    EXPECT_EQ(emitters.emit(storage, 0.0, nothingThere), 2u);
    EXPECT_EQ(emitters.emit(storage, 1.0 * scene.spacing, nothingThere), 2u);
    EXPECT_EQ(emitters.blocked(), 0u);
    const auto x = storage.getValue<sph::Vector<2>>(sph::QuantityId::POSITION);
    for (std::size_t e = initial; e < storage.size(); ++e)
        EXPECT_LT(x[e][0], 0.145 - 0.5 * scene.spacing) << "particle " << e;
}
