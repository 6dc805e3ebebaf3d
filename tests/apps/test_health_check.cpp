// The health check of the time loop: a non-finite value in any field the outputs write stops the
// run as unstable (exit code 9), naming the field; a healthy state passes.
#include <gtest/gtest.h>

#include <cstdio>
#include <limits>

#include "app/scene_loader.hpp"
#include "run/physical_check.hpp"
#include "run/run_state.hpp"

using namespace num::app;
using num::sph::QuantityId;

namespace {

SceneDocument tinyScene(const std::string& spacing) {
    SceneDocument d = SceneDocument::fromFile(std::string(APP_TEST_SCENES_DIR) + "/tiny_2d.json");
    if (!spacing.empty()) d.set("particles.spacing=" + spacing);
    return d;
}

struct Tiny {
    Scene<2> scene;
    SceneSetup<2> setup;
    num::sph::Storage<2> storage;
    /// spacing: the scene's unless given (a finer one gives more particles).
    explicit Tiny(const std::string& spacing = "")
        : scene(readScene<2>(tinyScene(spacing))),
          setup(makeSceneSetup(scene, 1)),
          storage(makeInitialStorage(scene, setup)) {}
    /// The message of checkHealth on one thread, or on the given scheduler; "" when it passes.
    std::string check() const {
        num::sph::SequentialScheduler serial;
        return check(serial);
    }
    std::string check(num::sph::IScheduler& scheduler) const {
        try {
            checkHealth(scheduler, storage, scene, 0.01, 7, 1e-4, "courant");
        } catch (const AppError& e) {
            EXPECT_EQ(e.code(), ExitCode::UNSTABLE);
            return e.what();
        }
        return "";
    }
};

const double kNan = std::numeric_limits<double>::quiet_NaN();

}  // namespace

TEST(HealthCheck, HealthyStatePasses) { EXPECT_EQ(Tiny().check(), ""); }

TEST(HealthCheck, EveryWrittenFieldIsChecked) {
    for (QuantityId id : {QuantityId::TEMPERATURE, QuantityId::PRESSURE, QuantityId::DENSITY}) {
        Tiny t;
        t.storage.getValue<double>(id)[3] =
            id == QuantityId::PRESSURE ? std::numeric_limits<double>::infinity() : kNan;
        const std::string m = t.check();
        const char* name = id == QuantityId::TEMPERATURE ? "temperature"
                           : id == QuantityId::PRESSURE  ? "pressure"
                                                         : "density";
        EXPECT_NE(m.find(std::string("non-finite ") + name), std::string::npos) << m;
        EXPECT_NE(m.find("unstable at t = 0.01 s (step 7"), std::string::npos) << m;
    }
    Tiny t;
    t.storage.getDt<num::sph::Vector<2>>(QuantityId::POSITION)[5][1] = kNan;
    EXPECT_NE(t.check().find("non-finite velocity"), std::string::npos);
}

// With several problems, the report names the first check's first particle in storage order,
// whatever the threads: the scan runs in chunks of 8192 particles, here more than two.
TEST(HealthCheck, TheFirstProblemIsNamedWhateverTheThreads) {
    Tiny t("0.0008");
    ASSERT_GT(t.storage.size(), 3 * 8192u);
    const auto id = t.storage.getValue<int>(QuantityId::PARTICLE_ID);
    auto temperature = t.storage.getValue<double>(QuantityId::TEMPERATURE);
    auto rho = t.storage.getValue<double>(QuantityId::DENSITY);
    temperature[20000] = temperature[9000] = kNan;
    rho[100] = -1;  // density is checked after every field's finiteness
    const std::string named =
        "particle " + std::to_string(id[9000]) + " has a non-finite temperature";
    num::sph::ThreadPoolScheduler pool(2);
    num::sph::ParallelScheduler omp(3);
    for (const std::string& m : {t.check(), t.check(pool), t.check(omp)})
        EXPECT_NE(m.find(named), std::string::npos) << m;
    temperature[20000] = temperature[9000] = 20;
    rho[17000] = 0;
    const std::string density = "particle " + std::to_string(id[100]) + " has a density <= 0";
    for (const std::string& m : {t.check(), t.check(pool), t.check(omp)})
        EXPECT_NE(m.find(density), std::string::npos) << m;
}

// A fluid particle more than a spacing beyond a wall stops the run, naming the wall; wall
// particles, which lie outside the domain, and fluid within a spacing of it do not.
TEST(HealthCheck, FluidBeyondAWallIsNamed) {
    Tiny t;
    auto x = t.storage.getValue<num::sph::Vector<2>>(QuantityId::POSITION);
    const auto kind = t.storage.getValue<int>(QuantityId::KIND);
    std::size_t fluid = 0;
    while (kind[fluid] != int(num::sph::ParticleKind::FLUID)) ++fluid;
    ASSERT_TRUE(t.scene.sides[0][1]->closes());
    x[fluid][0] = t.scene.domainMax[0] + 0.5 * t.scene.spacing;
    EXPECT_EQ(t.check(), "");
    x[fluid][0] = t.scene.domainMax[0] + 1.5 * t.scene.spacing;
    const std::string m = t.check();
    EXPECT_NE(m.find(std::string("a fluid particle left the domain through the ") + sideName(0, 1) +
                     " wall"),
              std::string::npos)
        << m;
    x[fluid][0] = t.scene.domainMin[0] + t.scene.spacing;  // back inside
    EXPECT_EQ(t.check(), "");
}

