// Region (CAD face) segmentation by dihedral angle.
#pragma once

#include "core/mesh.h"

#include <vector>

namespace holebench {

struct SegmentationOptions {
  /// An edge whose unsigned dihedral angle exceeds this (degrees) separates regions.
  double sharp_angle_degrees = 30.0;
};

struct SegmentationResult {
  std::vector<int> face_region;         ///< region id per face index
  int region_count = 0;                 ///< regions are numbered 0 .. region_count-1
  std::vector<EdgeHandle> sharp_edges;  ///< edges between different regions
};

/// Grows regions across edges whose dihedral angle is at most the threshold. Regions are
/// numbered in the order of their smallest face index, so the result depends only on the
/// mesh. Does not modify the mesh; see assign_regions.
SegmentationResult segment_regions(const Mesh& mesh, const SegmentationOptions& options = {});

/// Writes `segmentation.face_region` into the mesh's per-face region ids.
void assign_regions(Mesh& mesh, const SegmentationResult& segmentation);

}  // namespace holebench
