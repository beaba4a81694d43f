// Least-squares planes.
#pragma once

#include "core/mesh.h"

#include <vector>

namespace holebench {

struct Plane {
  Point point{0.0, 0.0, 0.0};   ///< a point on the plane (the centroid of the fitted points)
  Point normal{0.0, 0.0, 1.0};  ///< unit normal
  double rms_residual = 0.0;    ///< root mean square distance of the fitted points

  double signed_distance(const Point& p) const { return OpenMesh::dot(p - point, normal); }
};

/// The total-least-squares plane of `points` (the normal is the eigenvector of the
/// smallest eigenvalue of their covariance). Needs at least three points not on a line;
/// returns std::nullopt-like `valid = false` otherwise.
struct PlaneFit {
  Plane plane;
  bool valid = false;
};
PlaneFit fit_plane(const std::vector<Point>& points);

/// The plane of each region of `mesh`, fitted to the vertices of its faces and oriented
/// along the area-weighted mean of its face normals. Index = region id.
std::vector<PlaneFit> fit_region_planes(const Mesh& mesh);

}  // namespace holebench
