// The distance from a point to the nearest of a set of segments, answered from a bounding
// volume tree instead of a pass over every segment.
#pragma once

#include "core/mesh.h"

#include <cstddef>
#include <vector>

namespace holebench {

/// A segment [a, b] of a set searched by NearestSegment.
struct SegmentEnds {
  Point a, b;
};

/// The nearest of a fixed set of segments to a point. The segments' axis-aligned boxes form a
/// binary tree (median splits along the widest axis of the boxes' centres, up to four segments
/// a leaf); a query visits the nearer child first and skips a box only where it lies farther
/// than the nearest segment found so far by more than a margin far above rounding (1e-9 of the
/// largest coordinate). Its answer is the smallest point_segment_distance() over every segment,
/// bit for bit: the same function of the same segments, and a minimum does not depend on the
/// order it is taken in. Segments with a coordinate that is not finite are always visited.
class NearestSegment {
 public:
  explicit NearestSegment(std::vector<SegmentEnds> segments);

  /// The smallest point_segment_distance(p, s.a, s.b) over the segments; infinity for none.
  double distance(const Point& p) const;

  std::size_t size() const { return segments_.size() + unbounded_.size(); }

 private:
  struct Node {
    Point lower, upper;        ///< the box of the node's segments
    int first = 0, count = 0;  ///< a leaf's segments in `segments_` (count > 0)
    int left = -1, right = -1;
  };
  int build(int first, int count);
  double box_squared_distance(const Node& node, const Point& p) const;

  std::vector<SegmentEnds> segments_;   ///< the finite segments, in tree order
  std::vector<SegmentEnds> unbounded_;  ///< segments with a coordinate not finite
  std::vector<Node> nodes_;             ///< nodes_[0] is the root where there are segments
  double scale_ = 0.0;                  ///< the largest absolute coordinate of the segments
};

}  // namespace holebench
