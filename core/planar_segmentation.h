// Segmentation of a (possibly noisy) mesh into planar regions by region growing on fitted
// planes: the faces of a planar B-Rep when the mesh carries no region ids.
//
// Dihedral-angle segmentation (region_segmentation.h) compares neighbouring triangles, whose
// normals noise tilts by tens of degrees; here each face is compared with its region's
// least-squares plane, which averages the noise out. A face joins a region when its normal
// is within `max_normal_angle_degrees` of the plane's normal and its centroid within the
// distance tolerance of the plane. The tolerance adapts to the noise: a multiple of the
// median residual of local plane fits (1-rings), never below a floor relative to the
// bounding-box diagonal.
#pragma once

#include "core/mesh.h"
#include "core/plane_fit.h"

#include <vector>

namespace holebench {

struct PlanarSegmentationOptions {
  double max_normal_angle_degrees = 35.0;  ///< face normal vs. region plane normal
  double residual_factor = 4.0;            ///< distance tolerance = factor x median local residual
  double min_tolerance_rel_diag = 2e-3;    ///< floor of the distance tolerance
  int min_region_faces = 3;                ///< smaller regions are merged into a neighbour
};

struct PlanarSegmentation {
  std::vector<int> face_region;  ///< region per face index
  std::vector<PlaneFit> planes;  ///< plane per region, oriented along its faces' normals
  double distance_tolerance = 0.0;
};

/// Deterministic: seeds are taken in order of local flatness (ties by face index), regions
/// numbered in the order they are grown.
PlanarSegmentation segment_planar_regions(const Mesh& mesh,
                                          const PlanarSegmentationOptions& options = {});

}  // namespace holebench
