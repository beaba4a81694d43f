// The faces of the B-Rep: which region each triangle belongs to, and each region's plane.
#pragma once

#include "core/mesh.h"
#include "core/planar_segmentation.h"
#include "core/plane_fit.h"

#include <vector>

namespace holebench::brep_guidance {

struct BrepFaces {
  std::vector<int> face_region;  ///< region (B-Rep face) per triangle index
  std::vector<PlaneFit> planes;  ///< plane per region, normal along the region's triangles
  bool from_input = false;       ///< the input's own region ids (true) or segmentation
};

/// The input's region ids where every triangle has one (B-Rep cases); otherwise planar
/// region growing (core/planar_segmentation.h), which is robust to vertex noise because it
/// compares each triangle with its region's fitted plane, not with its neighbours.
BrepFaces extract_brep_faces(const Mesh& mesh, const PlanarSegmentationOptions& options = {});

}  // namespace holebench::brep_guidance
