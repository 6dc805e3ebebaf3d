// Ctrl-C, SIGTERM and SIGHUP act within a second, wherever the app is (docs/scenes.md, exit
// codes): during a set-up that would take minutes, during a step that would take minutes, and
// a second signal during a slow write. Every wait is a hang guard, not a timing measurement:
// the tests signal the app when it reports where it is, and fail only when it does not exit.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <sys/stat.h>

#include <csignal>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "app_process.hpp"
#include "vtu_reader.hpp"

using namespace apptest;
namespace fs = std::filesystem;

namespace {

constexpr double kStartGuard = 120;  ///< the app reaching the phase under test, on a busy machine
constexpr double kExitGuard = 20;    ///< a signalled app ending (it should take under a second)

/// A scene whose set-up walks 10^8 lattice points past 200 small bodies (minutes of work) but
/// creates few particles: periodic sides have no wall layers.
nlohmann::json slowSetUpScene(int dim) {
    const double size = dim == 2 ? 100 : 20, dx = dim == 2 ? 0.01 : 0.04;
    nlohmann::json j;
    j["dimension"] = dim;
    j["domain"] = {{"min", std::vector<double>(dim, 0.0)}, {"max", std::vector<double>(dim, size)}};
    const char* axes = "xyz";
    for (int k = 0; k < dim; ++k)
        for (const char* end : {"_min", "_max"})
            j["boundaries"][std::string(1, axes[k]) + end] = {{"type", "periodic"}};
    j["particles"] = {{"spacing", dx}};
    j["time"] = {{"end", 1.0}};
    j["physics"] = {{"max_speed", 1.0}};
    j["materials"]["water"] = {{"density", 1000}};
    j["fluids"] = {{{"material", "water"},
                    {"shape", "box"},
                    {"min", std::vector<double>(dim, 0.0)},
                    {"max", std::vector<double>(dim, 10 * dx)}}};
    for (int b = 0; b < 200; ++b) {
        std::vector<double> c(dim, size / 2);
        c[0] = size * (0.1 + 0.8 * (b % 20) / 19.0), c[1] = size * (0.3 + 0.6 * (b / 20) / 9.0);
        j["bodies"].push_back(
            {{"shape", dim == 2 ? "circle" : "sphere"}, {"center", c}, {"radius", 2 * dx}});
    }
    j["output"] = {{"directory", "out"}, {"every", 0.5}};
    return j;
}

struct SetUpCase {
    int dim;
    int signal;
};

class StopDuringSetUp : public ::testing::TestWithParam<SetUpCase> {};

TEST_P(StopDuringSetUp, ExitsWith130AndOneLineAndWritesNothing) {
    const auto [dim, sig] = GetParam();
    const std::string dir =
        freshDir("stop_setup_" + std::to_string(dim) + "d_" + std::to_string(sig));
    writeFile(dir + "/scene.json", slowSetUpScene(dim).dump());
    fs::create_directories(dir + "/out");
    writeFile(dir + "/out/summary.json", "{\"from\": \"an earlier run\"}\n");
    AppProcess app(dim == 2 ? FLUID_SIM : FLUID_SIM_3D, {"scene.json"}, dir);
    // The app's handler is installed when its set-up starts (the signal mask in /proc).
    ASSERT_TRUE(waitFor([&] { return !app.running() || app.catches(sig); }, kStartGuard));
    ASSERT_TRUE(app.running()) << "the set-up ended before the signal\n" << app.output();
    ::kill(app.pid(), sig);
    ASSERT_TRUE(app.waitForExit(kExitGuard)) << "no exit " << kExitGuard << " s after the signal";
    EXPECT_EQ(app.code(), 130) << app.output();
    const std::string name = sig == SIGINT    ? "SIGINT (Ctrl-C)"
                             : sig == SIGTERM ? "SIGTERM"
                                              : "SIGHUP";
    EXPECT_TRUE(contains(app.output(), "stopped by " + name + " during set-up")) << app.output();
    // Nothing was written; what an earlier run wrote stays.
    EXPECT_EQ(readFile(dir + "/out/summary.json"), "{\"from\": \"an earlier run\"}\n");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir + "/out"), fs::directory_iterator()), 1);
}

INSTANTIATE_TEST_SUITE_P(Apps, StopDuringSetUp,
                         ::testing::Values(SetUpCase{2, SIGTERM}, SetUpCase{3, SIGINT},
                                           SetUpCase{2, SIGHUP}),
                         [](const auto& info) {
                             return std::to_string(info.param.dim) + "d_signal" +
                                    std::to_string(info.param.signal);
                         });

/// The files of the pvd series, each read back whole.
void expectWholeSeries(const std::string& out) {
    const std::string pvd = readFile(out + "/particles.pvd");
    ASSERT_TRUE(contains(pvd, "</VTKFile>")) << pvd;
    int files = 0;
    for (auto p = pvd.find("file=\""); p != std::string::npos; p = pvd.find("file=\"", p + 1)) {
        const std::string file = pvd.substr(p + 6, pvd.find('"', p + 6) - p - 6);
        EXPECT_GT(readVtu(readFile(out + "/" + file)).points, 0u) << file;
        ++files;
    }
    EXPECT_GT(files, 0);
}

