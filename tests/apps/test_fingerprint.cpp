// A restart whose fingerprint differs from its checkpoint's is refused (exit code 8), naming
// what differs; when the particles' quantities differ, as with a checkpoint of another version
// of numerics, the message says so and what to do. Settings no result depends on (the
// neighbour lists' skin) may differ or be absent.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "scene/fingerprint.hpp"

using namespace num::app;

namespace {

const std::string kQuantities = "engine quantities (id:order) = 0:2 1:0 11:0 112:0 \n";
const std::string kScene = "gravity[1] = -9.81\n";

/// The message of checkFingerprint, or "" when it accepts.
std::string refusal(const std::string& stored, const std::string& current) {
    try {
        checkFingerprint(stored, current, "run/checkpoint_0001.chk");
    } catch (const AppError& e) {
        EXPECT_EQ(int(e.code()), int(ExitCode::CHECKPOINT));
        return e.what();
    }
    return "";
}

}  // namespace

TEST(Fingerprint, TheSameRunRestarts) {
    EXPECT_EQ(refusal(kQuantities + kScene, kQuantities + kScene), "");
}

TEST(Fingerprint, AnotherSceneIsRefusedNamingWhatDiffers) {
    const std::string message = refusal(kQuantities + "gravity[1] = -1\n", kQuantities + kScene);
    EXPECT_NE(message.find("run/checkpoint_0001.chk"), std::string::npos) << message;
    EXPECT_NE(message.find("gravity[1] is -9.81 here, -1 in the checkpoint"), std::string::npos)
        << message;
    EXPECT_EQ(message.find("version"), std::string::npos) << message;
}

TEST(Fingerprint, OtherQuantitiesNameAnotherVersion) {
    const std::string older = "engine quantities (id:order) = 0:2 1:0 10:0 11:0 100:0 112:0 \n";
    const std::string message = refusal(older + kScene, kQuantities + kScene);
    EXPECT_NE(message.find("engine quantities (id:order)"), std::string::npos) << message;
    EXPECT_NE(message.find("another version of numerics"), std::string::npos) << message;
    EXPECT_NE(message.find("run the scene from the start"), std::string::npos) << message;
}

TEST(Fingerprint, TheNeighbourSkinMayDifferOrBeAbsent) {
    const std::string older = kQuantities + kScene + "engine setting neighbour_skin = 0.1\n";
    const std::string current = kQuantities + kScene + "engine setting neighbour_skin = 0.2\n" +
                                "engine setting neighbour_skin_max = 0.3\n";
    EXPECT_EQ(refusal(older, current), "");
    EXPECT_EQ(refusal(older, kQuantities + kScene), "");
    EXPECT_NE(refusal(older + "engine setting cfl = 0.2\n", kQuantities + kScene), "")
        << "a setting results depend on is still compared";
}

TEST(Fingerprint, AnEditedMeshFileIsNamed) {
    // A wall read from a mesh file: the fingerprint holds the file's content hash, so a restart
    // after the file was edited is refused naming the shape's key.
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "fingerprint_mesh";
    std::filesystem::create_directories(dir);
    auto write = [&](const std::string& text) { std::ofstream(dir / "cup.stl") << text; };
    const nlohmann::json scene = nlohmann::json::parse(
        R"({"walls": [{"shape": "difference", "shapes": [{"shape": "box", "min": [0, 0, 0],
            "max": [1, 1, 1]}, {"shape": "mesh", "file": "cup.stl", "scale": 0.001}]}]})");
    auto fingerprint = [&] {
        std::map<std::string, std::string> lines;
        detail::hashShapeFiles(scene, "", dir.string(), lines);
        std::string text;
        for (const auto& [key, value] : lines) text += key + " = " + value + "\n";
        return text;
    };
    write("solid cup\nendsolid cup\n");
    const std::string before = fingerprint();
    EXPECT_NE(before.find("walls[0].shapes[1].file content (FNV-1a) = "), std::string::npos)
        << before;
    EXPECT_EQ(refusal(kQuantities + before, kQuantities + fingerprint()), "");
    write("solid cup\n\nendsolid cup\n");
    const std::string message = refusal(kQuantities + before, kQuantities + fingerprint());
    EXPECT_NE(message.find("walls[0].shapes[1].file content (FNV-1a) is "), std::string::npos)
        << message;
    std::filesystem::remove_all(dir);
}

TEST(Fingerprint, APathWhoseFileIsHashedMayBeWrittenOtherwise) {
    // A checkpoint stores a mesh's and a plugin's path absolute (a restart from it alone finds
    // them); the scene file names them relative. The file's content is compared, not its name,
    // also against a checkpoint that lists the name.
    const std::string mesh = "walls[0].file content (FNV-1a) = 1234\n";
    const std::string plugin = "plugin 0 library = /lib/p.so\n";
    const std::string stored = kQuantities + kScene + mesh + plugin +
                               "walls[0].file = \"cup.stl\"\nplugins[0].library = \"p.so\"\n";
    EXPECT_EQ(refusal(stored, kQuantities + kScene + mesh + plugin), "");
    EXPECT_EQ(refusal(stored, kQuantities + kScene + mesh + plugin +
                                  "walls[0].file = \"/scenes/cup.stl\"\n"),
              "");
    EXPECT_NE(
        refusal(stored, kQuantities + kScene + "walls[0].file content (FNV-1a) = 99\n" + plugin),
        "")
        << "an edited mesh is still refused";
    EXPECT_NE(refusal(kQuantities + kScene + "walls[0].file = \"cup.stl\"\n",
                      kQuantities + kScene + "walls[0].file = \"box.stl\"\n"),
              "")
        << "a name without a content hash is compared";
}
