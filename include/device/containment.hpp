// The solids the device step keeps fluid out of (boundary/particle_containment.hpp on the CPU):
// the bodies, then the walls inside the domain, each a box or ball (sph::BoxOrBall) or any other
// solid flattened into plain data (geometry/flat_solid.hpp), evaluated with the same formulas as
// on the host. Built from the geometry by containment_setup.hpp.
#pragma once

#include <vector>

#include "geometry/flat_solid_view.hpp"
#include "sph/bodies/body_frame.hpp"
#include "sph/formulas/post_step.hpp"
#include "sph/setup/shapes.hpp"

namespace num::device {

/// One solid of the containment: a box or ball, or the slice of the flat nodes and numbers that
/// holds a general solid.
template <int Dim>
struct ContainmentSolid {
    sph::BoxOrBall<Dim> shape;
    int firstNode = -1;  ///< -1: `shape`; else the solid's nodes [firstNode, + nodeCount)
    int nodeCount = 0, firstValue = 0, valueCount = 0;
    geometry::Bounds<Dim> bounds;  ///< PlacedShape::solidBounds: outside it, surely outside
    int moving = -1;  ///< a moving body's index (its frame; shape and bounds at t = 0), or -1

    NUMERICS_HD bool mayContain(const sph::Vector<Dim>& x) const {
        for (int k = 0; k < Dim; ++k)
            if (x[k] < bounds.min[k] || x[k] > bounds.max[k]) return false;
        return true;
    }
};

/// Every solid of the containment with the flat data of the general ones.
template <int Dim>
struct ContainmentSolids {
    std::vector<ContainmentSolid<Dim>> solids;
    std::vector<geometry::FlatNode> nodes;
    std::vector<double> values;
};

/// One solid with its flat data, in the pose of its shape (for a moving body: at t = 0).
template <int Dim>
struct SolidInPose {
    const ContainmentSolid<Dim>* s;
    const geometry::FlatNode* nodes;
    const double* values;
    NUMERICS_HD bool mayContain(const sph::Vector<Dim>& x) const { return s->mayContain(x); }
    NUMERICS_HD void contain(sph::Vector<Dim>& x, sph::Vector<Dim>& v) const {
        if (s->firstNode < 0) {
            sph::formulas::containOutsideBody<Dim>(x, v, s->shape);
        } else {
            const geometry::FlatSolidView<Dim> flat{nodes + s->firstNode, s->nodeCount,
                                                    values + s->firstValue, s->valueCount};
            sph::formulas::containOutsideBody<Dim>(x, v, flat);
        }
    }
};

/// Reflects x (and removes the velocity into it) out of every solid that may hold it
/// (sph::formulas::containOutsideBody, as ParticleContainment on the CPU); a moving body's in
/// its frame (frames: the bodies', null when none moves; sph::containInBodyFrame).
template <int Dim>
NUMERICS_HD void containOutsideSolids(sph::Vector<Dim>& x, sph::Vector<Dim>& v,
                                      const ContainmentSolid<Dim>* solids, int count,
                                      const geometry::FlatNode* nodes, const double* values,
                                      const sph::BodyFrame<Dim>* frames) {
    for (int b = 0; b < count; ++b) {
        const SolidInPose<Dim> solid{solids + b, nodes, values};
        if (frames && solids[b].moving >= 0)
            sph::containInBodyFrame<Dim>(x, v, frames[solids[b].moving], solid);
        else if (solid.mayContain(x))
            solid.contain(x, v);
    }
}

}  // namespace num::device
