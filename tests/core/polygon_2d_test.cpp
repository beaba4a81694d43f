// Tests of core/polygon_2d.h on polygons whose answers are known in closed form.
#include "core/polygon_2d.h"

#include <gtest/gtest.h>

#include <cmath>

namespace holebench {
namespace {

// The unit square, counter-clockwise, and an L (the square [0,2]^2 without [1,2]^2).
const std::vector<Point2d> kSquare = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
const std::vector<Point2d> kL = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};

TEST(Polygon2d, InsideByTheEvenOddRule) {
  EXPECT_TRUE(inside_polygon_2d(kSquare, {0.5, 0.5}));
  EXPECT_FALSE(inside_polygon_2d(kSquare, {1.5, 0.5}));
  EXPECT_FALSE(inside_polygon_2d(kSquare, {0.5, -0.1}));
  EXPECT_TRUE(inside_polygon_2d(kL, {0.5, 1.5}));
  EXPECT_FALSE(inside_polygon_2d(kL, {1.5, 1.5}));  // the notch
}

TEST(Polygon2d, DistanceToTheNearestEdge) {
  EXPECT_DOUBLE_EQ(distance_to_polygon_2d(kSquare, {0.5, 0.5}), 0.5);
  EXPECT_DOUBLE_EQ(distance_to_polygon_2d(kSquare, {0.5, 0.2}), 0.2);
  EXPECT_DOUBLE_EQ(distance_to_polygon_2d(kSquare, {2.0, 2.0}), std::sqrt(2.0));  // a corner
  EXPECT_DOUBLE_EQ(distance_to_polygon_2d(kSquare, {-0.25, 0.5}), 0.25);  // the closing edge
  EXPECT_DOUBLE_EQ(distance_to_polygon_2d(kL, {1.5, 1.5}), 0.5);
}

TEST(Polygon2d, SignedAreaIsPositiveCounterClockwise) {
  EXPECT_DOUBLE_EQ(signed_area_2d(kSquare), 1.0);
  EXPECT_DOUBLE_EQ(signed_area_2d(kL), 3.0);
  const std::vector<Point2d> clockwise(kL.rbegin(), kL.rend());
  EXPECT_DOUBLE_EQ(signed_area_2d(clockwise), -3.0);
}

}  // namespace
}  // namespace holebench
