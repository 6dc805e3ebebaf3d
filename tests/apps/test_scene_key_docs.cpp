// docs/scenes.md's tables of the sections of plain values are the reader's key tables
// (src/scene/scene_keys.hpp), and the reader gives each absent key the table's default.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "app/scene.hpp"
#include "scene/scene_keys.hpp"

namespace {

std::string scenesDoc() {
    std::ifstream in(std::string(NUMERICS_SOURCE_DIR) + "/docs/scenes.md");
    EXPECT_TRUE(in.good());
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

/// The first table after the heading "### `section`", its lines ending in '\n'.
std::string docTable(const std::string& doc, const std::string& section) {
    const std::size_t heading = doc.find("### `" + section + "`");
    if (heading == std::string::npos) return "";
    const std::size_t begin = doc.find("\n|", heading);
    std::size_t end = begin + 1;
    while (end < doc.size() && doc[end] == '|') end = doc.find('\n', end) + 1;
    return doc.substr(begin + 1, end - begin - 1);
}

template <class Spec>
void expectDocumented(const std::string& section, const num::app::KeyTable<Spec>& keys) {
    const std::string made = num::app::keyTableMarkdown(keys);
    EXPECT_EQ(docTable(scenesDoc(), section), made)
        << "docs/scenes.md's table of `" << section
        << "` differs from the reader's keys (src/scene/scene_keys.cpp); its table is:\n"
        << made;
}

TEST(SceneKeyDocs, TheTablesAreTheReadersKeys) {
    using namespace num::app;
    expectDocumented("particles", particleKeys());
    expectDocumented("time", timeKeys());
    expectDocumented("materials", materialKeys());
    expectDocumented("physics", physicsKeys());
    expectDocumented("numerics", numericsKeys());
    expectDocumented("output", outputKeys());
}

/// An absent key gets the table's default, which is the section struct's own (sections without
/// required keys).
template <class Spec>
void expectTheStructsDefaults(const num::app::KeyTable<Spec>& keys) {
    const nlohmann::json empty = nlohmann::json::object();
    const std::string file = "scene.json";
    Spec read;
    num::app::readKeys(num::app::detail::At{empty, file, "section"}, keys, read);
    const Spec plain;
    for (const auto& k : keys)
        if (k.type != num::app::KeyType::CUSTOM)  // a CUSTOM key is left alone when absent
            std::visit([&](auto member) { EXPECT_EQ(read.*member, plain.*member) << k.name; },
                       k.field);
}

TEST(SceneKeyDocs, AbsentKeysGetTheStructsDefaults) {
    using namespace num::app;
    expectTheStructsDefaults(materialKeys());
    expectTheStructsDefaults(physicsKeys());
    expectTheStructsDefaults(numericsKeys());
    expectTheStructsDefaults(outputKeys());
}

}  // namespace
