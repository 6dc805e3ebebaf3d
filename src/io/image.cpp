#include "io/image.hpp"

#include "io/file.hpp"

#include <png.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>

#include "font5x7.hpp"
#include "io/errors.hpp"

namespace num::io {

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

void Image::line(double x0, double y0, double x1, double y1, Rgb c) {
    const int steps = int(std::ceil(std::max(std::abs(x1 - x0), std::abs(y1 - y0)))) + 1;
    for (int k = 0; k <= steps; ++k) {
        const double f = double(k) / steps;
        set(int(std::floor(x0 + f * (x1 - x0))), int(std::floor(y0 + f * (y1 - y0))), c);
    }
}

void Image::text(int x, int y, const std::string& s, Rgb c, int scale) {
    for (std::size_t n = 0; n < s.size(); ++n) {
        const detail::Glyph* g = detail::glyphOf(s[n]);
        if (!g) continue;
        for (int row = 0; row < 7; ++row)
            for (int col = 0; col < 5; ++col)
                if (g->rows[row] & (0x10 >> col))
                    fillRect(x + (int(n) * 6 + col) * scale, y + row * scale,
                             x + (int(n) * 6 + col + 1) * scale, y + (row + 1) * scale, c);
    }
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

}  // namespace num::io
