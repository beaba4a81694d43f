#include "metrics/embree/triangle_scene.h"

#include "generators/box_solid.h"

#include <gtest/gtest.h>

#include <cmath>

namespace holebench::embree {
namespace {

TEST(TriangleScene, ClosestPointOnABox) {
  const Mesh box = generators::make_box({Point(2.0, 1.5, 1.0), 0.25});
  const TriangleScene scene(box);
  // Above the +z face: straight down. Outside a corner: the corner.
  auto above = scene.closest_point(Point(0.7, 0.4, 3.0));
  EXPECT_DOUBLE_EQ(above.distance, 2.0);
  EXPECT_EQ(region(box, box.face_handle(above.face)), 5);
  auto corner = scene.closest_point(Point(3.0, 2.5, 2.0));
  EXPECT_NEAR(corner.distance, std::sqrt(1.0 + 1.0 + 1.0), 1e-12);
  EXPECT_EQ(corner.point, Point(2.0, 1.5, 1.0));
  // Inside: the nearest face is -z at distance 0.1.
  auto inside = scene.closest_point(Point(1.0, 0.75, 0.1));
  EXPECT_NEAR(inside.distance, 0.1, 1e-12);
}

TEST(TriangleScene, RaysHitTheFrontFaceAndOcclusionAgrees) {
  const Mesh box = generators::make_box({Point(2.0, 1.5, 1.0), 0.25});
  const TriangleScene scene(box);
  const auto hit = scene.intersect(Point(1.0, 0.7, 5.0), Point(0, 0, -1));
  ASSERT_TRUE(hit.hit);
  EXPECT_NEAR(hit.distance, 4.0, 1e-5);
  EXPECT_NEAR(hit.normal[2], 1.0, 1e-12);
  EXPECT_TRUE(scene.occluded(Point(1.0, 0.7, 5.0), Point(0, 0, -1)));
  EXPECT_FALSE(scene.occluded(Point(1.0, 0.7, 5.0), Point(0, 0, 1)));
  EXPECT_FALSE(scene.occluded(Point(1.0, 0.7, 5.0), Point(0, 0, -1), 0.0, 3.9));
  EXPECT_FALSE(scene.intersect(Point(5, 5, 5), Point(1, 0, 0)).hit);
}

}  // namespace
}  // namespace holebench::embree
