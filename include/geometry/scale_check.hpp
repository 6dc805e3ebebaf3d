// A warning for shapes whose size looks like another unit than the domain's (a mesh in
// millimetres in a scene in metres).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "geometry/solid.hpp"

namespace num::geometry {

/// A sentence when the shape's largest extent is at least 100 times larger or smaller than the
/// domain's (a likely unit mistake: 1000 for mm in m), else "". Unbounded shapes pass.
template <int Dim>
std::string scaleWarning(const Bounds<Dim>& shape, const Bounds<Dim>& domain) {
    double s = 0, d = 0;
    for (int k = 0; k < Dim; ++k)
        s = std::max(s, shape.max[k] - shape.min[k]),
        d = std::max(d, domain.max[k] - domain.min[k]);
    if (!std::isfinite(s) || !(s > 0) || !(d > 0)) return "";
    const double ratio = s / d;
    if (ratio < 100 && ratio > 0.01) return "";
    const double factor = std::pow(10.0, std::round(std::log10(ratio)));
    char text[160];
    std::snprintf(text, sizeof text,
                  "the shape is about %g times %s than the domain: is it in other units? "
                  "(\"scale\": %g would fit it)",
                  ratio >= 1 ? factor : 1 / factor, ratio >= 1 ? "larger" : "smaller", 1 / factor);
    return text;
}

}  // namespace num::geometry
