#include "io/probe_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <vector>

#include "io/formatted.hpp"

namespace num::io {

namespace {

const Rgb kBackground{255, 255, 255}, kInk{30, 30, 30}, kGrid{225, 225, 225};
const Rgb kPalette[] = {{31, 119, 180},  {214, 39, 40}, {44, 160, 44},   {255, 127, 14},
                        {148, 103, 189}, {140, 86, 75}, {227, 119, 194}, {127, 127, 127}};

struct Table {
    std::vector<std::string> names;           ///< column names after "time"
    std::vector<double> time;                 ///< one per row
    std::vector<std::vector<double>> values;  ///< [column][row]
};

Table parse(const std::string& text) {
    Table t;
    std::istringstream in(text);
    std::string line;
    if (!std::getline(in, line)) return t;
    std::istringstream header(line);
    std::string name;
    std::getline(header, name, ',');  // "time"
    while (std::getline(header, name, ',')) t.names.push_back(name);
    t.values.resize(t.names.size());
    while (std::getline(in, line)) {
        std::istringstream row(line);
        std::string cell;
        if (!std::getline(row, cell, ',')) continue;
        t.time.push_back(std::strtod(cell.c_str(), nullptr));
        for (auto& column : t.values)
            column.push_back(std::getline(row, cell, ',') ? std::strtod(cell.c_str(), nullptr)
                                                          : std::nan(""));
    }
    return t;
}

/// The panel of a column: its field, velocity components together.
std::string panelOf(const std::string& column) {
    const std::string field = column.substr(column.rfind('.') + 1);
    if (field == "vx" || field == "vy" || field == "vz") return "velocity [m/s]";
    if (field == "temperature") return "temperature [C]";
    if (field == "pressure") return "pressure [Pa]";
    if (field == "density") return "density [kg/m3]";
    if (field.rfind("force_", 0) == 0) return "force [N, in 2D N/m]";
    return field;
}

std::string label(double v) { return formatted("%.4g", std::abs(v) < 1e-12 ? 0.0 : v); }

}  // namespace

Image plotProbes(const std::string& csvText, const std::string& title, int width) {
    const Table t = parse(csvText);
    std::vector<std::string> panels;
    std::map<std::string, std::vector<std::size_t>> columnsOf;
    for (std::size_t c = 0; c < t.names.size(); ++c) {
        const std::string p = panelOf(t.names[c]);
        if (!columnsOf.count(p)) panels.push_back(p);
        columnsOf[p].push_back(c);
    }
    const int panelH = 200, top = 40, gap = 44, left = 140, legendW = 220;
    const int plotW = std::max(100, width - left - legendW - 20);
    const int height = top + std::max<int>(1, panels.size()) * (panelH + gap) + 20;
    Image img(width, height, kBackground);
    img.text(left, 12, title.empty() ? "probes" : title, kInk, 2);
    if (panels.empty() || t.time.size() < 1) {
        img.text(left, top + 20, "no probe values", kInk, 2);
        return img;
    }
    const double t0 = t.time.front(), t1 = std::max(t.time.back(), t0 + 1e-12);
    for (std::size_t p = 0; p < panels.size(); ++p) {
        const int y0 = top + int(p) * (panelH + gap) + 16, y1 = y0 + panelH;
        double lo = 1e300, hi = -1e300;
        for (std::size_t c : columnsOf[panels[p]])
            for (double v : t.values[c])
                if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
        if (lo > hi) lo = 0, hi = 1;
        if (hi - lo < 1e-12 * std::max(1.0, std::abs(hi))) lo -= 1, hi += 1;
        const double pad = 0.05 * (hi - lo);
        lo -= pad, hi += pad;
        auto X = [&](double time) { return left + (time - t0) / (t1 - t0) * plotW; };
        auto Y = [&](double v) { return y1 - (v - lo) / (hi - lo) * panelH; };
        for (int k = 0; k <= 4; ++k) {  // grid and axis labels
            const double v = lo + (hi - lo) * k / 4, time = t0 + (t1 - t0) * k / 4;
            img.line(left, Y(v), left + plotW, Y(v), kGrid);
            img.line(X(time), y0, X(time), y1, kGrid);
            const std::string lv = label(v), lt = label(time);
            img.text(left - 8 - Image::textWidth(lv, 2), int(Y(v)) - 7, lv, kInk, 2);
            img.text(int(X(time)) - Image::textWidth(lt, 2) / 2, y1 + 6, lt, kInk, 2);
        }
        img.text(left, y0 - 18, panels[p] + "   (time [s] along x)", kInk, 2);
        img.line(left, y0, left, y1, kInk), img.line(left, y1, left + plotW, y1, kInk);
        int legendY = y0 + 4, colour = 0;
        for (std::size_t c : columnsOf[panels[p]]) {
            const Rgb ink = kPalette[colour++ % std::size(kPalette)];
            for (std::size_t i = 1; i < t.time.size(); ++i) {
                const double a = t.values[c][i - 1], b = t.values[c][i];
                if (std::isfinite(a) && std::isfinite(b))  // a gap where no fluid was near
                    img.thickLine(X(t.time[i - 1]), Y(a), X(t.time[i]), Y(b), ink, 2.0);
            }
            img.fillRect(left + plotW + 16, legendY + 4, left + plotW + 36, legendY + 8, ink);
            const std::string& name = t.names[c];  // the probe; velocity keeps its component
            const bool component =
                panels[p] == "velocity [m/s]" || panels[p] == "force [N, in 2D N/m]";
            img.text(left + plotW + 42, legendY, component ? name : name.substr(0, name.rfind('.')),
                     kInk, 2);
            legendY += 22;
        }
    }
    return img;
}

}  // namespace num::io
