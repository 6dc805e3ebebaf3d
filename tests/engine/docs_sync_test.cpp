// docs/extending.md shows the full code of the three examples: it must be the code that is built
// and tested, character for character. The scene reader's defaults are sph/defaults.hpp's.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "app/scene.hpp"
#include "sph/defaults.hpp"

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

// docs/scenes.md's key tables are the reader's (tests/apps/test_scene_key_docs.cpp); the scene
// reader starts from sph/defaults.hpp's values.
TEST(Docs, ScenesStartFromTheDefaults) {
    namespace d = num::sph::defaults;
    const num::app::Scene<2> scene;
    EXPECT_EQ(scene.hOverSpacing, d::hOverSpacing);
    EXPECT_EQ(scene.kernel, d::kernel);
    EXPECT_EQ(scene.cfl, d::cfl);
    EXPECT_EQ(scene.physics.shifting, d::shifting);
    EXPECT_EQ(scene.physics.densityDiffusion, d::densityDiffusion);
    EXPECT_EQ(scene.physics.freeSurfaceTensionLimit, d::freeSurfaceTensionLimit);
    EXPECT_EQ(scene.physics.freeSurfaceDensityFloor, d::freeSurfaceDensityFloor);
    EXPECT_EQ(scene.physics.maxTension, d::maxTension);
}

}  // namespace
