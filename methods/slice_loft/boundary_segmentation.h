// Step II of the slice paper (section 4.2): the hole boundary split into segments, each in
// one region; the hole typed single-segment, multi-segment or multi-segment corner.
#pragma once

#include "methods/slice_loft/hole_structures.h"

#include <vector>

namespace holebench::slice_loft {

struct BoundarySegmentationOptions {
  /// Dihedral angle between face normals, measured in [0, 360) degrees with the sign of
  /// convexity: an edge is a region boundary when the angle lies strictly between the two
  /// thresholds (the paper's MIN_THRESHOLD / MAX_THRESHOLD; regions are the rest).
  double min_threshold_degrees = 30.0;
  double max_threshold_degrees = 330.0;
  /// Runs of fewer boundary edges are merged into their neighbour (noise guard).
  int min_segment_edges = 2;
  /// Regions of fewer faces join the neighbour they share the most edges with (noise
  /// guard: under vertex noise single faces exceed the thresholds on every side).
  int min_region_faces = 4;
};

/// True if the edge is a region boundary by the thresholds.
bool is_region_boundary_edge(const Mesh& mesh, OpenMesh::EdgeHandle e,
                             const BoundarySegmentationOptions& options);

/// Region id per face index, regions grown across edges that are not region boundaries.
std::vector<int> segment_mesh_regions(const Mesh& mesh, const BoundarySegmentationOptions& options);

/// Merges every region of fewer than `min_faces` faces into the neighbouring region it
/// shares the most edges with, smallest first.
void merge_small_regions(const Mesh& mesh, int min_faces, std::vector<int>& face_region);

/// Fills hole.segments and hole.type from the regions of the faces along the boundary.
void segment_hole_boundary(const Mesh& mesh, const std::vector<int>& face_region, Hole& hole,
                           const BoundarySegmentationOptions& options = {});

}  // namespace holebench::slice_loft
