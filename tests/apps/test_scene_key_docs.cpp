// docs/scenes.md's tables of the domain, of the sections of plain values, of the elements of
// `emitters`, `probes` and `plugins`, of each boundary type, of a wall's `thermal` and of a
// body's motions and springs, and docs/geometry.md's table of each shape's keys, are the
// reader's key tables (src/scene/scene_keys.hpp, src/scene/boundary_types.cpp,
// src/scene/body_motion_reader.cpp, src/scene/shape_key_tables.cpp, src/plugin/plugins.cpp),
// and the reader gives each absent key the table's default.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app/scene.hpp"
#include "plugin/plugins.hpp"
#include "scene/body_motion_reader.hpp"
#include "scene/boundary_types.hpp"
#include "scene/scene_keys.hpp"
#include "scene/shape_reader.hpp"

namespace {

/// docs/`name`'s text.
std::string doc(const std::string& name = "scenes.md") {
    std::ifstream in(std::string(NUMERICS_SOURCE_DIR) + "/docs/" + name);
    EXPECT_TRUE(in.good()) << name;
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

/// The first table after the heading `title` ("### `particles`"), its lines ending in '\n'.
std::string docTable(const std::string& doc, const std::string& title) {
    const std::size_t heading = doc.find(title);
    if (heading == std::string::npos) return "";
    const std::size_t begin = doc.find("\n|", heading);
    std::size_t end = begin + 1;
    while (end < doc.size() && doc[end] == '|') end = doc.find('\n', end) + 1;
    return doc.substr(begin + 1, end - begin - 1);
}

/// The table under "### `section`" (or the heading `title`) of docs/`file` is that of `keys`.
template <class Spec>
void expectDocumented(const std::string& section, const num::app::KeyTable<Spec>& keys,
                      const std::string& title = "", const std::string& file = "scenes.md") {
    const std::string made = num::app::keyTableMarkdown(keys);
    EXPECT_EQ(docTable(doc(file), title.empty() ? "### `" + section + "`" : title), made)
        << "docs/" << file << "'s table of `" << section
        << "` differs from the reader's keys (src/scene/scene_key_tables*.cpp, "
           "src/scene/boundary_types.cpp, src/scene/body_motion_reader.cpp, "
           "src/scene/shape_key_tables.cpp, src/plugin/plugins.cpp); its table is:\n"
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
    expectDocumented("emitters", emitterKeys<2>());
    expectDocumented("probes", probeKeys<2>());
    expectDocumented("domain", domainKeys<2>());
    expectDocumented("fluids", fluidKeys<2>());
    expectDocumented("bodies", bodyKeys<2>());
    expectDocumented("walls", interiorWallKeys<2>());
    expectDocumented("shapes' transformations", transformKeys<2>(), "### Shapes");
    expectDocumented("thermal", wallThermalKeys(), "A wall's `thermal`");
    // The 3D table: a 2D mass is per metre of depth (kg/m).
    expectDocumented("bodies[i].motion (free)", freeMotionKeys<3>(), "**Free bodies**");
    expectDocumented("bodies[i].motion (prescribed)", prescribedMotionKeys<2>(),
                     "**Prescribed bodies**");
    expectDocumented("bodies[i].motion.springs", springKeys<2>(), "**Springs**");
    expectDocumented("plugins", pluginKeys<2>());
}

/// The heading of docs/geometry.md's table of a shape's keys: a line "### ..." naming it.
std::string shapeHeading(const std::string& text, const std::string& shape) {
    for (std::size_t at = text.find("\n### "); at != std::string::npos;
         at = text.find("\n### ", at + 1)) {
        const std::string line = text.substr(at + 1, text.find('\n', at + 1) - at - 1);
        if (line.find("`" + shape + "`") != std::string::npos) return line;
    }
    return "### `" + shape + "`";  // missing: docTable finds no table
}

/// Each shape of a Dim-dimensional scene has its table of keys in docs/geometry.md.
template <int Dim>
void expectShapesDocumented() {
    const std::string text = doc("geometry.md");
    for (const auto& [shape, keys] : num::app::shapeKeyTables<Dim>())
        expectDocumented(shape, *keys, shapeHeading(text, shape), "geometry.md");
}

TEST(SceneKeyDocs, TheShapesTablesAreTheReadersKeys) {
    expectShapesDocumented<2>();
    expectShapesDocumented<3>();
    EXPECT_EQ(num::app::shapeKeyTables<2>().size(), 9u);
    EXPECT_EQ(num::app::shapeKeyTables<3>().size(), 9u);
}

/// A free motion's keys are the same in 2D and 3D but for the unit of the mass.
TEST(SceneKeyDocs, TheMotionsTablesAreTheSameIn2DAnd3D) {
    using namespace num::app;
    std::string free2 = keyTableMarkdown(freeMotionKeys<2>());
    const std::size_t mass = free2.find("| `mass` | kg/m |");
    ASSERT_NE(mass, std::string::npos);
    free2.replace(mass, 17, "| `mass` | kg |");
    EXPECT_EQ(keyTableMarkdown(freeMotionKeys<3>()), free2);
    EXPECT_EQ(keyTableMarkdown(prescribedMotionKeys<3>()),
              keyTableMarkdown(prescribedMotionKeys<2>()));
    EXPECT_EQ(keyTableMarkdown(springKeys<3>()), keyTableMarkdown(springKeys<2>()));
}

/// Each boundary type with keys beside "type" has its table, under "#### `type` sides".
TEST(SceneKeyDocs, TheBoundaryTypesTablesAreTheReadersKeys) {
    using namespace num::app;
    const auto& types2 = boundaryTypes<2>();
    const auto& types3 = boundaryTypes<3>();
    ASSERT_EQ(types2.size(), types3.size());
    for (std::size_t k = 0; k < types2.size(); ++k) {
        EXPECT_EQ(keyTableMarkdown(types3[k].keys), keyTableMarkdown(types2[k].keys));
        if (types2[k].keys.empty()) continue;
        const std::string title = "#### `" + types2[k].name + "` sides";
        expectDocumented("boundaries." + types2[k].name, types2[k].keys, title);
    }
}

TEST(SceneKeyDocs, TheArraysTablesAreTheSameIn2DAnd3D) {
    using namespace num::app;
    EXPECT_EQ(keyTableMarkdown(emitterKeys<3>()), keyTableMarkdown(emitterKeys<2>()));
    EXPECT_EQ(keyTableMarkdown(probeKeys<3>()), keyTableMarkdown(probeKeys<2>()));
    EXPECT_EQ(keyTableMarkdown(domainKeys<3>()), keyTableMarkdown(domainKeys<2>()));
    EXPECT_EQ(keyTableMarkdown(fluidKeys<3>()), keyTableMarkdown(fluidKeys<2>()));
    EXPECT_EQ(keyTableMarkdown(bodyKeys<3>()), keyTableMarkdown(bodyKeys<2>()));
    EXPECT_EQ(keyTableMarkdown(interiorWallKeys<3>()), keyTableMarkdown(interiorWallKeys<2>()));
    EXPECT_EQ(keyTableMarkdown(transformKeys<3>()), keyTableMarkdown(transformKeys<2>()));
    EXPECT_EQ(keyTableMarkdown(pluginKeys<3>()), keyTableMarkdown(pluginKeys<2>()));
}

/// An absent key gets the table's default, which is the section struct's own: `read` is read
/// from `given`, an object of the section's required keys (and what they need), then its keys
/// that are neither required nor CUSTOM are compared with a plain struct's. Returns what it read.
template <class Spec>
Spec expectTheStructsDefaults(const num::app::KeyTable<Spec>& keys, Spec read = {},
                              const nlohmann::json& given = nlohmann::json::object()) {
    const std::string file = "scene.json";
    const num::app::detail::At at{given, file, "section"};
    if constexpr (requires { read.at; }) read.at = &at;
    num::app::readKeys(at, keys, read);
    const Spec plain;
    for (const auto& k : keys)
        if (k.type != num::app::KeyType::CUSTOM && !k.required)  // CUSTOM: left alone when absent
            std::visit([&](auto member) { EXPECT_EQ(read.*member, plain.*member) << k.name; },
                       k.field);
    return read;
}

template <int Dim>
void expectTheArraysDefaults() {
    using namespace num::app;
    const std::map<std::string, MaterialSpec> materials{{"water", MaterialSpec{}}};
    EmitterInput<Dim> emitter;
    emitter.materials = &materials;
    const nlohmann::json vector(std::vector<double>(Dim, 1.0));
    expectTheStructsDefaults(emitterKeys<Dim>(), emitter,
                             {{"position", vector},
                              {"direction", vector},
                              {"speed", 1},
                              {"radius", 0.1},
                              {"material", "water"}});
    BodyInput<Dim> body;
    body.materials = &materials;
    expectTheStructsDefaults(bodyKeys<Dim>(), body, {{"shape", "box"}});
    std::set<std::string> names;
    ProbeInput<Dim> probe;
    probe.names = &names;
    // A CUSTOM key left alone when absent: a point probe's are the struct's (the reader then
    // gives it its default fields).
    const Probe<Dim> point =
        expectTheStructsDefaults(probeKeys<Dim>(), probe, {{"name", "p"}, {"point", vector}});
    EXPECT_EQ(point.body, -1);
    EXPECT_EQ(point.wall, -1);
    EXPECT_EQ(point.side, -1);
    EXPECT_TRUE(point.fields.empty());
}

TEST(SceneKeyDocs, AbsentKeysGetTheStructsDefaults) {
    using namespace num::app;
    expectTheStructsDefaults(materialKeys());
    expectTheStructsDefaults(physicsKeys());
    expectTheStructsDefaults(numericsKeys());
    expectTheStructsDefaults(outputKeys());
    expectTheArraysDefaults<2>();
    expectTheArraysDefaults<3>();
    expectTheStructsDefaults(wallThermalKeys());
}

template <int Dim>
void expectTheMotionsDefaults() {
    using namespace num::app;
    // Neither density nor mass: their exactly-one check is the motion reader's, not the table's.
    expectTheStructsDefaults(freeMotionKeys<Dim>(), {}, {{"type", "free"}});
    expectTheStructsDefaults(prescribedMotionKeys<Dim>(), {}, {{"type", "prescribed"}});
    const nlohmann::json vector(std::vector<double>(Dim, 1.0));
    const SpringSpec<Dim> spring =
        expectTheStructsDefaults(springKeys<Dim>(), {}, {{"anchor", vector}, {"stiffness", 5}});
    EXPECT_EQ(spring.stiffness, 5);
    EXPECT_EQ(spring.anchorBody, -1);
    EXPECT_FALSE(spring.point);
    EXPECT_FALSE(spring.length);
}

TEST(SceneKeyDocs, AbsentMotionKeysGetTheStructsDefaults) {
    expectTheMotionsDefaults<2>();
    expectTheMotionsDefaults<3>();
}

/// readKeyValues with keys read first reads those first, then the others in the table's order,
/// and refuses a name the table does not have.
TEST(SceneKeyDocs, KeysReadFirstAreReadFirst) {
    using namespace num::app;
    const nlohmann::json given = {{"type", "free"}, {"friction", 20}, {"center_of_mass", "x"}};
    const std::string file = "scene.json";
    const detail::At at{given, file, "motion"};
    BodyMotionSpec<2> motion;
    try {
        readKeyValues(at, freeMotionKeys<2>(), motion, {"friction"});
        ADD_FAILURE() << "no error";
    } catch (const AppError& e) {
        EXPECT_NE(std::string(e.what()).find("motion.friction"), std::string::npos) << e.what();
    }
    try {
        readKeyValues(at, freeMotionKeys<2>(), motion);
        ADD_FAILURE() << "no error";
    } catch (const AppError& e) {
        EXPECT_NE(std::string(e.what()).find("motion.center_of_mass"), std::string::npos)
            << e.what();
    }
    EXPECT_THROW(readKeyValues(at, freeMotionKeys<2>(), motion, {"fiction"}), std::logic_error);
}

}  // namespace
