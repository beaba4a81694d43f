#include "core/distances.h"

#include <algorithm>

namespace holebench {

double point_segment_distance(const Point& p, const Point& a, const Point& b) {
  const Point ab = b - a;
  const double length2 = ab.sqrnorm();
  double t = length2 > 0.0 ? OpenMesh::dot(p - a, ab) / length2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return (a + ab * t - p).norm();
}

double distance_to_line(const Point& p, const Point& a, const Point& b) {
  const Point d = (b - a) / (b - a).norm();
  const Point w = p - a;
  return (w - d * OpenMesh::dot(w, d)).norm();
}

}  // namespace holebench
