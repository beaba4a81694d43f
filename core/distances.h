// Distances between points, lines, segments and triangles in double precision, used by the
// generators (labels) and the metrics (Hausdorff, feature recovery, patch distances).
#pragma once

#include "core/mesh.h"

namespace holebench {

/// The closest point of triangle (a, b, c) to p (Ericson, Real-Time Collision Detection,
/// 5.1.5).
Point closest_point_on_triangle(const Point& p, const Point& a, const Point& b, const Point& c);

/// The distance from p to the segment [a, b] (to a when the segment is a point).
double point_segment_distance(const Point& p, const Point& a, const Point& b);

/// The distance between the segments [p1, q1] and [p2, q2] (Ericson, 5.1.9).
double segment_segment_distance(const Point& p1, const Point& q1, const Point& p2, const Point& q2);

/// The distance from p to the infinite line through a and b (a != b).
double distance_to_line(const Point& p, const Point& a, const Point& b);

}  // namespace holebench
