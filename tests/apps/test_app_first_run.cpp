// What a new user gets from the two apps' defaults, shortened: the movie (a valid MP4 when ffmpeg
// is installed, else the one-line notice), the probe plot, the ParaView script, the key figures
// as the last lines; and --list-scenes.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "app/outputs.hpp"
#include "app/scene_loader.hpp"
#include "app_runner.hpp"

namespace {

using namespace apptest;
namespace fs = std::filesystem;

std::uint32_t bigEndian32(const std::string& b, std::size_t at) {
    return std::uint32_t(std::uint8_t(b[at])) << 24 | std::uint32_t(std::uint8_t(b[at + 1])) << 16 |
           std::uint32_t(std::uint8_t(b[at + 2])) << 8 | std::uint32_t(std::uint8_t(b[at + 3]));
}

/// A PNG: its signature, an IHDR chunk of a non-empty image first and IEND last.
void expectPng(const std::string& path) {
    const std::string b = readFile(path);
    ASSERT_GT(b.size(), 33u) << path;
    EXPECT_EQ(b.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8)) << path;
    EXPECT_EQ(b.substr(12, 4), "IHDR") << path;
    EXPECT_GT(bigEndian32(b, 16), 0u) << path;
    EXPECT_GT(bigEndian32(b, 20), 0u) << path;
    EXPECT_EQ(b.substr(b.size() - 8, 4), "IEND") << path;
}

/// An MP4: top-level boxes that tile the file exactly, starting with ftyp, with moov and mdat.
void expectMp4(const std::string& path) {
    const std::string b = readFile(path);
    ASSERT_GT(b.size(), 16u) << path;
    EXPECT_EQ(b.substr(4, 4), "ftyp") << path;
    bool moov = false, mdat = false;
    std::size_t at = 0;
    while (at + 8 <= b.size()) {
        std::uint64_t size = bigEndian32(b, at);
        const std::string type = b.substr(at + 4, 4);
        if (size == 1 && at + 16 <= b.size())  // 64-bit size follows the type
            size = std::uint64_t(bigEndian32(b, at + 8)) << 32 | bigEndian32(b, at + 12);
        if (size == 0) size = b.size() - at;  // the box runs to the end of the file
        ASSERT_GE(size, 8u) << path << ": box " << type;
        moov |= type == "moov", mdat |= type == "mdat";
        at += size;
    }
    EXPECT_EQ(at, b.size()) << path << ": the boxes do not tile the file";
    EXPECT_TRUE(moov && mdat) << path;
}

bool ffmpegInstalled() { return num::app::onPath("ffmpeg"); }

/// The last non-empty line of a text.
std::string lastLine(const std::string& text) {
    std::size_t end = text.find_last_not_of('\n');
    if (end == std::string::npos) return "";
    const std::size_t start = text.rfind('\n', end);
    return text.substr(start == std::string::npos ? 0 : start + 1,
                       end - (start == std::string::npos ? 0 : start + 1) + 1);
}

/// Runs an app's default scene shortened and checks what a first run leaves behind.
void checkDefaultRun(const std::string& program, const std::string& name,
                     const std::string& shorten, const std::string& spacing) {
    const std::string dir = freshDir(name);
    const Result r = run(
        program, shorten + " --set particles.spacing=" + spacing + " --threads 2 --out out", dir);
    ASSERT_EQ(r.code, 0) << r.output;
    const std::string out = dir + "/out/";
    const auto summary = nlohmann::json::parse(readFile(out + "summary.json"));
    EXPECT_EQ(summary.at("status"), "completed");
    // The key figures of summary.json are the last lines.
    for (const char* figure : {"steps ", "particle-steps/s", "conservation", "warnings "})
        EXPECT_TRUE(contains(r.output.substr(r.output.find("summary.json")), figure))
            << figure << "\n"
            << r.output;
    if (ffmpegInstalled()) {
        expectMp4(out + "particles.mp4");
        EXPECT_EQ(summary.at("video"), "out/particles.mp4");
        EXPECT_EQ(summary.at("video_note"), "");
    } else {
        EXPECT_FALSE(fs::exists(out + "particles.mp4"));
        EXPECT_TRUE(contains(lastLine(r.output), "no movie: ffmpeg is not installed")) << r.output;
        EXPECT_TRUE(contains(summary.at("video_note").get<std::string>(), "ffmpeg"));
    }
    expectPng(out + "probes.png");
    EXPECT_EQ(summary.at("probe_plot"), "out/probes.png");
    const std::string script = readFile(out + "particles_paraview.py");
    EXPECT_EQ(summary.at("paraview_script"), "out/particles_paraview.py");
    for (const std::string& part :
         std::vector<std::string>{"from paraview.simple import", "\"particles.pvd\"",
                                  "spacing = " + spacing, "\"temperature\"", "Point Gaussian"})
        EXPECT_TRUE(contains(script, part)) << part << "\n" << script;
    // Valid Python: parsed by python3 (installed by scripts/setup.sh with the validation tools).
    ASSERT_TRUE(num::app::onPath("python3")) << "python3 is needed to check the ParaView script";
    const Result parsed = run("python3",
                              "-c 'import ast, sys; ast.parse(open(sys.argv[1]).read())' " + out +
                                  "particles_paraview.py",
                              dir);
    EXPECT_EQ(parsed.code, 0) << parsed.output;
}

