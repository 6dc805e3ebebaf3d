// Bad input: each case gets one clear message (file, key path, expected, found, a hint for a
// misspelt key) and its documented exit code (docs/scenes.md), never a crash or a hang.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "app/checkpoint.hpp"
#include "app_runner.hpp"

using namespace apptest;
using nlohmann::json;

namespace {

// Exit codes documented in docs/scenes.md.
constexpr int kUsage = 2, kSceneFile = 3, kJson = 4, kScene = 5, kExpression = 6, kOutput = 7,
              kCheckpoint = 8, kUnstable = 9, kResources = 11;

json tiny() { return json::parse(readFile(scene("tiny_2d.json"))); }

/// Runs fluid_sim on the scene text written to <dir>/scene.json.
Result runScene(const std::string& name, const std::string& text, const std::string& extra = "") {
    const std::string dir = freshDir("bad_" + name);
    writeFile(dir + "/scene.json", text);
    return run(FLUID_SIM, "scene.json --quiet --out out " + extra, dir);
}

void expectMessage(const Result& r, int code, std::initializer_list<const char*> parts) {
    EXPECT_EQ(r.code, code) << r.output;
    for (const char* p : parts)
        EXPECT_TRUE(contains(r.output, p)) << "missing '" << p << "' in:\n" << r.output;
    // One message, on one line.
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

}  // namespace

TEST(BadInput, MissingSceneFile) {
    const Result r = run(FLUID_SIM, "no_such_scene.json", freshDir("bad_missing"));
    expectMessage(r, kSceneFile, {"no_such_scene.json", "No such file"});
}

TEST(BadInput, UnreadableSceneFile) {
    const std::string dir = freshDir("bad_unreadable");
    std::filesystem::create_directory(dir + "/a_directory.json");
    expectMessage(run(FLUID_SIM, "a_directory.json", dir), kSceneFile, {"a_directory.json"});
}

TEST(BadInput, MalformedJsonGivesLineAndColumn) {
    const Result r =
        runScene("malformed",
                 "{\n  \"dimension\": 2,\n  \"domain\": { \"min\": [0, 0] \"max\": [1, 1] }\n}");
    expectMessage(r, kJson, {"scene.json:3:", "malformed JSON"});
}

TEST(BadInput, UnknownKeySuggestsTheRightOne) {
    json j = tiny();
    j["particles"]["spacnig"] = j["particles"]["spacing"];
    j["particles"].erase("spacing");
    expectMessage(runScene("unknown", j.dump()), kScene,
                  {"scene.json", "particles.spacnig", "did you mean 'spacing'?"});
}

TEST(BadInput, WrongType) {
    json j = tiny();
    j["time"]["end"] = "soon";
    expectMessage(
        runScene("type", j.dump()), kScene,
        {"scene.json", "time.end", "expected a positive number", "found the string \"soon\""});
}

TEST(BadInput, NegativeSpacing) {
    json j = tiny();
    j["particles"]["spacing"] = -0.01;
    expectMessage(runScene("negative", j.dump()), kScene,
                  {"particles.spacing", "expected a positive number [m]", "found -0.01"});
}

TEST(BadInput, ZeroSpacing) {
    json j = tiny();
    j["particles"]["spacing"] = 0;
    expectMessage(runScene("zero", j.dump()), kScene, {"particles.spacing", "positive", "found 0"});
}

TEST(BadInput, FluidBlockOutsideTheDomain) {
    json j = tiny();
    j["fluids"][0]["max"] = {0.1, 0.5};
    expectMessage(runScene("outside", j.dump()), kScene, {"fluids[0]", "inside the domain"});
}

// A block fills its volume outside every body; one wholly inside a body holds no particle.
TEST(BadInput, FluidBlockInsideABody) {
    json j = tiny();
    j["fluids"][0]["min"] = {0.135, 0.025};  // lattice points (0.15, 0.03) and (0.15, 0.05)
    j["fluids"][0]["max"] = {0.165, 0.055};
    expectMessage(runScene("inside_body", j.dump()), kScene,
                  {"fluids[0]", "holding particles", "outside every body"});
}

TEST(BadInput, EmptyScene) {
    json j = tiny();
    j["fluids"] = json::array();
    expectMessage(runScene("empty", j.dump()), kScene, {"fluids", "no fluid particles"});
}

// A density of 1e-300 kg/m^3 passed a check of "> 0" and ended in an internal error (its square
// underflows, p / rho^2 is infinite and the first step moves particles to infinity).
TEST(BadInput, DensityFarBelowAnyFluid) {
    json j = tiny();
    j["materials"]["water"]["density"] = 1e-300;
    expectMessage(runScene("density", j.dump()), kScene,
                  {"materials.water.density", "expected a number in [1e-06, 1e+07]", "1e-300"});
    j["materials"]["water"]["density"] = 1e-6;
    const Result r = runScene("density_low", j.dump(), "--end-time 1e-5");  // heat: dt ~ 3e-9 s
    EXPECT_EQ(r.code, 0) << r.output;
}

TEST(BadInput, TensionLimitMustBePositive) {
    json j = tiny();
    j["physics"]["max_tension"] = 0;
    expectMessage(runScene("max_tension", j.dump()), kScene,
                  {"physics.max_tension", "expected a number in (0, 1e+12] [Pa]", "found 0"});
}

TEST(BadInput, PeriodicOnOneSideOnly) {
    json j = tiny();
    j["boundaries"]["x_min"] = {{"type", "periodic"}};
    expectMessage(runScene("periodic", j.dump()), kScene,
                  {"boundaries.x_max.type", "periodic", "both sides"});
}

TEST(BadInput, MissingSide) {
    json j = tiny();
    j["boundaries"].erase("y_max");
    expectMessage(runScene("side", j.dump()), kScene, {"boundaries.y_max", "missing"});
}

TEST(BadInput, OldSideNameNamesTheNewKey) {
    json j = tiny();
    j["boundaries"]["top"] = j["boundaries"]["y_max"];
    j["boundaries"].erase("y_max");
    expectMessage(runScene("old_side", j.dump()), kScene,
                  {"boundaries.top", "x_min, x_max, y_min, y_max", "did you mean y_max?"});
    json j3 = json::parse(readFile(scene("tiny_3d.json")));
    j3["boundaries"]["front"] = j3["boundaries"]["z_max"];
    j3["boundaries"].erase("z_max");
    const std::string dir = freshDir("bad_old_side_3d");
    writeFile(dir + "/scene.json", j3.dump());
    expectMessage(run(FLUID_SIM_3D, "scene.json --quiet --out out", dir), kScene,
                  {"boundaries.front", "z_min, z_max", "did you mean z_max?"});
}

TEST(BadInput, ExpressionThatDoesNotParse) {
    json j = tiny();
    j["fluids"][0]["temperature"] = "20 + sin(x";
    expectMessage(runScene("expression", j.dump()), kExpression,
                  {"fluids[0].temperature", "expression", "20 + sin(x"});
}

TEST(BadInput, UnwritableOutputDirectory) {
    const std::string dir = freshDir("bad_unwritable");
    writeFile(dir + "/plain_file", "not a directory");
    const Result r =
        run(FLUID_SIM, "'" + scene("tiny_2d.json") + "' --quiet --out plain_file/out", dir);
    expectMessage(r, kOutput, {"plain_file/out", "cannot create the output directory"});
}

TEST(BadInput, DiskFullLeavesNoPartialFile) {
    // Every output is written to <name>.tmp and renamed when complete. /dev/full fails every
    // write with ENOSPC: a temporary file that leads there behaves like a full disk.
    ASSERT_TRUE(std::filesystem::exists("/dev/full"));
    for (const char* file : {"particles_0000.vtu", "particles_0000.png", "particles_0000.csv"}) {
        const std::string dir = freshDir(std::string("bad_full_") + file);
        std::filesystem::create_directories(dir + "/out");
        std::filesystem::create_symlink("/dev/full", dir + "/out/" + file + ".tmp");
        const Result r = run(FLUID_SIM, "'" + scene("tiny_2d.json") + "' --quiet --out out", dir);
        expectMessage(r, kOutput, {file, "No space left on device", "disk is full"});
        EXPECT_FALSE(std::filesystem::exists(dir + "/out/" + file)) << file;
    }
}

TEST(BadInput, ThreeDSceneGivenToTheTwoDApp) {
    const Result r = run(FLUID_SIM, "'" + scene("tiny_3d.json") + "' --quiet", freshDir("bad_dim"));
    expectMessage(r, kScene, {"3D scene", "fluid_sim_3d"});
    const Result r3 =
        run(FLUID_SIM_3D, "'" + scene("tiny_2d.json") + "' --quiet", freshDir("bad_dim3"));
    expectMessage(r3, kScene, {"2D scene", "run it with fluid_sim"});
}

TEST(BadInput, UnknownMaterialSuggestsName) {
    json j = tiny();
    j["fluids"][0]["material"] = "watr";
    expectMessage(runScene("material", j.dump()), kScene,
                  {"fluids[0].material", "did you mean \"water\"?"});
}

TEST(BadInput, BadCommandLine) {
    const std::string dir = freshDir("bad_cli");
    expectMessage(run(FLUID_SIM, "--backend gpu", dir), kUsage, {"--backend"});
    const Result r = run(FLUID_SIM, "--set particles.spacing", dir);
    expectMessage(r, kUsage, {"KEY=VALUE"});
}

TEST(BadInput, CorruptedAndTruncatedCheckpoints) {
    const std::string dir = freshDir("bad_checkpoint");
    const Result ok =
        run(FLUID_SIM, "'" + scene("tiny_2d.json") + "' --quiet --out out --checkpoint-every 0.01",
            dir);
    ASSERT_EQ(ok.code, 0) << ok.output;
    const std::string good = readFile(dir + "/out/checkpoint_0001.chk");
    ASSERT_GT(good.size(), 100u);
    std::string flipped = good;
    flipped[flipped.size() / 2] ^= 0x10;
    writeFile(dir + "/corrupted.chk", flipped);
    expectMessage(run(FLUID_SIM, "--quiet --restart corrupted.chk", dir), kCheckpoint,
                  {"corrupted.chk", "checksum", "corrupted"});
    writeFile(dir + "/truncated.chk", good.substr(0, good.size() - 100));
    expectMessage(run(FLUID_SIM, "--quiet --restart truncated.chk", dir), kCheckpoint,
                  {"truncated.chk", "truncated"});
    writeFile(dir + "/other.chk", "{\"dimension\": 2}");
    expectMessage(run(FLUID_SIM, "--quiet --restart other.chk", dir), kCheckpoint,
                  {"other.chk", "not a numerics checkpoint"});
    expectMessage(run(FLUID_SIM_3D, "--quiet --restart out/checkpoint_0001.chk", dir), kCheckpoint,
                  {"2D checkpoint", "fluid_sim"});
}

// A checkpoint edited after it was written, its checksum written again to match, ended as an
// internal error (issue 47): every such edit is a checkpoint error (8) naming the file.
TEST(BadInput, EditedCheckpointsWithARewrittenChecksum) {
    const std::string dir = freshDir("bad_checkpoint_edited");
    const Result ok =
        run(FLUID_SIM, "'" + scene("tiny_2d.json") + "' --quiet --out out --checkpoint-every 0.01",
            dir);
    ASSERT_EQ(ok.code, 0) << ok.output;
    const std::string path = dir + "/out/checkpoint_0001.chk";
    const std::string payload = num::app::checkpointPayload(readFile(path), path, 2);
    // The payload: the scene (8-byte length, text), the fingerprint, the run state, the particles.
    std::uint64_t sceneBytes = 0;
    std::memcpy(&sceneBytes, payload.data(), sizeof sceneBytes);
    const std::size_t afterScene = 8 + sceneBytes;
    const std::vector<std::pair<std::string, std::string>> edits = {
        {"cut_end", payload.substr(0, payload.size() - 8)},
        {"extra_bytes", payload + std::string(8, '\0')},
        {"scene_not_json", std::string("\x01\0\0\0\0\0\0\0{", 9) + payload.substr(afterScene)},
        {"huge_length", std::string(8, '\xff') + payload.substr(8)},
    };
    for (const auto& [name, edited] : edits) {
        writeFile(dir + "/" + name + ".chk", num::app::checkpointBytes(2, edited));
        const Result r = run(FLUID_SIM, "--quiet --out again --restart " + name + ".chk", dir);
        expectMessage(r, kCheckpoint, {(name + ".chk").c_str()});
        EXPECT_FALSE(contains(r.output, "internal error")) << name << ": " << r.output;
    }
    // Values that are finite but no run reached (1e304 in a quantity of the engine's own) pass
    // every check of the file; the first step stops as unstable (9) and says where it started.
    const std::string scrambled = payload.substr(0, payload.size() / 2) + std::string(64, '\x7f') +
                                  payload.substr(payload.size() / 2 + 64);
    writeFile(dir + "/scrambled.chk", num::app::checkpointBytes(2, scrambled));
    const Result r = run(FLUID_SIM, "--quiet --out again --restart scrambled.chk", dir);
    EXPECT_TRUE(r.code == kCheckpoint || r.code == kUnstable) << r.output;
    if (r.code == kUnstable) {
        EXPECT_TRUE(contains(r.output,
                             "this was the first step from scrambled.chk: if that "
                             "checkpoint was edited"))
            << r.output;
    }
    EXPECT_FALSE(contains(r.output, "internal error")) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

// Files that are not what their names say are refused before they are read whole (issue 47):
// /dev/zero as a scene grew to gigabytes.
TEST(BadInput, EndlessFilesAreNotReadWhole) {
    const std::string dir = freshDir("bad_endless");
    expectMessage(run(FLUID_SIM, "/dev/zero --quiet", dir), kSceneFile,
                  {"/dev/zero", "larger than 16 MiB"});
    expectMessage(run(FLUID_SIM, "--quiet --restart /dev/zero", dir), kCheckpoint,
                  {"/dev/zero", "not a numerics checkpoint"});
    // A header that promises more than the file holds: refused from the header.
    std::string header("NUMSPHCK", 8);
    const std::uint32_t version = num::app::kCheckpointVersion, dim = 2, crc = 0, spare = 0;
    const std::uint64_t size = std::uint64_t(1) << 60;
    for (const auto& [p, n] : {std::pair<const void*, std::size_t>{&version, 4},
                               {&dim, 4},
                               {&size, 8},
                               {&crc, 4},
                               {&spare, 4}})
        header.append(static_cast<const char*>(p), n);
    writeFile(dir + "/promise.chk", header + "abc");
    expectMessage(run(FLUID_SIM, "--quiet --restart promise.chk", dir), kCheckpoint,
                  {"promise.chk", "truncated (35 bytes, expected 1152921504606847008)"});
    std::filesystem::create_directory(dir + "/folder.chk");
    expectMessage(run(FLUID_SIM, "--quiet --restart folder.chk", dir), kCheckpoint,
                  {"folder.chk", "a directory"});
}

// The threads a run asks for may be refused by the system (a batch system's limit on processes
// or memory): a documented exit code and one line, not an abort (issue 47). Each thread
// reserves its stack (8 MiB here) of the address space that ulimit -v bounds to 4 GB.
TEST(BadInput, ThreadsTheSystemRefuses) {
    const std::string dir = freshDir("bad_threads");
    const Result r = run("/bin/sh",
                         "-c \"ulimit -s 8192; ulimit -v 4000000; exec '" + std::string(FLUID_SIM) +
                             "' '" + scene("tiny_2d.json") + "' --quiet --out out --threads 1024\"",
                         dir);
    expectMessage(r, kResources, {"the system refused thread", "of 1024", "fewer --threads"});
}

// Water cooled through a wall below absolute zero ran on and reported success (issue 47).
TEST(BadInput, TemperatureBelowAbsoluteZeroDuringTheRun) {
    // No wall or body at a fixed temperature to feed heat back: 1 GW/m^2 leaves through the
    // floor and the water reaches absolute zero at t = 0.15 s.
    json j = tiny();
    j["boundaries"]["y_min"]["thermal"] = {{"heat_flux", -1e9}};
    j["boundaries"]["x_max"].erase("thermal");
    j["bodies"] = json::array();
    j["materials"]["water"]["conductivity"] = 1e6;
    j["output"]["formats"] = {"csv"};
    const Result r = runScene("below_absolute_zero", j.dump(), "--end-time 0.3");
    expectMessage(r, kUnstable, {"temperature reached", "below -273.15 degC", "heat_flux"});
    const json summary = json::parse(
        readFile(std::string(APP_TEST_WORK) + "/bad_below_absolute_zero/out/summary.json"));
    EXPECT_EQ(summary["status"], "unstable");
}

// Water at 20,000 degC and a run of some 1e8 steps were accepted without a word (issue 57):
// each is a warning before the run, also in summary.json.
TEST(BadInput, SceneAtTheEdgeOfSenseIsWarnedAbout) {
    json j = tiny();
    j["fluids"][0]["temperature"] = 20000;
    j["bodies"][0]["temperature"] = -50;           // a boundary condition: no warning
    j["materials"]["water"]["sound_speed"] = 1e6;  // the largest allowed: dt = 6.5e-9 s
    j["output"]["formats"] = {"csv"};
    j["output"]["images"] = false;
    const std::string dir = freshDir("bad_edge_of_sense");
    writeFile(dir + "/scene.json", j.dump());
    // Stopped after its first step (NUMERICS_TEST_SIGNAL): the warnings come before the run.
    const Result r = run("/usr/bin/env",
                         "NUMERICS_TEST_SIGNAL=2:1 '" + std::string(FLUID_SIM) +
                             "' scene.json --out out --end-time 1",
                         dir);
    EXPECT_EQ(r.code, 130) << r.output;
    const char* parts[] = {
        "warning: scene.json: fluids[0].temperature: 20000 degC is outside -20 to 200 degC",
        "warning: scene.json: time.end: the run takes about 1.5e+08 steps or more"};
    for (const char* p : parts)
        EXPECT_TRUE(contains(r.output, p)) << "missing '" << p << "' in:\n" << r.output;
    const json summary = json::parse(readFile(dir + "/out/summary.json"));
    EXPECT_TRUE(contains(summary["warnings"].dump(), "1.5e+08 steps")) << summary.dump();
    EXPECT_FALSE(contains(r.output, "bodies[0]")) << "a body held at -50 degC is no warning";
}

// A symbolic link in a loop (or to nothing) in ./scenes aborted --list-scenes (issue 47).
TEST(BadInput, ListScenesPastBrokenLinks) {
    const std::string dir = freshDir("bad_list_scenes");
    std::filesystem::create_directories(dir + "/scenes");
    std::filesystem::copy_file(scene("tiny_2d.json"), dir + "/scenes/tiny_2d.json");
    std::filesystem::create_symlink("loop_b.json", dir + "/scenes/loop_a.json");
    std::filesystem::create_symlink("loop_a.json", dir + "/scenes/loop_b.json");
    std::filesystem::create_symlink("nowhere.json", dir + "/scenes/dangling.json");
    std::filesystem::create_symlink("validation", dir + "/scenes/validation");  // a loop too
    const Result r = run(FLUID_SIM, "--list-scenes", dir);
    EXPECT_EQ(r.code, 0) << r.output;
    EXPECT_TRUE(contains(r.output, "scenes/tiny_2d.json")) << r.output;
    EXPECT_FALSE(contains(r.output, "loop_a")) << r.output;
}

// A spacing so fine that the particle count passes the range of a long was printed as a negative
// count (issue 47).
TEST(BadInput, ImpossibleParticleCountIsPrintedAsIs) {
    const Result r = runScene("particle_count", tiny().dump(), "--set particles.spacing=1e-12");
    expectMessage(r, kScene, {"particles.spacing", "at most 20 million", "particles)"});
    EXPECT_FALSE(contains(r.output, "about -")) << r.output;
    EXPECT_TRUE(contains(r.output, "e+2")) << r.output;  // about 1e+22
}
