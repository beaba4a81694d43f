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

/// Where the B-Rep's faces come from.
enum class FaceSource {
  /// The input's region ids (B-Rep face ids: the paper's input) where every triangle has
  /// one, else segmentation.
  InputWhenPresent,
  /// Always segmentation, as for a scan, even where the input carries face ids.
  Segmentation,
};

/// The input's region ids where every triangle has one and `source` allows it (B-Rep
/// cases, and cases punched into B-Rep files); otherwise planar region growing
/// (core/planar_segmentation.h), which is robust to vertex noise because it compares each
/// triangle with its region's fitted plane, not with its neighbours.
BrepFaces extract_brep_faces(const Mesh& mesh, const PlanarSegmentationOptions& options = {},
                             FaceSource source = FaceSource::InputWhenPresent);

}  // namespace holebench::brep_guidance
