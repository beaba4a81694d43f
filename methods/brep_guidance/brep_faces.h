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

struct UniteCoplanarOptions {
  /// Two neighbouring faces are one where a single plane fits both with an rms residual at
  /// most residual_ratio times the larger of their own, plus residual_floor_rel_diag of the
  /// diagonal. The default unites exactly coplanar faces only: on 20 KiCad models at 25 %
  /// noise a noise-tolerant ratio (1.0, 1.25) united faces that meet at a draft angle the
  /// noise hides, and k was right less often than with no uniting (docs/step_input.md).
  double residual_ratio = 0.0;
  double residual_floor_rel_diag = 1e-6;
  double max_normal_angle_degrees = 30.0;  ///< normals further apart are never one face
};

/// For each input region, its face: neighbouring regions that one plane fits are one face
/// (a planar B-Rep face split in two where bodies were fused: one face of the model, as the
/// hole taxonomy counts faces). A face is named by its smallest region id, so an input without
/// such neighbours keeps its ids, and new triangles take an id of the input. `planes`:
/// fit_region_planes.
std::vector<int> unite_coplanar_faces(const Mesh& mesh, const std::vector<PlaneFit>& planes,
                                      const UniteCoplanarOptions& options = {});

/// The input's region ids where every triangle has one and `source` allows it (B-Rep
/// cases, and cases punched into B-Rep files), coplanar neighbours united
/// (unite_coplanar_faces); otherwise planar region growing
/// (core/planar_segmentation.h), which is robust to vertex noise because it compares each
/// triangle with its region's fitted plane, not with its neighbours.
BrepFaces extract_brep_faces(const Mesh& mesh, const PlanarSegmentationOptions& options = {},
                             FaceSource source = FaceSource::InputWhenPresent);

}  // namespace holebench::brep_guidance
