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

double cone_cosine(const Point& n, const std::array<Point, 3>& t) {
  return std::clamp(OpenMesh::dot(n, triangle_unit_normal(t[0], t[1], t[2])), -1.0, 1.0);
}

void NormalConeFold::add(double cosine) {
  largest_cosine = std::max(largest_cosine, cosine);
  cone.largest_abs_cosine = std::max(cone.largest_abs_cosine, std::abs(cosine));
  ++cone.cone_faces;
}

NormalConeAngle NormalConeFold::finish(double nearest_distance) const {
  NormalConeAngle out = cone;
  out.nearest_distance = nearest_distance;
  out.smallest_deg = std::acos(largest_cosine) * 180.0 / kPi;
  return out;
}

NormalConeAngle normal_cone_angle(const embree::TriangleScene& scene, const Point& p,
                                  const Point& n, const NormalConeOptions& options) {
  const auto nearest = scene.closest_point(p);
  std::vector<int> faces = scene.faces_within(p, nearest.distance + options.tolerance);
  if (faces.empty())
    faces.push_back(nearest.face);  // the nearest face belongs to the cone by definition
  NormalConeFold fold;
  for (int face : faces)
    fold.add(cone_cosine(n, scene.triangle_of_face(face)));
  return fold.finish(nearest.distance);
}

}  // namespace holebench
