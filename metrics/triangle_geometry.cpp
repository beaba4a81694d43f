#include "metrics/triangle_geometry.h"

#include "core/distances.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace holebench {

double triangle_area(const std::array<Point, 3>& c) {
  return 0.5 * OpenMesh::cross(c[1] - c[0], c[2] - c[0]).norm();
}

bool plane_of(const std::array<Point, 3>& t, Plane& plane) {
  const Point n = OpenMesh::cross(t[1] - t[0], t[2] - t[0]);
  const double length = n.norm();
  if (!(length > 0.0))
    return false;
  plane.point = t[0];
  plane.normal = n / length;
  return true;
}

GrowingBox box_of(const std::array<Point, 3>& t) {
  GrowingBox box;
  for (const Point& p : t)
    box.add(p);
  return box;
}

std::array<double, 3> corner_distances_to_triangle(const std::array<Point, 3>& corners,
                                                   const std::array<Point, 3>& t) {
  std::array<double, 3> distance;
  for (int i = 0; i < 3; ++i)
    distance[i] = (closest_point_on_triangle(corners[i], t[0], t[1], t[2]) - corners[i]).norm();
  return distance;
}

bool segment_meets_triangle(const Point& p, const Point& q, const std::array<Point, 3>& t) {
  const Point d = q - p;
  const Point e1 = t[1] - t[0], e2 = t[2] - t[0];
  const Point h = OpenMesh::cross(d, e2);
  const double det = OpenMesh::dot(e1, h);
  if (det == 0.0)
    return false;  // parallel: coplanar contact is found by the edge distances
  const double inv = 1.0 / det;
  const Point s = p - t[0];
  const double u = OpenMesh::dot(s, h) * inv;
  if (u < 0.0 || u > 1.0)
    return false;
  const Point k = OpenMesh::cross(s, e1);
  const double v = OpenMesh::dot(d, k) * inv;
  if (v < 0.0 || u + v > 1.0)
    return false;
  const double param = OpenMesh::dot(e2, k) * inv;
  return param >= 0.0 && param <= 1.0;
}

bool edges_meet_triangles(const std::array<Point, 3>& a, const std::array<Point, 3>& b) {
  for (int i = 0; i < 3; ++i) {
    if (segment_meets_triangle(a[i], a[(i + 1) % 3], b) ||
        segment_meets_triangle(b[i], b[(i + 1) % 3], a))
      return true;
  }
  return false;
}

double triangle_triangle_distance(const std::array<Point, 3>& a, const std::array<Point, 3>& b) {
  if (edges_meet_triangles(a, b))
    return 0.0;
  // The smallest square, then one square root: the root is monotone and correctly rounded,
  // so this is the smallest of the distances, bit for bit.
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    best = std::min(best, (closest_point_on_triangle(a[i], b[0], b[1], b[2]) - a[i]).sqrnorm());
    best = std::min(best, (closest_point_on_triangle(b[i], a[0], a[1], a[2]) - b[i]).sqrnorm());
    for (int j = 0; j < 3; ++j)
      best = std::min(best,
                      segment_segment_squared_distance(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3]));
  }
  return std::sqrt(best);
}

}  // namespace holebench
