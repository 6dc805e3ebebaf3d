#include "io/render.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "io/formatted.hpp"

namespace num::io {

using sph::QuantityId;
using sph::Size;

namespace {

const Rgb kBackground{24, 26, 30}, kText{235, 235, 235}, kWall{110, 110, 118}, kFloor{44, 47, 54};

/// The colour bar at the right edge (x from x0), from y0 to y1, with its labels.
void colourBar(Image& img, int x0, int y0, int y1, double lo, double hi) {
    const int w = 22;
    for (int y = y0; y < y1; ++y)
        img.fillRect(x0, y, x0 + w, y + 1,
                     coolWarm(1.0 - double(y - y0) / std::max(1, y1 - y0 - 1)));
    for (int k = 0; k <= 4; ++k) {
        const int y = y0 + (y1 - y0 - 1) * k / 4;
        img.fillRect(x0 + w, y, x0 + w + 5, y + 1, kText);
        img.text(x0 + w + 8, y - 7, formatted("%.4g", hi - (hi - lo) * k / 4), kText, 2);
    }
    img.text(x0 - 4, y0 - 26, "T [C]", kText, 2);
}

struct Particle2 {
    double u, v, depth;
    Rgb c;
};

template <int Dim>
Rgb colourOf(const sph::Storage<Dim>& s, Size i, const RenderSettings<Dim>& r) {
    const bool hasT = s.has(QuantityId::TEMPERATURE);
    const int kind = s.has(QuantityId::KIND) ? s.template getValue<int>(QuantityId::KIND)[i] : 0;
    if (kind == int(sph::ParticleKind::WALL)) return kWall;
    if (!hasT) return {70, 130, 220};
    const double T = s.template getValue<double>(QuantityId::TEMPERATURE)[i];
    return coolWarm((T - r.colorMin) / (r.colorMax - r.colorMin));
}

}  // namespace

template <int Dim>
Image renderParticles(const sph::Storage<Dim>& s, const RenderSettings<Dim>& r, double time) {
    const int margin = 16, top = 44, barSpace = 130;
    const int plotW = std::max(64, r.width - barSpace - 2 * margin);
    const auto x = s.template getValue<sph::Vector<Dim>>(QuantityId::POSITION);
    const auto* kind =
        s.has(QuantityId::KIND) ? s.template getValue<int>(QuantityId::KIND).data() : nullptr;
    std::vector<Particle2> parts;
    parts.reserve(s.size());
    double uMin, uMax, vMin, vMax, scale, radius, dMin = 0, dMax = 0;
    std::vector<std::array<double, 2>> boxEdges, floor;
    if constexpr (Dim == 2) {
        uMin = r.min[0], uMax = r.max[0], vMin = r.min[1], vMax = r.max[1];
        scale = plotW / (uMax - uMin);
        radius = 0.55 * r.spacing * scale;
        for (Size i = 0; i < s.size(); ++i)
            parts.push_back({x[i][0], x[i][1], 0, colourOf(s, i, r)});
    } else {
        // Orthographic camera: azimuth 35 degrees around the up axis, elevation 30 degrees; the
        // whole box is framed, so the view does not move while the water does.
        const int up = r.upAxis, a1 = (up + 1) % 3, a2 = (up + 2) % 3;
        const double az = 35 * M_PI / 180, el = 30 * M_PI / 180;
        auto project = [&](const sph::Vector<3>& p, double& u, double& v, double& d) {
            const double h1 = p[a1], h2 = p[a2];
            const double side = std::cos(az) * h1 - std::sin(az) * h2;
            const double toward = std::sin(az) * h1 + std::cos(az) * h2;  // towards the viewer
            u = side;
            v = std::cos(el) * p[up] - std::sin(el) * toward;
            d = std::sin(el) * p[up] + std::cos(el) * toward;
        };
        auto corner = [&](int c) {
            sph::Vector<3> p;
            for (int k = 0; k < 3; ++k) p[k] = (c >> k) & 1 ? r.max[k] : r.min[k];
            return p;
        };
        uMin = vMin = dMin = 1e300, uMax = vMax = dMax = -1e300;
        for (int c = 0; c < 8; ++c) {
            double u, v, d;
            project(corner(c), u, v, d);
            uMin = std::min(uMin, u), uMax = std::max(uMax, u), vMin = std::min(vMin, v),
            vMax = std::max(vMax, v), dMin = std::min(dMin, d), dMax = std::max(dMax, d);
            for (int k = 0; k < 3; ++k)
                if (!((c >> k) & 1)) {
                    double u2, v2, d2;
                    project(corner(c | 1 << k), u2, v2, d2);
                    boxEdges.push_back({u, v}), boxEdges.push_back({u2, v2});
                }
        }
        // The floor (the box's lower side along the up axis), corners in order around it.
        for (int c : {0, 1 << a1, (1 << a1) | (1 << a2), 1 << a2}) {
            double u, v, d;
            project(corner(c), u, v, d);
            floor.push_back({u, v});
        }
        scale = plotW / (uMax - uMin);
        radius = 0.6 * r.spacing * scale;  // neighbours overlap a little: a continuous surface
        for (Size i = 0; i < s.size(); ++i) {
            if (kind && kind[i] == int(sph::ParticleKind::WALL)) continue;
            double u, v, d;
            project(x[i], u, v, d);
            parts.push_back({u, v, d, colourOf(s, i, r)});
        }
        std::sort(parts.begin(), parts.end(),
                  [](const Particle2& a, const Particle2& b) { return a.depth < b.depth; });
    }
    const int plotH = std::max(32, int(std::ceil((vMax - vMin) * scale)));
    Image img(margin * 2 + plotW + barSpace, top + plotH + margin, kBackground);
    auto px = [&](double u) { return margin + (u - uMin) * scale; };
    auto py = [&](double v) { return top + (vMax - v) * scale; };
    for (auto& f : floor) f = {px(f[0]), py(f[1])};
    img.fillPolygon(floor, kFloor);
    for (std::size_t e = 0; e + 1 < boxEdges.size(); e += 2)
        img.line(px(boxEdges[e][0]), py(boxEdges[e][1]), px(boxEdges[e + 1][0]),
                 py(boxEdges[e + 1][1]), kWall);
    for (const auto& p : parts) {
        if constexpr (Dim == 2) {
            img.fillDisc(px(p.u), py(p.v), radius, p.c);
        } else {  // depth cue: the farther, the more the background shows through
            const double far = (dMax - p.depth) / std::max(1e-300, dMax - dMin);
            img.fillSphere(px(p.u), py(p.v), radius, p.c, kBackground, 0.5 * far);
        }
    }
    img.text(margin, 12, "time " + formatted("%.3f", time) + " s", kText, 2);
    if (!r.title.empty()) img.text(margin + 200, 12, r.title, kText, 2);
    colourBar(img, margin + plotW + 30, top + 20, std::min(top + plotH - 10, top + 20 + 300),
              r.colorMin, r.colorMax);
    return img;
}

template Image renderParticles<2>(const sph::Storage<2>&, const RenderSettings<2>&, double);
template Image renderParticles<3>(const sph::Storage<3>&, const RenderSettings<3>&, double);

}  // namespace num::io