TEST(FirstRun, Default2DSceneShortenedLeavesMoviePlotAndParaviewScript) {
    checkDefaultRun(FLUID_SIM, "first_run_2d", "--end-time 0.1", "0.05");
}

TEST(FirstRun, Default3DSceneShortenedLeavesMoviePlotAndParaviewScript) {
    checkDefaultRun(FLUID_SIM_3D, "first_run_3d", "--end-time 0.1", "0.04");
}

TEST(FirstRun, WithoutFfmpegTheLastLineSaysSoAndSummaryWhy) {
    const std::string dir = freshDir("first_run_no_ffmpeg");
    // An empty PATH: the app finds no ffmpeg (it is started by its full path).
    const Result r = run("env",
                         "PATH= '" + std::string(FLUID_SIM) +
                             "' --end-time 0.08 --set particles.spacing=0.05 --out out",
                         dir);
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_EQ(lastLine(r.output),
              "fluid_sim: no movie: ffmpeg is not installed "
              "(./scripts/setup.sh or apt-get install ffmpeg adds it)")
        << r.output;
    const auto summary = nlohmann::json::parse(readFile(dir + "/out/summary.json"));
    EXPECT_EQ(summary.at("video"), "");
    EXPECT_TRUE(contains(summary.at("video_note").get<std::string>(), "ffmpeg is not installed"));
    EXPECT_FALSE(fs::exists(dir + "/out/particles.mp4"));
}

TEST(FirstRun, MovieTurnedOffIsNoNoticeButSummarySaysWhy) {
    const std::string dir = freshDir("first_run_video_off");
    const Result r =
        run(FLUID_SIM,
            "--end-time 0.08 --set particles.spacing=0.05 --set output.video=false --out out", dir);
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_FALSE(contains(r.output, "no movie")) << r.output;
    const auto summary = nlohmann::json::parse(readFile(dir + "/out/summary.json"));
    EXPECT_EQ(summary.at("video_note"), "output.video is false");
}

/// The shipped scene files and the program of each (by its dimension).
std::vector<std::pair<std::string, std::string>> shippedScenes() {
    std::vector<std::pair<std::string, std::string>> scenes;
    for (const std::string sub : {"", "/validation"}) {
        if (!fs::is_directory(NUMERICS_SCENES_DIR + sub)) continue;
        for (const auto& e : fs::directory_iterator(NUMERICS_SCENES_DIR + sub))
            if (e.path().extension() == ".json") {
                const auto doc = num::app::SceneDocument::fromFile(e.path().string());
                scenes.emplace_back(e.path().string(),
                                    doc.dimension() == 3 ? "fluid_sim_3d" : "fluid_sim");
            }
    }
    return scenes;
}

TEST(ListScenes, ListsEveryShippedSceneWithItsProgramAndDescription) {
    const auto scenes = shippedScenes();
    ASSERT_GE(scenes.size(), 4u);
    for (const std::string program : {FLUID_SIM, FLUID_SIM_3D}) {
        const Result r = run(program, "--list-scenes", freshDir("list_scenes"));
        ASSERT_EQ(r.code, 0) << r.output;
        for (const auto& [file, app] : scenes) {
            const std::string line = "  " + app + " " + file + "\n";
            ASSERT_TRUE(contains(r.output, line)) << line << r.output;
            // The next line is the description, indented.
            const std::size_t next = r.output.find(line) + line.size();
            EXPECT_EQ(r.output.substr(next, 6), "      ") << file;
            EXPECT_NE(r.output.substr(next + 6, 16), "(no description)") << file;
        }
    }
    const Result r2 = run(FLUID_SIM, "--list-scenes", freshDir("list_scenes"));
    EXPECT_TRUE(contains(r2.output, "[default of fluid_sim] ")) << r2.output;
    const Result r3 = run(FLUID_SIM_3D, "--list-scenes", freshDir("list_scenes"));
    EXPECT_TRUE(contains(r3.output, "[default of fluid_sim_3d] ")) << r3.output;
}

TEST(ListScenes, PrefersTheScenesOfTheCurrentDirectory) {
    const std::string dir = freshDir("list_own_scenes");
    fs::create_directories(dir + "/scenes/validation");
    writeFile(dir + "/scenes/mine_2d.json",
              "{ \"dimension\": 2, // a comment\n \"description\": \"Mine. More text.\" }");
    writeFile(dir + "/scenes/validation/check_3d.json",
              "{ \"dimension\": 3, \"description\": \"A check\" }");
    writeFile(dir + "/scenes/broken.json", "{ \"dimension\": ");
    const Result r = run(FLUID_SIM, "--list-scenes", dir);
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_TRUE(contains(r.output, "  fluid_sim scenes/mine_2d.json\n      Mine.\n")) << r.output;
    EXPECT_TRUE(
        contains(r.output, "  fluid_sim_3d scenes/validation/check_3d.json\n      A check\n"))
        << r.output;
    EXPECT_TRUE(contains(r.output, "scenes/broken.json\n      (cannot be read: ")) << r.output;
}

}  // namespace
