#include "app/image.hpp"

#include "app/file.hpp"

#include <png.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>

#include "app/errors.hpp"
#include "output/font5x7.hpp"

#ifdef NUMERICS_HAVE_FREETYPE
#include <ft2build.h>
#include FT_FREETYPE_H
#endif

namespace num::app {

Rgb coolWarm(double u) {
    // Control points of a diverging map: deep blue, light blue, near white, orange, deep red.
    static const double stops[5][3] = {{0.23, 0.30, 0.75},
                                       {0.55, 0.69, 0.99},
                                       {0.87, 0.87, 0.87},
                                       {0.96, 0.60, 0.48},
                                       {0.71, 0.02, 0.15}};
    if (!(u == u)) u = 0;
    u = std::clamp(u, 0.0, 1.0) * 4.0;
    const int k = std::min(3, int(u));
    const double f = u - k;
    auto mix = [&](int c) {
        return std::uint8_t(std::lround(255 * ((1 - f) * stops[k][c] + f * stops[k + 1][c])));
    };
    return {mix(0), mix(1), mix(2)};
}

Rgb shade(Rgb c, double f) {
    f = std::clamp(f, 0.0, 1.0);
    return {std::uint8_t(c.r * f), std::uint8_t(c.g * f), std::uint8_t(c.b * f)};
}

Rgb mix(Rgb c, Rgb d, double f) {
    f = std::clamp(f, 0.0, 1.0);
    auto m = [f](std::uint8_t a, std::uint8_t b) {
        return std::uint8_t(std::lround((1 - f) * a + f * b));
    };
    return {m(c.r, d.r), m(c.g, d.g), m(c.b, d.b)};
}

Image::Image(int width, int height, Rgb bg)
    : w_(width), h_(height), px_(std::size_t(width) * height * 3) {
    for (std::size_t i = 0; i < px_.size(); i += 3)
        px_[i] = bg.r, px_[i + 1] = bg.g, px_[i + 2] = bg.b;
}

Rgb Image::at(int x, int y) const {
    const std::size_t o = (std::size_t(y) * w_ + x) * 3;
    return {px_[o], px_[o + 1], px_[o + 2]};
}

void Image::set(int x, int y, Rgb c) {
    if (x < 0 || y < 0 || x >= w_ || y >= h_) return;
    const std::size_t o = (std::size_t(y) * w_ + x) * 3;
    px_[o] = c.r, px_[o + 1] = c.g, px_[o + 2] = c.b;
}

void Image::fillRect(int x0, int y0, int x1, int y1, Rgb c) {
    for (int y = std::max(0, y0); y < std::min(h_, y1); ++y)
        for (int x = std::max(0, x0); x < std::min(w_, x1); ++x) set(x, y, c);
}

void Image::fillDisc(double cx, double cy, double r, Rgb c) {
    if (r < 0.75) {  // sub-pixel particles: one pixel
        set(int(std::floor(cx)), int(std::floor(cy)), c);
        return;
    }
    const int x0 = int(std::floor(cx - r)), x1 = int(std::ceil(cx + r));
    const int y0 = int(std::floor(cy - r)), y1 = int(std::ceil(cy + r));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
            if (dx * dx + dy * dy <= r * r) set(x, y, c);
        }
}

void Image::fillSphere(double cx, double cy, double r, Rgb c, Rgb fog, double fogAmount) {
    if (r < 1.5) return fillDisc(cx, cy, r, mix(c, fog, fogAmount));
    // Light from the upper left and towards the viewer; the half vector for the highlight.
    const double lx = -0.45, ly = -0.55, lz = 0.70;
    const double hn = std::sqrt(lx * lx + ly * ly + (lz + 1) * (lz + 1));
    const double hx = lx / hn, hy = ly / hn, hz = (lz + 1) / hn;
    const int x0 = int(std::floor(cx - r)), x1 = int(std::ceil(cx + r));
    const int y0 = int(std::floor(cy - r)), y1 = int(std::ceil(cy + r));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const double nx = (x + 0.5 - cx) / r, ny = (y + 0.5 - cy) / r;
            const double rr = nx * nx + ny * ny;
            if (rr > 1) continue;
            const double nz = std::sqrt(1 - rr);
            const double diffuse = std::max(0.0, nx * lx + ny * ly + nz * lz);
            const double spec = std::pow(std::max(0.0, nx * hx + ny * hy + nz * hz), 24);
            const Rgb lit = mix(shade(c, 0.45 + 0.55 * diffuse), {255, 255, 255}, 0.45 * spec);
            set(x, y, mix(lit, fog, fogAmount));
        }
}

void Image::fillPolygon(const std::vector<std::array<double, 2>>& p, Rgb c) {
    if (p.size() < 3) return;
    double xMin = p[0][0], xMax = xMin, yMin = p[0][1], yMax = yMin;
    for (const auto& q : p)
        xMin = std::min(xMin, q[0]), xMax = std::max(xMax, q[0]), yMin = std::min(yMin, q[1]),
        yMax = std::max(yMax, q[1]);
    for (int y = int(std::floor(yMin)); y <= int(std::ceil(yMax)); ++y)
        for (int x = int(std::floor(xMin)); x <= int(std::ceil(xMax)); ++x) {
            // Inside when the pixel centre is on the same side of every edge.
            int positive = 0, negative = 0;
            for (std::size_t k = 0; k < p.size(); ++k) {
                const auto& a = p[k];
                const auto& b = p[(k + 1) % p.size()];
                const double cross =
                    (b[0] - a[0]) * (y + 0.5 - a[1]) - (b[1] - a[1]) * (x + 0.5 - a[0]);
                positive += cross > 0, negative += cross < 0;
            }
            if (positive == 0 || negative == 0) set(x, y, c);
        }
}