// The check of unphysical but finite states (physical_check.hpp): warnings once per kind,
// a stop (exit code 9) where the run is lost.
namespace {

struct Physical : Tiny {
    PhysicalCheck check{setup.velocityScale, setup.model.c0(), setup.model.restDensity};
    /// Sets the speed of the first fluid particle to `factor` times the velocity scale and
    /// returns where that particle is, as the messages write it.
    std::string speed(double factor) {
        auto v = storage.getDt<num::sph::Vector<2>>(QuantityId::POSITION);
        const auto r = storage.getValue<num::sph::Vector<2>>(QuantityId::POSITION);
        const auto kind = storage.getValue<int>(QuantityId::KIND);
        for (std::size_t i = 0; i < storage.size(); ++i)
            if (kind[i] == int(num::sph::ParticleKind::FLUID)) {
                v[i] = num::sph::Vector<2>{{factor * setup.velocityScale, 0}};
                char at[64];
                std::snprintf(at, sizeof at, "at (%.3g, %.3g) m", r[i][0], r[i][1]);
                return at;
            }
        return "";
    }
};

}  // namespace

TEST(PhysicalCheck, FlowAtItsScalePasses) {
    Physical p;
    p.speed(1.0);
    EXPECT_EQ(p.check.check(p.storage, 0.1), "");
    EXPECT_TRUE(p.check.warnings().empty());
}

TEST(PhysicalCheck, SprayFarAboveTheScaleWarnsOnce) {
    Physical p;
    const std::string at = p.speed(3.5);  // above 3 U, below c0 (20 m/s, U = 2 m/s)
    const std::string w = p.check.check(p.storage, 0.1);
    EXPECT_NE(w.find("times the velocity scale"), std::string::npos) << w;
    EXPECT_NE(w.find(at), std::string::npos) << w;  // says where the spray is
    EXPECT_EQ(p.check.check(p.storage, 0.2), "");   // once per kind
    EXPECT_EQ(p.check.warnings().size(), 1u);
}

TEST(PhysicalCheck, SupersonicFlowStopsTheRun) {
    Physical p;
    const std::string at = p.speed(1.05 * p.setup.model.c0() / p.setup.velocityScale);
    try {
        p.check.check(p.storage, 0.1);
        FAIL() << "no stop";
    } catch (const AppError& e) {
        EXPECT_EQ(e.code(), ExitCode::UNSTABLE);
        EXPECT_NE(std::string(e.what()).find("sound speed"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(at), std::string::npos) << e.what();
    }
}

TEST(PhysicalCheck, DensityFarFromRestWarnsThenStops) {
    Physical p;
    auto rho = p.storage.getValue<double>(QuantityId::DENSITY);
    const auto kind = p.storage.getValue<int>(QuantityId::KIND);
    std::size_t fluid = 0;
    while (kind[fluid] != int(num::sph::ParticleKind::FLUID)) ++fluid;
    const double rho0 = p.setup.model.restDensity;
    rho[fluid] = 1.3 * rho0;
    const std::string w = p.check.check(p.storage, 0.1);
    EXPECT_NE(w.find("more than 20 %"), std::string::npos) << w;
    EXPECT_NE(w.find("the highest at ("), std::string::npos) << w;
    rho[fluid] = 2.5 * rho0;
    EXPECT_THROW(p.check.check(p.storage, 0.2), AppError);
}

// Water cooled below absolute zero (a wall's heat flux, a plugin's heat sink) ran on to the end
// and reported success (issue 47): any particle below -273.15 degC stops the run.
TEST(PhysicalCheck, TemperatureBelowAbsoluteZeroStopsTheRun) {
    Physical p;
    auto T = p.storage.getValue<double>(QuantityId::TEMPERATURE);
    T[2] = -273.15;  // at absolute zero: still physical
    EXPECT_EQ(p.check.check(p.storage, 0.1), "");
    T[2] = -293.4;
    try {
        p.check.check(p.storage, 0.25);
        FAIL() << "no stop";
    } catch (const AppError& e) {
        EXPECT_EQ(e.code(), ExitCode::UNSTABLE);
        const std::string m = e.what();
        EXPECT_NE(m.find("at t = 0.25 s a particle's temperature reached -293.4 degC, below "
                         "-273.15 degC"),
                  std::string::npos)
            << m;
        EXPECT_NE(m.find("heat_flux"), std::string::npos) << m;
    }
}

// A quantity with a declared range (a plugin's, Registry::addField) is checked the same way.
TEST(PhysicalCheck, DeclaredRangesAreChecked) {
    Physical p;
    const auto id = QuantityId(1234);
    p.storage.insert<double>(id, num::sph::OrderEnum::ZERO, 0.5);
    p.check.addRange({id, "concentration", "mol/m^3", 0, 1, "the test's hint"});
    EXPECT_EQ(p.check.check(p.storage, 0.1), "");
    p.storage.getValue<double>(id)[4] = 1.5;
    try {
        p.check.check(p.storage, 0.1);
        FAIL() << "no stop";
    } catch (const AppError& e) {
        EXPECT_EQ(e.code(), ExitCode::UNSTABLE);
        EXPECT_NE(std::string(e.what()).find("concentration reached 1.5 mol/m^3, above 1 mol/m^3: "
                                             "the test's hint"),
                  std::string::npos)
            << e.what();
    }
}
