// The pictures' text (Image::text): DejaVu Sans through FreeType where the build has it, upper and
// lower case, anti-aliased, capitals 7 * scale pixels tall as the 5x7 font's; else that font.
#include <gtest/gtest.h>

#include "app/image.hpp"

namespace {

using num::app::Image;
using num::app::Rgb;

const Rgb kWhite{255, 255, 255}, kBlack{0, 0, 0};

Image drawn(const std::string& text, int scale = 2) {
    Image img(200, 60, kWhite);
    img.text(10, 10, text, kBlack, scale);
    return img;
}

bool inked(Rgb c) { return c.r < 255 || c.g < 255 || c.b < 255; }

/// The rows from the first to the last with ink, and how many pixels are neither colour.
struct Ink {
    int top = -1, bottom = -1, partial = 0;
};

Ink inkOf(const Image& img) {
    Ink ink;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const Rgb c = img.at(x, y);
            if (!inked(c)) continue;
            if (ink.top < 0) ink.top = y;
            ink.bottom = y;
            ink.partial += c.r > 0;
        }
    return ink;
}

TEST(ImageText, CapitalsAreSevenFontPixelsTall) {
    for (int scale : {1, 2, 3}) {
        const Ink ink = inkOf(drawn("HT", scale));
        ASSERT_GE(ink.top, 0) << "nothing drawn";
        EXPECT_NEAR(ink.bottom - ink.top + 1, 7 * scale, 1 + scale / 2) << scale;
        EXPECT_NEAR(ink.top, 10, 1) << scale;
    }
}

#ifdef NUMERICS_HAVE_FREETYPE
TEST(ImageText, RealFontWithLowerCaseAndSmoothEdges) {
    EXPECT_NE(drawn("a").pixels(), drawn("A").pixels());
    EXPECT_GT(inkOf(drawn("time 0.030 s")).partial, 20);  // anti-aliased
    const Ink degree = inkOf(drawn("°"));
    EXPECT_GE(degree.top, 0) << "the degree sign is drawn";
}
#else
TEST(ImageText, FiveBySevenFontWithoutFreeType) {
    EXPECT_EQ(inkOf(drawn("T")).partial, 0);  // whole pixels only
    EXPECT_LT(inkOf(drawn("°")).top, 0);      // not in the font: left out
}
#endif

}  // namespace
