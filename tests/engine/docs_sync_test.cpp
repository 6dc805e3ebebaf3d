// docs/extending.md shows the full code of the three examples: it must be the code that is built
// and tested, character for character. docs/scenes.md states the numerical defaults: they must
// be those of sph/defaults.hpp, the ones the scene reader uses; and it lists every name of each
// choice's table (sph/choice_table.hpp).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "io/density_choice.hpp"
#include "io/scene.hpp"
#include "sph/defaults.hpp"
#include "sph/equation_of_state_choice.hpp"
#include "sph/evaluation_mode.hpp"
#include "sph/integrator_choice.hpp"
#include "sph/kernel_table.hpp"

namespace {

std::string readFile(const std::string& path) {
    std::ifstream in(path);
    EXPECT_TRUE(in.good()) << path;
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

TEST(Docs, ExtendingShowsTheExamplesVerbatim) {
    const std::string root = NUMERICS_SOURCE_DIR;
    const std::string doc = readFile(root + "/docs/extending.md");
    for (const char* example :
         {"spring_force.hpp", "heat_diffusion.hpp", "corrected_gradient.hpp"}) {
        const std::string code = readFile(root + "/examples/" + example);
        ASSERT_GT(code.size(), 500u) << example;
        EXPECT_NE(doc.find("```cpp\n" + code + "```"), std::string::npos)
            << example << " differs from its copy in docs/extending.md";
    }
}

/// The row of docs/scenes.md's tables for `key`, from its first cell on.
std::string docRow(const std::string& doc, const std::string& key) {
    const std::size_t at = doc.find("| `" + key + "` |");
    EXPECT_NE(at, std::string::npos) << key << " has no row in docs/scenes.md";
    return at == std::string::npos ? "" : doc.substr(at, doc.find('\n', at) - at);
}

TEST(Docs, ScenesStateTheDefaults) {
    namespace d = num::sph::defaults;
    const std::string doc = readFile(std::string(NUMERICS_SOURCE_DIR) + "/docs/scenes.md");
    auto cell = [](const std::string& v) { return "| " + v + " |"; };
    auto number = [](double x) {
        std::ostringstream s;
        s << x;
        return s.str();
    };
    const bool yes = true;
    EXPECT_NE(docRow(doc, "h_over_spacing").find(cell(number(d::hOverSpacing))), std::string::npos);
    EXPECT_NE(docRow(doc, "kernel").find(cell(std::string("`\"") + d::kernel + "\"`")),
              std::string::npos);
    EXPECT_NE(docRow(doc, "cfl").find(cell(number(d::cfl))), std::string::npos);
    EXPECT_NE(docRow(doc, "density_diffusion").find(cell(number(d::densityDiffusion))),
              std::string::npos);
    EXPECT_NE(docRow(doc, "shifting").find(cell(d::shifting == yes ? "true" : "false")),
              std::string::npos);
    EXPECT_NE(docRow(doc, "free_surface_clamp")
                  .find(cell(d::freeSurfaceTensionLimit == yes ? "true" : "false")),
              std::string::npos);
    EXPECT_NE(
        docRow(doc, "free_surface_density_floor").find(cell(number(d::freeSurfaceDensityFloor))),
        std::string::npos);
    EXPECT_NE(docRow(doc, "max_tension").find(cell(number(d::maxTension))), std::string::npos);
    EXPECT_NE(docRow(doc, "eos").find(cell(std::string("`\"") + d::eos + "\"`")),
              std::string::npos);
    // The scene reader starts from the same values.
    const num::io::Scene<2> scene;
    EXPECT_EQ(scene.hOverSpacing, d::hOverSpacing);
    EXPECT_EQ(scene.kernel, d::kernel);
    EXPECT_EQ(scene.cfl, d::cfl);
    EXPECT_EQ(scene.physics.shifting, d::shifting);
    EXPECT_EQ(scene.physics.densityDiffusion, d::densityDiffusion);
    EXPECT_EQ(scene.physics.freeSurfaceTensionLimit, d::freeSurfaceTensionLimit);
    EXPECT_EQ(scene.physics.freeSurfaceDensityFloor, d::freeSurfaceDensityFloor);
    EXPECT_EQ(scene.physics.maxTension, d::maxTension);
}

/// Every name of `table` is in the row of `key`, as `name` or `"name"`.
template <class Table>
void expectTheRowListsTheTable(const std::string& doc, const std::string& key, const Table& table) {
    const std::string row = docRow(doc, key);
    for (const std::string& name : num::sph::choiceNames(table))
        EXPECT_TRUE(row.find("`" + name + "`") != std::string::npos ||
                    row.find("`\"" + name + "\"`") != std::string::npos)
            << key << ": docs/scenes.md does not list " << name;
}

TEST(Docs, ScenesListEveryChoice) {
    const std::string doc = readFile(std::string(NUMERICS_SOURCE_DIR) + "/docs/scenes.md");
    expectTheRowListsTheTable(doc, "kernel", num::sph::kernelTable);
    expectTheRowListsTheTable(doc, "evaluation", num::sph::evaluationTable);
    expectTheRowListsTheTable(doc, "integrator", num::sph::integratorTable);
    expectTheRowListsTheTable(doc, "eos", num::sph::eosTable);
    const std::string physics = doc.substr(doc.find("### `physics`"));
    expectTheRowListsTheTable(physics, "density", num::io::densityTable);
}

}  // namespace
