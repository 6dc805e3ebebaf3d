// A small RGB raster with the drawing the apps' pictures need (discs, rectangles, lines, text
// in DejaVu Sans through FreeType, or a built-in 5x7 font without them), a colour map, and PNG
// output through libpng.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace num::app {

struct Rgb {
    std::uint8_t r = 0, g = 0, b = 0;
};

/// Colour of u in [0, 1] on a blue-white-red map (cold to hot); clamped outside.
Rgb coolWarm(double u);
/// c scaled towards black by f in [0, 1] (1 keeps it).
Rgb shade(Rgb c, double f);
/// c moved towards d by f in [0, 1] (0 keeps c).
Rgb mix(Rgb c, Rgb d, double f);

class Image {
  public:
    Image(int width, int height, Rgb background = {});
    int width() const { return w_; }
    int height() const { return h_; }
    Rgb at(int x, int y) const;
    void set(int x, int y, Rgb c);
    void fillRect(int x0, int y0, int x1, int y1, Rgb c);
    void fillDisc(double cx, double cy, double radius, Rgb c);
    /// A sphere seen from the front: a disc lit from the upper left (diffuse and a highlight),
    /// then moved towards `fog` by fogAmount in [0, 1] (the depth cue of 3D pictures).
    void fillSphere(double cx, double cy, double radius, Rgb c, Rgb fog, double fogAmount);
    /// A convex polygon (corners in order, either orientation).
    void fillPolygon(const std::vector<std::array<double, 2>>& corners, Rgb c);
    void line(double x0, double y0, double x1, double y1, Rgb c);
    /// A line `width` pixels wide (plots).
    void thickLine(double x0, double y0, double x1, double y1, Rgb c, double width);
    /// UTF-8 text, its capitals 7 * scale pixels tall from (x, y) down: DejaVu Sans where
    /// FreeType and the font are (scripts/setup.sh), else the 5x7 font, each of its pixels a
    /// scale x scale square (capitals, digits and a few signs only).
    void text(int x, int y, const std::string& s, Rgb c, int scale = 2);
    const std::vector<std::uint8_t>& pixels() const { return px_; }

  private:
    int w_, h_;
    std::vector<std::uint8_t> px_;
};

/// Writes the image as an 8-bit RGB PNG (AppError OUTPUT on failure).
void writePng(const std::string& path, const Image& image);

}  // namespace num::app