void Image::thickLine(double x0, double y0, double x1, double y1, Rgb c, double width) {
    const double length = std::hypot(x1 - x0, y1 - y0);
    const int steps = int(std::ceil(length)) + 1;
    for (int k = 0; k <= steps; ++k) {
        const double f = double(k) / steps;
        fillDisc(x0 + f * (x1 - x0), y0 + f * (y1 - y0), 0.5 * width, c);
    }
}

void Image::line(double x0, double y0, double x1, double y1, Rgb c) {
    const int steps = int(std::ceil(std::max(std::abs(x1 - x0), std::abs(y1 - y0)))) + 1;
    for (int k = 0; k <= steps; ++k) {
        const double f = double(k) / steps;
        set(int(std::floor(x0 + f * (x1 - x0))), int(std::floor(y0 + f * (y1 - y0))), c);
    }
}

namespace {

/// The code points of UTF-8 text (a malformed byte stands for itself).
std::vector<char32_t> codePoints(const std::string& s) {
    std::vector<char32_t> out;
    for (std::size_t i = 0; i < s.size();) {
        const unsigned char b = s[i];
        const int extra = b >= 0xF0 ? 3 : b >= 0xE0 ? 2 : b >= 0xC0 ? 1 : 0;
        char32_t cp = extra ? b & (0x3F >> extra) : b;
        bool ok = i + extra < s.size();
        for (int k = 1; ok && k <= extra; ++k) {
            ok = (static_cast<unsigned char>(s[i + k]) & 0xC0) == 0x80;
            cp = cp << 6 | (s[i + k] & 0x3F);
        }
        out.push_back(ok ? cp : b);
        i += ok ? extra + 1 : 1;
    }
    return out;
}

/// Text in the built-in 5x7 font (capitals, digits, a few signs), where no real font is.
void text5x7(Image& img, int x, int y, const std::vector<char32_t>& s, Rgb c, int scale) {
    int n = 0;
    for (char32_t cp : s) {
        const detail::Glyph* g = cp < 128 ? detail::glyphOf(char(cp)) : nullptr;
        if (!g) continue;  // not in the font (e.g. the degree sign): left out
        for (int row = 0; row < 7; ++row)
            for (int col = 0; col < 5; ++col)
                if (g->rows[row] & (0x10 >> col))
                    img.fillRect(x + (n * 6 + col) * scale, y + row * scale,
                                 x + (n * 6 + col + 1) * scale, y + (row + 1) * scale, c);
        ++n;
    }
}

#ifdef NUMERICS_HAVE_FREETYPE
/// DejaVu Sans (Debian's fonts-dejavu-core) through FreeType, opened for one text; ok() is
/// false where the font file is missing.
class Face {
  public:
    explicit Face(int pixels) {
        if (FT_Init_FreeType(&lib_) != 0) {
            lib_ = nullptr;
            return;
        }
        if (FT_New_Face(lib_, "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", 0, &face_) != 0)
            face_ = nullptr;
        else if (FT_Set_Pixel_Sizes(face_, 0, FT_UInt(pixels)) != 0)
            FT_Done_Face(face_), face_ = nullptr;
    }
    ~Face() {
        if (face_) FT_Done_Face(face_);
        if (lib_) FT_Done_FreeType(lib_);
    }
    Face(const Face&) = delete;
    Face& operator=(const Face&) = delete;
    bool ok() const { return face_ != nullptr; }

    /// Draws the text with its baseline at y, each glyph's coverage blended over the image.
    void draw(Image& img, int x, int baseline, const std::vector<char32_t>& s, Rgb c) const {
        for (char32_t cp : s) {
            if (FT_Load_Char(face_, cp, FT_LOAD_RENDER) != 0) continue;
            const FT_GlyphSlot g = face_->glyph;
            for (unsigned row = 0; row < g->bitmap.rows; ++row)
                for (unsigned col = 0; col < g->bitmap.width; ++col) {
                    const int px = x + g->bitmap_left + int(col),
                              py = baseline - g->bitmap_top + int(row);
                    const int alpha = g->bitmap.buffer[row * g->bitmap.pitch + col];
                    if (alpha && px >= 0 && py >= 0 && px < img.width() && py < img.height())
                        img.set(px, py, mix(img.at(px, py), c, alpha / 255.0));
                }
            x += int(g->advance.x >> 6);
        }
    }

  private:
    FT_Library lib_ = nullptr;
    FT_Face face_ = nullptr;
};
#endif

}  // namespace

void Image::text(int x, int y, const std::string& s, Rgb c, int scale) {
    const std::vector<char32_t> cps = codePoints(s);
#ifdef NUMERICS_HAVE_FREETYPE
    // About the 5x7 font's height at the same scale: capitals 7 * scale pixels tall, on the
    // same baseline.
    const Face face(10 * scale);
    if (face.ok()) return face.draw(*this, x, y + 7 * scale, cps, c);
#endif
    text5x7(*this, x, y, cps, c, scale);
}

void writePng(const std::string& path, const Image& image) {
    std::string bytes;  // encoded in memory, then written whole (never a partial file)
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        throw AppError(ExitCode::OUTPUT, path + ": encoding the PNG failed");
    }
    png_set_write_fn(
        png, &bytes,
        [](png_structp p, png_bytep data, png_size_t n) {
            static_cast<std::string*>(png_get_io_ptr(p))->append(reinterpret_cast<char*>(data), n);
        },
        [](png_structp) {});
    png_set_IHDR(png, info, image.width(), image.height(), 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < image.height(); ++y)
        png_write_row(
            png, const_cast<png_bytep>(image.pixels().data() + std::size_t(y) * image.width() * 3));
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    writeFileAtomically(path, bytes, false);
}

}  // namespace num::app
