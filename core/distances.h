// Distances between points, lines, segments and triangles in double precision, used by the
// generators (labels) and the metrics (Hausdorff, feature recovery, patch distances).
#pragma once

#include "core/mesh.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace holebench {

/// The closest point of triangle (a, b, c) to p (Ericson, Real-Time Collision Detection,
/// 5.1.5). Defined here, inline: the distance searches call it in their innermost loops.
inline Point closest_point_on_triangle(const Point& p, const Point& a, const Point& b,
                                       const Point& c) {
  using OpenMesh::dot;
  const Point ab = b - a;
  const Point ac = c - a;
  const Point ap = p - a;
  const double d1 = dot(ab, ap);
  const double d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0)
    return a;
  const Point bp = p - b;
  const double d3 = dot(ab, bp);
  const double d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3)
    return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
    return a + ab * (d1 / (d1 - d3));
  const Point cp = p - c;
  const double d5 = dot(ab, cp);
  const double d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6)
    return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
    return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  const double denominator = 1.0 / (va + vb + vc);
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

/// The distance from p to the triangle t: |closest_point_on_triangle(p, t) - p|. The one
/// expression TriangleScene's radius query compares with its radius, so that a caller who
/// measures the faces it returns gets the numbers the query weighed.
inline double point_triangle_distance(const Point& p, const std::array<Point, 3>& t) {
  return (closest_point_on_triangle(p, t[0], t[1], t[2]) - p).norm();
}

/// The distance from p to the segment [a, b] (to a when the segment is a point).
double point_segment_distance(const Point& p, const Point& a, const Point& b);

/// The squared distance between the segments [p1, q1] and [p2, q2] (Ericson, 5.1.9). Inline,
/// as above.
inline double segment_segment_squared_distance(const Point& p1, const Point& q1, const Point& p2,
                                               const Point& q2) {
  using OpenMesh::dot;
  const Point d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  double s = 0.0, t = 0.0;
  if (a <= 0.0 && e <= 0.0)
    return r.sqrnorm();
  if (a <= 0.0) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = dot(d1, r);
    if (e <= 0.0) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = dot(d1, d2);
      const double denominator = a * e - b * b;
      s = denominator > 0.0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return ((p1 + d1 * s) - (p2 + d2 * t)).sqrnorm();
}

/// The distance between the segments [p1, q1] and [p2, q2]: the square root of the above.
inline double segment_segment_distance(const Point& p1, const Point& q1, const Point& p2,
                                       const Point& q2) {
  return std::sqrt(segment_segment_squared_distance(p1, q1, p2, q2));
}

/// The distance from p to the infinite line through a and b (a != b).
double distance_to_line(const Point& p, const Point& a, const Point& b);

}  // namespace holebench
