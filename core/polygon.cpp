#include "core/polygon.h"

#include <algorithm>
#include <cmath>

namespace holebench {

Point newell_normal(const std::vector<Point>& polygon) {
  Point n(0, 0, 0);
  if (polygon.size() < 3)
    return n;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point& p = polygon[i];
    const Point& q = polygon[(i + 1) % polygon.size()];
    n[0] += (p[1] - q[1]) * (p[2] + q[2]);
    n[1] += (p[2] - q[2]) * (p[0] + q[0]);
    n[2] += (p[0] - q[0]) * (p[1] + q[1]);
  }
  return n;
}

bool inside_projected_polygon(const std::vector<Point>& polygon, const Point& direction,
                              const Point& p) {
  const double length = direction.norm();
  if (polygon.size() < 3 || !(length > 0.0))
    return false;
  const Point n = direction / length;
  // Two unit axes of the plane normal to n, the first across n's smallest component.
  const Point helper = std::abs(n[0]) <= std::abs(n[1]) && std::abs(n[0]) <= std::abs(n[2])
                           ? Point(1, 0, 0)
                       : std::abs(n[1]) <= std::abs(n[2]) ? Point(0, 1, 0)
                                                          : Point(0, 0, 1);
  Point u = OpenMesh::cross(n, helper);
  u /= u.norm();
  const Point v = OpenMesh::cross(n, u);
  const double x = OpenMesh::dot(p, u), y = OpenMesh::dot(p, v);
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const double xi = OpenMesh::dot(polygon[i], u), yi = OpenMesh::dot(polygon[i], v);
    const double xj = OpenMesh::dot(polygon[j], u), yj = OpenMesh::dot(polygon[j], v);
    if ((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi)
      inside = !inside;
  }
  return inside;
}

double diameter(const std::vector<Point>& points) {
  double d = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t j = i + 1; j < points.size(); ++j)
      d = std::max(d, (points[i] - points[j]).norm());
  }
  return d;
}

}  // namespace holebench
