// Distances from points on a mesh's faces through each face's candidate triangles
// (NearFaceDistance) are the scene's closest-point distances, bit for bit.
#include "metrics/embree/near_face_distance.h"

#include "generators/case_catalog.h"
#include "metrics/embree/triangle_scene.h"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

namespace holebench::embree {
namespace {

// Points spread over every face of `mesh` (random barycentric weights, a fixed seed), face
// by face as a picture's pixels come.
std::vector<std::pair<FaceHandle, Point>> points_on_faces(const Mesh& mesh, int per_face) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<std::pair<FaceHandle, Point>> points;
  for (auto f : mesh.faces()) {
    std::vector<Point> corners;
    for (auto v : mesh.fv_range(f))
      corners.push_back(mesh.point(v));
    for (int i = 0; i < per_face; ++i) {
      double a = unit(random), b = unit(random);
      if (a + b > 1.0) {
        a = 1.0 - a;
        b = 1.0 - b;
      }
      points.emplace_back(
          f, corners[0] + (corners[1] - corners[0]) * a + (corners[2] - corners[0]) * b);
    }
  }
  return points;
}

// The noisy input's faces against the complete model: no face lies on it, every point has a
// distance of its own.
TEST(NearFaceDistance, SameDistancesAsTheScene) {
  for (const char* id : {"box/corner", "brep/k3/inner/convex-convex-convex/small"}) {
    const Case c = generators::make_case(id, 0, 25.0);
    const TriangleScene complete(c.complete);
    NearFaceDistance near(c.input, complete);
    const auto points = points_on_faces(c.input, 8);
    for (const auto& [f, p] : points)
      ASSERT_EQ(near.distance(f, p), complete.closest_point(p).distance)
          << id << " face " << f.idx();
    // Most points answered from their face's candidates (the path under test).
    EXPECT_GT(near.local_answers(), points.size() * 9 / 10) << id;
    EXPECT_EQ(near.local_answers() + near.scene_answers(), points.size()) << id;
  }
}

// No candidates allowed: every point is the scene's, with the same distances.
TEST(NearFaceDistance, FacesWithTooManyCandidatesAskTheScene) {
  const Case c = generators::make_case("box/corner", 0, 25.0);
  const TriangleScene complete(c.complete);
  NearFaceDistanceOptions options;
  options.max_candidates = 0;
  NearFaceDistance near(c.input, complete, options);
  const auto points = points_on_faces(c.input, 4);
  for (const auto& [f, p] : points)
    ASSERT_EQ(near.distance(f, p), complete.closest_point(p).distance);
  EXPECT_EQ(near.local_answers(), 0u);
  EXPECT_EQ(near.scene_answers(), points.size());
}

}  // namespace
}  // namespace holebench::embree
