// Splitting a sub-hole for equation 6 (not a step of the crest-line paper, but its aim in
// 3.4.4: feature lines divide a complex hole into "smaller, more planar and simpler
// sub-holes"). Where a sub-hole's boundary projected on the plane of equation 6 intersects
// itself, it is cut by a straight chord into two sub-holes that are each as planar as any
// chord makes them (least-squares residual), and each is projected by equation 6 again.
#pragma once

#include "core/mesh.h"
#include "methods/common/planar_polygon_triangulation.h"
#include "methods/crest_feature/hole_partitioning.h"

#include <functional>
#include <vector>

namespace holebench::crest_feature {

struct PlanaritySplitOptions {
  bool enabled = true;
  int max_depth = 2;          ///< a piece may be cut again, up to this many cuts deep
  int max_chords_tried = 24;  ///< the most planar chords tried per cut, best first
};

/// One piece of a split sub-hole: its loop (running the sub-hole's way round) and its
/// triangulation by equation 6 (indices into `nodes`).
struct ProjectedPiece {
  std::vector<Node> nodes;
  PolygonTriangulation triangulation;
};

struct PlanaritySplit {
  bool ok = false;
  std::vector<ProjectedPiece> pieces;
  int chords = 0;  ///< chords cut
};

/// Cuts `loop` into pieces that `project` (equation 6's triangulation of a loop) accepts.
/// `point` gives a node's position; the chords' interior points, spaced like the loop's
/// edges, are appended to `new_points` (new_point_node numbering) only if the split works.
PlanaritySplit split_for_equation_6(
    const std::vector<Node>& loop, std::vector<Point>& new_points,
    const std::function<Point(Node)>& point,
    const std::function<PolygonTriangulation(const std::vector<Node>&)>& project,
    const PlanaritySplitOptions& options = {});

}  // namespace holebench::crest_feature
