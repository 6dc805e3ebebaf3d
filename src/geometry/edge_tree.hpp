// A bounding-volume tree of axis-aligned boxes over the edges of 2D polygons (internal to
// numerics_geometry): the nearest edge, the even-odd count of crossings of a ray and the edges a
// segment may meet, each in about log(edges) steps instead of a loop over every edge.
//
// Its answers equal those of the plain loops bit for bit: it computes the same per-edge values
// and only skips boxes that cannot change the result, with a margin far above the rounding of
// those values (pruning less is never wrong, only slower).
#pragma once

#include <vector>

#include "geometry/solid.hpp"

namespace num::geometry::detail {

struct PolygonEdge {
    Point<2> a, b;
};

class EdgeTree {
  public:
    /// A tree over `edges` (one at least); an edge's id is its index there.
    explicit EdgeTree(const std::vector<PolygonEdge>& edges);

    /// The least segmentDistanceSqr(x, a, b) over the edges: the plain loop's minimum, exactly.
    double nearestDistanceSqr(const Point<2>& x) const;

    /// Whether a ray from x towards +x crosses an odd number of edges, an edge counting when
    /// (a.y > x.y) != (b.y > x.y) and x.x is left of its crossing: the plain loop's parity.
    bool oddCrossings(const Point<2>& x) const;

    /// The ids of the edges that segment p-q may meet: every edge whose box overlaps the box of
    /// p-q and that the line through p and q does not leave clearly on one side (a superset of
    /// the edges that touch or cross p-q, with rounding allowed for), in no particular order.
    void edgesNear(const Point<2>& p, const Point<2>& q, std::vector<int>& ids) const;

    /// The edges, in the input's order.
    std::vector<PolygonEdge> inputEdges() const;

  private:
    struct Node {
        Bounds<2> box;
        int first, count;  ///< leaf: edges_[first, first + count); inner: count = 0, children
                           ///< first and first + 1
    };
    void build(const std::vector<PolygonEdge>& edges, int slot, int begin, int end);

    std::vector<PolygonEdge> edges_;  ///< in tree order
    std::vector<int> ids_;            ///< edges_[k] is the input's edge ids_[k]
    std::vector<Node> nodes_;
    double scale_ = 0;      ///< the largest |coordinate| of a vertex
    bool rayPrune_ = true;  ///< whether the ray may skip boxes left of x (see oddCrossings)
    double raySlack_ = 0;   ///< how far a computed crossing may lie right of its edge's box
};

}  // namespace num::geometry::detail
