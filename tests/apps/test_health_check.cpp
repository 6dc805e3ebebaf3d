// The health check of the time loop: a non-finite value in any field the outputs write stops the
// run as unstable (exit code 9), naming the field; a healthy state passes.
#include <gtest/gtest.h>

#include <limits>

#include "io/scene_loader.hpp"
#include "run_state.hpp"

using namespace num::io;
using num::sph::QuantityId;

namespace {

struct Tiny {
    Scene<2> scene;
    SceneSetup<2> setup;
    num::sph::Storage<2> storage;
    Tiny()
        : scene(readScene<2>(
              SceneDocument::fromFile(std::string(APP_TEST_SCENES_DIR) + "/tiny_2d.json"))),
          setup(makeSceneSetup(scene, 1)),
          storage(makeInitialStorage(scene, setup)) {}
    /// The message of checkHealth, or "" when it passes.
    std::string check() const {
        try {
            checkHealth(storage, scene, 0.01, 7, 1e-4, "courant");
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
