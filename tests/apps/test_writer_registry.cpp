// The writers by name: the built-in formats, a writer added by name and made for a run, and the
// error an unknown format gives (the scene file, the key, and the names there are).
#include <gtest/gtest.h>

#include "app/scene_loader.hpp"
#include "app/writer_registry.hpp"

using namespace num::app;

namespace {

/// Counts its outputs; enough to tell that the registry made it with the run's context.
template <int Dim>
class CountingWriter : public IWriter<Dim> {
  public:
    explicit CountingWriter(const WriterContext& context) : prefix(context.prefix) {}
    void write(const num::sph::Storage<Dim>&, const std::vector<OutputField>&, double,
               int) override {
        ++outputs;
    }
    std::string prefix;
    int outputs = 0;
};

const std::vector<std::string> kBuiltIn = {"vtu", "csv"};

/// The message checkOutputFormats<Dim> throws for `formats` (exit code SCENE), or "".
template <int Dim>
std::string formatError(const std::vector<std::string>& formats, const WriterRegistry& writers) {
    try {
        checkOutputFormats<Dim>("scene.json", formats, writers);
    } catch (const AppError& e) {
        EXPECT_EQ(e.code(), ExitCode::SCENE);
        return e.what();
    }
    return "";
}

}  // namespace

TEST(WriterRegistry, TheBuiltInFormats) {
    const WriterRegistry writers = builtInWriters();
    EXPECT_EQ(writers.names<2>(), kBuiltIn);
    EXPECT_EQ(writers.names<3>(), kBuiltIn);
    WriterContext context;
    context.directory = "out", context.prefix = "particles";
    for (const std::string& name : kBuiltIn) {
        EXPECT_TRUE(writers.has<2>(name) && writers.has<3>(name)) << name;
        EXPECT_NE(writers.make<2>(name, context), nullptr) << name;
        EXPECT_NE(writers.make<3>(name, context), nullptr) << name;
    }
    EXPECT_FALSE(writers.has<2>("png"));
}

TEST(WriterRegistry, AWriterAddedByName) {
    WriterRegistry writers = builtInWriters();
    writers.add<CountingWriter>("counts");
    EXPECT_EQ(writers.names<2>(), (std::vector<std::string>{"vtu", "csv", "counts"}));
    WriterContext context;
    context.prefix = "run";
    const auto writer = writers.make<3>("counts", context);
    auto& counting = dynamic_cast<CountingWriter<3>&>(*writer);
    EXPECT_EQ(counting.prefix, "run");
    writer->write(num::sph::Storage<3>(), {}, 0.0, 0);
    EXPECT_EQ(counting.outputs, 1);
    EXPECT_THROW(writers.add<CountingWriter>("counts"), std::logic_error);
    EXPECT_THROW(writers.add<CountingWriter>("vtu"), std::logic_error);
    // One dimension only: the other does not list it.
    writers.add("flat", writerFactory<CountingWriter<2>>());
    EXPECT_TRUE(writers.has<2>("flat"));
    EXPECT_FALSE(writers.has<3>("flat"));
}

TEST(WriterRegistry, AnUnknownFormatListsTheNames) {
    WriterRegistry writers = builtInWriters();
    EXPECT_EQ(formatError<2>({"csv", "vtu"}, writers), "");
    EXPECT_EQ(formatError<2>({}, writers), "");
    EXPECT_EQ(formatError<2>({"vtu", "vtk"}, writers),
              "scene.json: output.formats.1: expected one of \"vtu\", \"csv\", found the string "
              "\"vtk\" (did you mean \"vtu\"?)");
    EXPECT_EQ(formatError<3>({"hdf5"}, writers),
              "scene.json: output.formats.0: expected one of \"vtu\", \"csv\", found the string "
              "\"hdf5\"");
    writers.add<CountingWriter>("counts");
    EXPECT_EQ(formatError<2>({"count"}, writers),
              "scene.json: output.formats.0: expected one of \"vtu\", \"csv\", \"counts\", found "
              "the string \"count\" (did you mean \"counts\"?)");
}

TEST(WriterRegistry, TheSceneKeepsFormatNamesInOrderOnce) {
    SceneDocument doc = SceneDocument::fromFile(std::string(APP_TEST_SCENES_DIR) + "/tiny_2d.json");
    EXPECT_EQ(readScene<2>(doc).output.formats, (std::vector<std::string>{"vtu", "csv"}));
    doc.set("output.formats=[\"csv\", \"mine\", \"csv\", \"vtu\"]");
    EXPECT_EQ(readScene<2>(doc).output.formats, (std::vector<std::string>{"csv", "mine", "vtu"}));
    doc.set("output.formats=[\"csv\", 3]");
    try {
        readScene<2>(doc);
        ADD_FAILURE() << "a format that is not a string was read";
    } catch (const AppError& e) {
        EXPECT_NE(std::string(e.what()).find("output.formats.1: expected a string"),
                  std::string::npos)
            << e.what();
    }
}
