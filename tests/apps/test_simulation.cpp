// Simulation, the object the apps drive: its steps, advanceTo, observers and particles, and a
// run driven in pieces against one run() (the same files, byte for byte).
#include "app/simulation.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

using num::app::IStepObserver;
using num::app::RunOptions;
using num::app::SceneDocument;
using num::app::Simulation;

std::string work(const std::string& name) {
    const std::string dir = std::string(APP_TEST_WORK) + "/simulation/" + name;
    std::filesystem::remove_all(dir);
    return dir;
}

SceneDocument tinyScene() {
    return SceneDocument::fromFile(std::string(APP_TEST_SCENES) + "/tiny_2d.json");
}

RunOptions quietRun(const std::string& out) {
    RunOptions o;
    o.quiet = true, o.threads = 1, o.outDir = out;
    return o;
}

std::string contents(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// Counts the steps it sees and records the times.
class StepCounter final : public IStepObserver<2> {
  public:
    explicit StepCounter(std::vector<double>& times) : times_(times) {}
    void afterStep(Simulation<2>& sim) override { times_.push_back(sim.time()); }

  private:
    std::vector<double>& times_;
};

TEST(Simulation, StepsAdvanceTimeAndCallObservers) {
    Simulation<2> sim(tinyScene(), quietRun(work("steps")));
    std::vector<double> times;
    sim.addObserver(std::make_unique<StepCounter>(times));
    EXPECT_EQ(sim.time(), 0.0);
    EXPECT_EQ(sim.steps(), 0u);
    const double dt = sim.step();
    EXPECT_GT(dt, 0.0);
    EXPECT_EQ(sim.steps(), 1u);
    EXPECT_DOUBLE_EQ(sim.time(), dt);
    ASSERT_EQ(times.size(), 1u);
    EXPECT_EQ(times[0], sim.time());
    EXPECT_GT(sim.particles().size(), 0u);
}

TEST(Simulation, AdvanceToLandsOnTheTimeGiven) {
    Simulation<2> sim(tinyScene(), quietRun(work("advance")));
    sim.advanceTo(0.0123);
    EXPECT_EQ(sim.time(), 0.0123);
    sim.advanceTo(1.0);  // beyond the end time: stops there
    EXPECT_EQ(sim.time(), sim.endTime());
}

TEST(Simulation, RunInPiecesWritesTheFilesOfOneRun) {
    const std::string whole = work("whole"), pieces = work("pieces");
    {
        Simulation<2> sim(tinyScene(), quietRun(whole));
        EXPECT_EQ(sim.run(), 0);
    }
    {
        Simulation<2> sim(tinyScene(), quietRun(pieces));
        sim.advanceTo(0.01);  // an output time: the steps land there anyway
        EXPECT_EQ(sim.time(), 0.01);
        EXPECT_EQ(sim.run(), 0);
    }
    for (const char* f : {"particles_0001.vtu", "particles_0002.vtu", "particles_0002.csv",
                          "probes.csv", "particles.pvd"}) {
        const std::string a = contents(whole + "/" + f);
        EXPECT_FALSE(a.empty()) << f;
        EXPECT_EQ(a, contents(pieces + "/" + f)) << f;
    }
}

TEST(Simulation, BadSceneIsAnAppError) {
    SceneDocument doc = tinyScene();
    doc.set("particles.spacing=-1");
    try {
        Simulation<2> sim(doc, quietRun(work("bad")));
        FAIL() << "a negative spacing was accepted";
    } catch (const num::app::AppError& e) {
        EXPECT_EQ(e.code(), num::app::ExitCode::SCENE);
        EXPECT_NE(std::string(e.what()).find("particles.spacing"), std::string::npos) << e.what();
    }
}

}  // namespace
