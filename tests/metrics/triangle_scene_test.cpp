#include "metrics/embree/triangle_scene.h"

#include "core/distances.h"
#include "generators/box_solid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

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

// A face deleted and not yet collected is no part of the surface: neither the nearest face
// nor in the way of a ray, while the faces kept answer with their own indices.
TEST(TriangleScene, FacesDeletedButNotCollectedAreLeftOut) {
  Mesh box = generators::make_box({Point(2.0, 1.5, 1.0), 4.0});  // two triangles a side
  std::vector<int> top;
  for (auto f : box.faces()) {
    if (region(box, f) == 5)
      top.push_back(f.idx());
  }
  ASSERT_EQ(top.size(), 2u);
  const auto faces_before = box.n_faces();
  box.delete_face(box.face_handle(top[0]), false);
  ASSERT_EQ(box.n_faces(), faces_before);  // marked only
  const TriangleScene scene(box);
  EXPECT_EQ(scene.triangle_count(), faces_before - 1);
  // Above the top's two triangles: the deleted one is nowhere nearest nor hit (a ray through
  // it goes on to the bottom), and the kept one is nearest somewhere.
  bool kept_seen = false;
  for (double x : {0.1, 0.5, 1.0, 1.5, 1.9}) {
    for (double y : {0.1, 0.75, 1.4}) {
      const auto above = scene.closest_point(Point(x, y, 3.0));
      EXPECT_NE(above.face, top[0]);
      kept_seen = kept_seen || above.face == top[1];
      const auto hit = scene.intersect(Point(x, y, 3.0), Point(0, 0, -1));
      ASSERT_TRUE(hit.hit);
      EXPECT_NE(hit.face, top[0]);
    }
  }
  EXPECT_TRUE(kept_seen);
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

// A camera's rays traced as one coherent stream hit what the same rays traced one by one hit,
// at the same distance, and the misses miss. Where a ray meets the edge between two triangles
// the two may name either: the face named lies on the ray at that distance.
TEST(TriangleScene, CoherentRaysHitWhatSingleRaysHit) {
  const Mesh box = generators::make_box({Point(2.0, 1.5, 1.0), 0.25});
  const TriangleScene scene(box);
  const Point eye(1.1, 0.9, 6.0);
  std::vector<Point> directions;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 40; ++x)
      directions.push_back(Point((x - 20) * 0.0317, (y - 20) * 0.0291, -1.0));
  std::vector<RayHit> hits;
  scene.intersect_coherent(eye, directions, hits);
  ASSERT_EQ(hits.size(), directions.size());
  std::size_t hit_count = 0, ties = 0;
  for (std::size_t i = 0; i < directions.size(); ++i) {
    const RayHit one = scene.intersect(eye, directions[i]);
    ASSERT_EQ(hits[i].hit, one.hit) << i;
    hit_count += one.hit;
    if (!one.hit)
      continue;
    EXPECT_EQ(hits[i].distance, one.distance) << i;
    const Point at = eye + directions[i] / directions[i].norm() * hits[i].distance;
    const auto& t = scene.triangle_of_face(hits[i].face);
    EXPECT_LT((closest_point_on_triangle(at, t[0], t[1], t[2]) - at).norm(), 1e-5) << i;
    if (hits[i].face == one.face)
      EXPECT_EQ(hits[i].normal, one.normal) << i;
    ties += hits[i].face != one.face;
  }
  EXPECT_LT(ties, hit_count / 10) << "only rays through an edge may name another face";
  EXPECT_GT(hit_count, 100u);
  EXPECT_LT(hit_count, directions.size());  // some rays pass the box
}

// faces_within against a brute-force count; with a limit, the same faces or nothing when
// more than the limit are within the radius.
TEST(TriangleScene, FacesWithinARadiusAndTheirLimit) {
  const Mesh box = generators::make_box({Point(2.0, 1.5, 1.0), 0.25});
  const TriangleScene scene(box);
  for (const Point& p : {Point(1.0, 0.75, 0.5), Point(0.1, 0.1, 0.1), Point(3.0, 3.0, 3.0)}) {
    for (double radius : {0.05, 0.3, 0.6, 1.0, 10.0}) {
      std::vector<int> expected;
      for (const auto f : box.faces()) {
        const auto& t = scene.triangle_of_face(f.idx());
        if ((closest_point_on_triangle(p, t[0], t[1], t[2]) - p).norm() <= radius)
          expected.push_back(f.idx());
      }
      EXPECT_EQ(scene.faces_within(p, radius), expected);
      const auto all = scene.faces_within(p, radius, expected.size());
      ASSERT_TRUE(all.has_value());
      EXPECT_EQ(*all, expected);
      if (!expected.empty()) {
        EXPECT_FALSE(scene.faces_within(p, radius, expected.size() - 1).has_value())
            << expected.size() << " faces within " << radius;
      }
    }
  }
}

}  // namespace
}  // namespace holebench::embree
