#include "app/render.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "app/formatted.hpp"

namespace num::app {

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
    img.text(x0 - 4, y0 - 26, "T [°C]", kText, 2);  // "T [C]" in the 5x7 font
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

/// The particles as the picture shows them: projected, with the frame of the domain.
struct View {
    std::vector<Particle2> parts;
    double uMin = 0, uMax = 0, vMin = 0, vMax = 0, dMin = 0, dMax = 0, scale = 1, radius = 1;
    std::vector<std::array<double, 2>> boxEdges, floor;  ///< 3D: the box's edges and floor
};

/// 2D: the domain as it is (with its wall layers), walls drawn as particles.
View view2d(const sph::Storage<2>& s, const RenderSettings<2>& r, int plotW) {
    const auto x = s.getValue<sph::Vector<2>>(QuantityId::POSITION);
    View w;
    w.uMin = r.min[0], w.uMax = r.max[0], w.vMin = r.min[1], w.vMax = r.max[1];
    w.scale = plotW / (w.uMax - w.uMin);
    w.radius = 0.55 * r.spacing * w.scale;
    w.parts.reserve(s.size());
    for (Size i = 0; i < s.size(); ++i) w.parts.push_back({x[i][0], x[i][1], 0, colourOf(s, i, r)});
    return w;
}

/// Whether x lies inside the box shown (a wall inside the domain rather than beyond a side).
bool insideBox(const sph::Vector<3>& x, const RenderSettings<3>& r) {
    for (int k = 0; k < 3; ++k)
        if (x[k] < r.min[k] || x[k] > r.max[k]) return false;
    return true;
}

/// 3D: an orthographic camera at azimuth 35 degrees around the up axis, elevation 30 degrees;
/// the whole box is framed, so the view does not move while the water does. The box's walls
/// are left out, drawn by its edges and floor; walls inside the box are shown cut away (their
/// half farther from the viewer than the box's centre), so the fluid inside them shows; particles
/// sorted far to near.
View view3d(const sph::Storage<3>& s, const RenderSettings<3>& r, int plotW) {
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
    View w;
    w.uMin = w.vMin = w.dMin = 1e300, w.uMax = w.vMax = w.dMax = -1e300;
    for (int c = 0; c < 8; ++c) {
        double u, v, d;
        project(corner(c), u, v, d);
        w.uMin = std::min(w.uMin, u), w.uMax = std::max(w.uMax, u), w.vMin = std::min(w.vMin, v),
        w.vMax = std::max(w.vMax, v), w.dMin = std::min(w.dMin, d), w.dMax = std::max(w.dMax, d);
        for (int k = 0; k < 3; ++k)
            if (!((c >> k) & 1)) {
                double u2, v2, d2;
                project(corner(c | 1 << k), u2, v2, d2);
                w.boxEdges.push_back({u, v}), w.boxEdges.push_back({u2, v2});
            }
    }
    // The floor (the box's lower side along the up axis), corners in order around it.
    for (int c : {0, 1 << a1, (1 << a1) | (1 << a2), 1 << a2}) {
        double u, v, d;
        project(corner(c), u, v, d);
        w.floor.push_back({u, v});
    }
    w.scale = plotW / (w.uMax - w.uMin);
    w.radius = 0.6 * r.spacing * w.scale;  // neighbours overlap a little: a continuous surface
    const auto x = s.getValue<sph::Vector<3>>(QuantityId::POSITION);
    const auto* kind = s.has(QuantityId::KIND) ? s.getValue<int>(QuantityId::KIND).data() : nullptr;
    double cu, cv, middle;  // the depth of the box's centre: walls nearer than it are cut away
    project((r.min + r.max) * 0.5, cu, cv, middle);
    w.parts.reserve(s.size());
    for (Size i = 0; i < s.size(); ++i) {
        const bool wall = kind && kind[i] == int(sph::ParticleKind::WALL);
        if (wall && !insideBox(x[i], r)) continue;
        double u, v, d;
        project(x[i], u, v, d);
        if (wall && d > middle) continue;
        w.parts.push_back({u, v, d, colourOf(s, i, r)});
    }
    std::sort(w.parts.begin(), w.parts.end(),
              [](const Particle2& a, const Particle2& b) { return a.depth < b.depth; });
    return w;
}

}  // namespace

template <int Dim>
Image renderParticles(const sph::Storage<Dim>& s, const RenderSettings<Dim>& r, double time) {
    const int margin = 16, top = 44, barSpace = 130;
    const int plotW = std::max(64, r.width - barSpace - 2 * margin);
    View w;
    if constexpr (Dim == 2)
        w = view2d(s, r, plotW);
    else
        w = view3d(s, r, plotW);
    const int plotH = std::max(32, int(std::ceil((w.vMax - w.vMin) * w.scale)));
    Image img(margin * 2 + plotW + barSpace, top + plotH + margin, kBackground);
    auto px = [&](double u) { return margin + (u - w.uMin) * w.scale; };
    auto py = [&](double v) { return top + (w.vMax - v) * w.scale; };
    for (auto& f : w.floor) f = {px(f[0]), py(f[1])};
    img.fillPolygon(w.floor, kFloor);
    for (std::size_t e = 0; e + 1 < w.boxEdges.size(); e += 2)
        img.line(px(w.boxEdges[e][0]), py(w.boxEdges[e][1]), px(w.boxEdges[e + 1][0]),
                 py(w.boxEdges[e + 1][1]), kWall);
    for (const auto& p : w.parts) {
        if constexpr (Dim == 2) {
            img.fillDisc(px(p.u), py(p.v), w.radius, p.c);
        } else {  // depth cue: the farther, the more the background shows through
            const double far = (w.dMax - p.depth) / std::max(1e-300, w.dMax - w.dMin);
            img.fillSphere(px(p.u), py(p.v), w.radius, p.c, kBackground, 0.5 * far);
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

}  // namespace num::app
