// Step III of the slice paper (section 4.3): missing edges traced from each segment end with
// discrete curvature continuity (equations 1-3) until they leave the hole's box; with more
// than one, the missing corner as the average of the mutually closest points of the missing
// edges, and the edges re-interpolated to end at it.
#pragma once

#include "methods/slice_loft/boundary_segmentation.h"
#include "methods/slice_loft/hole_structures.h"

namespace holebench::slice_loft {

struct MissingFeatureOptions {
  BoundarySegmentationOptions segmentation;  ///< which edges are region boundaries
  double baseline_edges = 2.0;     ///< spacing of the points curvature is taken from (edges)
  double step_edges = 0.5;         ///< tracing step (mean boundary-edge lengths)
  double max_turn_degrees = 20.0;  ///< cap on the turn per step (noise guard)
  /// Two ends whose traces start more opposite than this (cosine) are one edge through the
  /// hole; otherwise the traces meet at a corner.
  double through_edge_cosine = -0.5;
  /// The paper (section 4.3) takes the average of the mutually closest points of the missing
  /// edges as the corner, whatever their distance. With this on (the project's own guard),
  /// a corner is rejected, and the hole filled as one portion without features, when a trace
  /// passes further than `corner_tolerance_rel_box` of the hole's box diagonal from it.
  /// Off: docs/slice_loft.md ("The missing corner") has the measured comparison.
  bool reject_far_corner = false;
  double corner_tolerance_rel_box = 0.35;
};

/// Missing edges and corner of `hole` (segments filled by step II). New points are spaced
/// like the hole boundary's edges. Sets the segments' missing-curve indices. On an empty
/// result (`points` empty and no edges) `note` says why, and the hole is filled as one
/// portion.
MissingFeatures reconstruct_missing_features(const Mesh& mesh, Hole& hole,
                                             const MissingFeatureOptions& options = {});

}  // namespace holebench::slice_loft
