// The app library's number formatter: printf's text, never cut short, and the scene messages
// that use it (a spacing reads as the scene wrote it, not with six fixed decimals).
#include <gtest/gtest.h>

#include <string>

#include "app/formatted.hpp"
#include "app/scene_loader.hpp"

namespace {

using num::app::formatted;

TEST(Formatted, IsPrintfsText) {
    EXPECT_EQ(formatted("%.3g s", 0.000123456), "0.000123 s");
    EXPECT_EQ(formatted("%g", 0.008), "0.008");
    EXPECT_EQ(formatted("_%04d.", 7), "_0007.");
    EXPECT_EQ(formatted("%+.3g %%", 12.3456), "+12.3 %");
    EXPECT_EQ(formatted("no numbers"), "no numbers");
    EXPECT_EQ(formatted("%s", ""), "");
}

TEST(Formatted, IsNeverCutShort) {
    const std::string longText(1000, 'x');
    EXPECT_EQ(formatted("%s|%.17g", longText.c_str(), 0.1), longText + "|0.10000000000000001");
}

TEST(Formatted, SceneMessagesShowNumbersAsWritten) {
    num::app::SceneDocument doc =
        num::app::SceneDocument::fromFile(std::string(APP_TEST_SCENES_DIR) + "/tiny_2d.json");
    doc.set("particles.spacing=0.75");
    try {
        (void)num::app::readScene<2>(doc);
        ADD_FAILURE() << "a spacing above half the domain was accepted";
    } catch (const num::app::AppError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("0.75"), std::string::npos) << message;
        EXPECT_EQ(message.find("0.750000"), std::string::npos) << message;
    }
}

}  // namespace
