// Where a fluid region, a body or a wall is: a box or ball (BoxOrBall, plain data) or any solid of
// include/geometry/ (a polygon, a mesh, a combination; the CUDA back end takes every one but a
// mesh, flattened by geometry/flat_solid.hpp). The set-up, the checks and the containment ask the
// placed shape, never its parts, so that boxes and balls keep their exact formulas and other solids
// use theirs.
#pragma once

#include "geometry/solid.hpp"
#include "sph/setup/shapes.hpp"

namespace num::sph {

template <int Dim>
struct PlacedShape {
    BoxOrBall<Dim> shape;                     ///< the box or ball, used when `solid` is empty
    geometry::SolidPtr<Dim> solid = nullptr;  ///< any other solid
    /// A box holding `solid`, kept for mayContain (infinite, the default: not known).
    geometry::Bounds<Dim> solidBounds{};

    bool isGeneral() const { return solid != nullptr; }
    /// Signed distance to the surface: negative inside, positive outside.
    Float signedDistance(const Vector<Dim>& x) const {
        return solid ? solid->signedDistance(x) : shape.signedDistance(x);
    }
    bool contains(const Vector<Dim>& x) const { return signedDistance(x) < 0; }
    /// False where x is surely outside: beyond `solidBounds` (a cheap test before a solid's
    /// signed distance, which for a mesh is a tree search); true otherwise.
    bool mayContain(const Vector<Dim>& x) const {
        for (int k = 0; k < Dim; ++k)
            if (x[k] < solidBounds.min[k] || x[k] > solidBounds.max[k]) return false;
        return true;
    }
    /// Unit normal of the nearest surface, pointing out of the solid.
    Vector<Dim> outwardNormal(const Vector<Dim>& x) const {
        return solid ? solid->outwardNormal(x) : shape.outwardNormal(x);
    }
    /// A box that holds every point inside (infinite components for an unbounded solid).
    geometry::Bounds<Dim> bounds() const {
        if (solid) return solid->bounds();
        if (shape.type == BoxOrBall<Dim>::Type::BOX) return {shape.min, shape.max};
        const Vector<Dim> r = Vector<Dim>::filled(shape.radius);
        return {shape.center - r, shape.center + r};
    }
};

}  // namespace num::sph
