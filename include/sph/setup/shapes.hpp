// Shapes for particle set-up and for keeping particles out of solids: an axis-aligned box and a
// ball (a circle in 2D, a sphere in 3D), written once for every dimension. The signed distance
// and the outward normal are callable on host and device (containment in bodies, formulas/
// post_step.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "sph/host_device.hpp"
#include "sph/types.hpp"

namespace num::sph {

template <int Dim>
struct BoxOrBall {
    using Vec = Vector<Dim>;
    enum class Type { BOX, BALL };

    Type type = Type::BOX;
    Vec min{}, max{};  // box corners
    Vec center{};      // ball centre
    Float radius = 0;  // ball radius

    static BoxOrBall box(const Vec& lo, const Vec& hi) {
        BoxOrBall s;
        s.type = Type::BOX, s.min = lo, s.max = hi;
        return s;
    }
    static BoxOrBall ball(const Vec& c, Float r) {
        BoxOrBall s;
        s.type = Type::BALL, s.center = c, s.radius = r;
        return s;
    }

    /// Signed distance to the surface: negative inside, positive outside.
    NUMERICS_HD Float signedDistance(const Vec& x) const {
        if (type == Type::BALL) return norm(x - center) - radius;
        Float outside = 0, inside = -std::numeric_limits<Float>::infinity();
        for (int k = 0; k < Dim; ++k) {
            const Float d = hd::max(min[k] - x[k], x[k] - max[k]);
            outside += d > 0 ? d * d : 0;
            inside = hd::max(inside, d);
        }
        return outside > 0 ? hd::sqrt(outside) : inside;
    }
    NUMERICS_HD bool contains(const Vec& x) const { return signedDistance(x) < 0; }

    /// Unit normal of the surface nearest to x, pointing out of the shape.
    NUMERICS_HD Vec outwardNormal(const Vec& x) const {
        if (type == Type::BALL) {
            const Vec d = x - center;
            const Float r = norm(d);
            Vec n{};
            n[0] = 1;
            return r > 0 ? d / r : n;
        }
        if (!contains(x)) {  // outside: direction from the nearest box point
            Vec d{};
            for (int k = 0; k < Dim; ++k) d[k] = x[k] - hd::min(hd::max(x[k], min[k]), max[k]);
            return d / norm(d);
        }
        int best = 0;
        Float bestGap = std::numeric_limits<Float>::infinity(), sign = 1;
        for (int k = 0; k < Dim; ++k) {
            if (x[k] - min[k] < bestGap) bestGap = x[k] - min[k], best = k, sign = -1;
            if (max[k] - x[k] < bestGap) bestGap = max[k] - x[k], best = k, sign = 1;
        }
        Vec n{};
        n[best] = sign;
        return n;
    }
};

}  // namespace num::sph
