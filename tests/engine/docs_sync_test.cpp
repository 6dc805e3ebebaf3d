// docs/extending.md shows the full code of both examples: it must be the code that is built
// and tested, character for character.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

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
    for (const char* example : {"spring_force.hpp", "heat_diffusion.hpp"}) {
        const std::string code = readFile(root + "/examples/" + example);
        ASSERT_GT(code.size(), 500u) << example;
        EXPECT_NE(doc.find("```cpp\n" + code + "```"), std::string::npos)
            << example << " differs from its copy in docs/extending.md";
    }
}

}  // namespace
