// Feature points on boundary edges (crest-line paper, section 3.4.1): "the intersection
// point between the crest line ... with the hole boundary", a point that lies on a hole
// edge. A detected feature point inside a boundary edge is inserted into the mesh there:
// the edge and its one input face are split in two, so that the feature line starts
// exactly where the crest line crosses the boundary.
//
// The input outside the hole stays bit for bit: no existing vertex moves. The split face's
// two halves and the inserted vertex are marked `Provenance::New` (they are the method's
// triangles, made to carry the feature line); the metrics then count them as patch. The
// halves cover the input face exactly (same plane, same outline), and touch the hole
// boundary, where metrics/validity.h's check of unchanged input faces does not look.
#pragma once

#include "methods/crest_feature/feature_points.h"
#include "methods/crest_feature/hole_identification.h"

namespace holebench::crest_feature {

struct InsertedFeaturePoints {
  /// The hole with the inserted vertices in its loop (`loop`, `vertices`); the centroid,
  /// the mean edge length a of equation 4, the radius and the islands stay the input's.
  Hole hole;
  /// The features with every point on a vertex of the new loop (`loop_index` re-indexed,
  /// `edge_parameter` cleared); pairs and the corner triple unchanged.
  HoleFeatures features;
  int inserted = 0;  ///< vertices inserted (boundary edges split)
};

/// Splits, for each feature point of `features` with an `edge_parameter` (on the edge from
/// `hole.vertices[loop_index]` to the next), that boundary edge of `mesh` and its input face
/// at the point's position. Points on a vertex are re-indexed only. Deterministic.
/// \pre `hole` is a hole of `mesh` whose loop has not been filled.
InsertedFeaturePoints insert_feature_points(Mesh& mesh, const Hole& hole,
                                            const HoleFeatures& features);

}  // namespace holebench::crest_feature
