// Where a portion's boundary touches itself. On a tessellated CAD model the hole boundary
// often runs along a sharp edge for a few edges (the triangles on one side were removed, the
// ones on the other kept), so the rebuilt missing edge (4.3) passes through boundary
// vertices: the portion bounded by the segment and the missing edges (4.4) is pinched there
// and has zero-width spikes, which no trimming domain can triangulate. The paper trims its
// composite surface with ACIS, which imprints the boundary on the surface and splits the
// faces it cuts (figure 14); here the same split is made on the boundary itself:
//   1. a missing-feature point that lies on a boundary vertex (within a tolerance) is that
//      vertex (feature_points_on_boundary), the same in every portion;
//   2. each portion's boundary loses its spikes (a path that returns the way it came) and is
//      split where it passes a node twice (simple_boundary_loops), each loop trimmed alone
//      on the portion's patch.
#pragma once

#include "methods/slice_loft/composite_surface.h"

#include <vector>

namespace holebench::slice_loft {

/// For every point of `features.points`, the vertex of `boundary_vertices` it lies on
/// (nearer than `tolerance`; the nearest if several), else an invalid handle.
std::vector<VertexHandle> feature_points_on_boundary(
    const Mesh& mesh, const std::vector<VertexHandle>& boundary_vertices,
    const MissingFeatures& features, double tolerance);

/// Replaces every feature node whose point lies on a boundary vertex by that vertex.
void snap_feature_nodes(const Mesh& mesh, const std::vector<VertexHandle>& on_boundary,
                        std::vector<BoundaryNode>& nodes);

/// The closed loop `boundary` as simple loops: repeated consecutive nodes merged, spikes
/// (a, b, a) cut off, and the loop split at every node it passes twice. Loops with fewer
/// than three nodes (zero area) are dropped. Every loop keeps the original direction.
std::vector<std::vector<BoundaryNode>> simple_boundary_loops(
    const std::vector<BoundaryNode>& boundary);

/// The portion as one portion per simple boundary loop, each island given to the loop that
/// contains it in the patch's plane.
std::vector<Portion> split_pinched_portion(const Portion& portion, const LoftedPatch& patch);

}  // namespace holebench::slice_loft
