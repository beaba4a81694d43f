// Distances between points, segments, lines and triangles (core/distances.h), checked on
// configurations whose answer is known in closed form.
#include "core/distances.h"

#include <gtest/gtest.h>

#include <cmath>

namespace holebench {
namespace {

TEST(ClosestPointOnTriangle, RegionsOfTheTriangle) {
  const Point a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  auto expect_near = [](const Point& p, const Point& q) { EXPECT_LT((p - q).norm(), 1e-15); };
  expect_near(closest_point_on_triangle(Point(0.2, 0.2, 5), a, b, c), Point(0.2, 0.2, 0));  // face
  expect_near(closest_point_on_triangle(Point(-1, -1, 0), a, b, c), a);                  // vertex
  expect_near(closest_point_on_triangle(Point(0.5, -2, 1), a, b, c), Point(0.5, 0, 0));  // edge
  const Point p = closest_point_on_triangle(Point(1, 1, 0), a, b, c);  // hypotenuse
  EXPECT_NEAR(p[0], 0.5, 1e-15);
  EXPECT_NEAR(p[1], 0.5, 1e-15);
}

// Inside the segment's slab the distance is the distance to the line; past an end, to
// that end; a segment of length zero is its point.
TEST(PointSegmentDistance, InsideTheSlabAndPastTheEnds) {
  const Point a(1, 1, 1), b(4, 1, 1);
  EXPECT_DOUBLE_EQ(point_segment_distance(Point(2, 4, 5), a, b), 5.0);   // 3-4-5 across
  EXPECT_DOUBLE_EQ(point_segment_distance(Point(-2, 5, 1), a, b), 5.0);  // past a
  EXPECT_DOUBLE_EQ(point_segment_distance(Point(7, 1, 5), a, b), 5.0);   // past b
  EXPECT_DOUBLE_EQ(point_segment_distance(Point(4, 5, 1), a, a), 5.0);   // a point
  EXPECT_DOUBLE_EQ(distance_to_line(Point(-2, 4, 5), a, b), 5.0);        // the line goes on
}

// Skew segments: the distance is the gap between the lines where both closest points lie
// inside; crossing segments are at 0; parallel ones at their offset; and past the ends the
// distance between the nearest ends.
TEST(SegmentSegmentDistance, SkewCrossingParallelAndApart) {
  EXPECT_DOUBLE_EQ(
      segment_segment_distance(Point(-1, 0, 0), Point(1, 0, 0), Point(0, -1, 2), Point(0, 1, 2)),
      2.0);
  EXPECT_DOUBLE_EQ(
      segment_segment_distance(Point(-1, 0, 0), Point(1, 0, 0), Point(0, -1, 0), Point(0, 1, 0)),
      0.0);
  EXPECT_DOUBLE_EQ(
      segment_segment_distance(Point(0, 0, 0), Point(2, 0, 0), Point(1, 3, 0), Point(5, 3, 0)),
      3.0);
  EXPECT_DOUBLE_EQ(
      segment_segment_distance(Point(0, 0, 0), Point(1, 0, 0), Point(4, 4, 0), Point(4, 9, 0)),
      5.0);
  // Symmetric in its two segments.
  const Point p(0.3, -1.7, 2.2), q(1.9, 0.4, -0.6), r(-0.8, 0.5, 1.1), s(2.4, 2.0, 0.3);
  EXPECT_NEAR(segment_segment_distance(p, q, r, s), segment_segment_distance(r, s, p, q), 1e-15);
}

}  // namespace
}  // namespace holebench