TEST(StopDuringStep, AbandonsTheStepAndKeepsWhatWasWritten) {
    // NUMERICS_TEST_HOLD_STEP holds step 2 in its pair loop until a signal, as a step that would
    // take minutes: the stop abandons it (half a second after the signal) instead of waiting.
    const std::string dir = freshDir("stop_step");
    AppProcess app(FLUID_SIM,
                   {scene("tiny_2d.json"), "--out", "out", "--end-time", "0.5", "--set",
                    "output.every=1e-5", "--checkpoint-every", "1e-5"},
                   dir, {"NUMERICS_TEST_HOLD_STEP=2"});
    ASSERT_TRUE(waitFor([&] { return !app.running() || contains(app.output(), "holding step 2"); },
                        kStartGuard));
    ASSERT_TRUE(app.running()) << app.output();
    ::kill(app.pid(), SIGTERM);
    ASSERT_TRUE(app.waitForExit(kExitGuard)) << "no exit " << kExitGuard << " s after the signal";
    EXPECT_EQ(app.code(), 130) << app.output();
    EXPECT_TRUE(contains(app.output(), "stopped by SIGTERM during step 2")) << app.output();
    const auto s = nlohmann::json::parse(readFile(dir + "/out/summary.json"));
    EXPECT_EQ(s["status"], "interrupted");
    EXPECT_EQ(s["steps"], 1);
    EXPECT_TRUE(contains(s["message"].get<std::string>(), "abandoned")) << s["message"];
    // The outputs of t = 0 and step 1 stay whole; no output or checkpoint of the half step.
    expectWholeSeries(dir + "/out");
    for (const auto& e : fs::directory_iterator(dir + "/out"))
        EXPECT_NE(e.path().extension(), ".tmp") << e.path();
    EXPECT_TRUE(fs::exists(dir + "/out/particles_0001.vtu"));
    EXPECT_FALSE(fs::exists(dir + "/out/particles_0002.vtu"));
    EXPECT_TRUE(fs::exists(dir + "/out/checkpoint_0001.chk"));
    EXPECT_FALSE(fs::exists(dir + "/out/checkpoint_interrupted.chk"));
    // The checkpoint of step 1 continues the run.
    const Result resumed = run(FLUID_SIM,
                               "--quiet --out out --restart out/checkpoint_0001.chk --end-time " +
                                   std::to_string(s["final_time"].get<double>() * 2),
                               dir);
    EXPECT_EQ(resumed.code, 0) << resumed.output;
}

TEST(SecondSignal, DuringASlowWriteLeavesEveryFileWhole) {
    // The first Ctrl-C comes after step 3 (NUMERICS_TEST_SIGNAL); the final output's first file
    // is then written to a pipe the test holds open (its temporary name is a FIFO): the write
    // waits for the test, which reads one byte of it and sends the second Ctrl-C.
    const std::string dir = freshDir("second_signal");
    fs::create_directories(dir + "/out");
    const std::string fifo = dir + "/out/particles_0001.vtu.tmp";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
    const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
    ASSERT_GE(reader, 0);
    // Spacing 0.005: a VTU of about 200 KB, more than a pipe holds, so the writer must wait.
    AppProcess app(FLUID_SIM,
                   {scene("tiny_2d.json"), "--quiet", "--out", "out", "--end-time", "1000", "--set",
                    "particles.spacing=0.005", "--set", "output.every=1000"},
                   dir, {"NUMERICS_TEST_SIGNAL=" + std::to_string(SIGINT) + ":3"});
    pollfd p{reader, POLLIN, 0};
    char byte = 0;
    ASSERT_TRUE(waitFor([&] { return !app.running() || ::poll(&p, 1, 0) > 0; }, kStartGuard));
    ASSERT_EQ(::read(reader, &byte, 1), 1) << app.output();
    EXPECT_EQ(byte, '<');  // the start of the VTU, which the app is writing now
    ::kill(app.pid(), SIGINT);
    ASSERT_TRUE(app.waitForExit(kExitGuard)) << "no exit " << kExitGuard << " s after the signal";
    ::close(reader);
    EXPECT_EQ(app.code(), -SIGINT) << "the second Ctrl-C ends the program at once\n"
                                   << app.output();
    EXPECT_FALSE(fs::exists(dir + "/out/particles_0001.vtu"));  // never renamed into place
    EXPECT_FALSE(fs::exists(dir + "/out/summary.json"));
    expectWholeSeries(dir + "/out");  // the FIFO stays as the temporary name it was
}

}  // namespace

// Two runs writing one folder at once failed on the ParaView script (issue 57): the output
// folder is locked while a run writes it, and a second run is refused (exit code 7), naming the
// process that holds it; when that run ends, the folder is free again.
TEST(OutputLock, ASecondRunWritingTheFolderAtOnceIsRefused) {
    const std::string dir = freshDir("output_lock");
    AppProcess first(FLUID_SIM, {scene("tiny_2d.json"), "--out", "out", "--end-time", "0.5"}, dir,
                     {"NUMERICS_TEST_HOLD_STEP=2"});
    ASSERT_TRUE(
        waitFor([&] { return !first.running() || contains(first.output(), "holding step 2"); },
                kStartGuard));
    ASSERT_TRUE(first.running()) << first.output();
    const Result second =
        run(FLUID_SIM, "'" + scene("tiny_2d.json") + "' --quiet --out out --end-time 0.01", dir);
    EXPECT_EQ(second.code, 7) << second.output;
    EXPECT_TRUE(
        contains(second.output, "out: the output directory is in use by another run (process " +
                                    std::to_string(first.pid()) + ")"))
        << second.output;
    EXPECT_EQ(std::count(second.output.begin(), second.output.end(), '\n'), 1) << second.output;
    // The first run's files are its own: the second neither removed nor wrote any.
    EXPECT_TRUE(fs::exists(dir + "/out/particles_0000.vtu"));
    ::kill(first.pid(), SIGTERM);
    ASSERT_TRUE(first.waitForExit(kExitGuard));
    EXPECT_EQ(first.code(), 130) << first.output();
    const Result after =
        run(FLUID_SIM, "'" + scene("tiny_2d.json") + "' --quiet --out out --end-time 0.01", dir);
    EXPECT_EQ(after.code, 0) << after.output;
}
