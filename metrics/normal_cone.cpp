#include "metrics/normal_cone.h"

#include "core/portable_math.h"
#include "metrics/embree/triangle_scene.h"

#include <algorithm>
#include <cmath>

namespace holebench {

Point triangle_unit_normal(const Point& a, const Point& b, const Point& c) {
  Point m = OpenMesh::cross(b - a, c - a);
  const double length = m.norm();
  return length > 0.0 ? m / length : Point(0.0, 0.0, 0.0);
}

NormalConeAngle normal_cone_angle(const embree::TriangleScene& scene, const Point& p,
                                  const Point& n, const NormalConeOptions& options) {
  NormalConeAngle cone;
  const auto nearest = scene.closest_point(p);
  cone.nearest_distance = nearest.distance;
  std::vector<int> faces = scene.faces_within(p, nearest.distance + options.tolerance);
  if (faces.empty())
    faces.push_back(nearest.face);  // the nearest face belongs to the cone by definition
  double largest_cosine = -1.0;
  for (int face : faces) {
    const auto& t = scene.triangle_of_face(face);
    const Point m = triangle_unit_normal(t[0], t[1], t[2]);
    const double cosine = std::clamp(OpenMesh::dot(n, m), -1.0, 1.0);
    largest_cosine = std::max(largest_cosine, cosine);
    cone.largest_abs_cosine = std::max(cone.largest_abs_cosine, std::abs(cosine));
  }
  cone.smallest_deg = std::acos(largest_cosine) * 180.0 / kPi;
  cone.cone_faces = static_cast<int>(faces.size());
  return cone;
}

}  // namespace holebench
