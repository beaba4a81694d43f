// Invariant: the normal cone does not flip on a crease. A point on the ridge of a tent has
// both sides' faces in its cone, so a normal equal to either side's deviates by 0 degrees
// (the nearest-face rule gives 0 or the full dihedral angle, depending on which face a
// search meets first); away from the crease the cone is the one face below the point.
#include "metrics/normal_cone.h"

#include "core/mesh_builder.h"
#include "metrics/embree/triangle_scene.h"

#include <gtest/gtest.h>

#include <cmath>

namespace holebench {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A tent over [-1, 1] x [0, 1]: planes z = h (1 - |x|) meeting at the ridge x = 0.
Mesh tent(double h) {
  TriangleSoup soup;
  soup.points = {Point(-1, 0, 0), Point(0, 0, h), Point(1, 0, 0),
                 Point(-1, 1, 0), Point(0, 1, h), Point(1, 1, 0)};
  soup.triangles = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}};
  return build_mesh(soup);
}

// The unit normals of the tent's two sides (x < 0, x > 0), computed here from their planes'
// points, and the angle between them in degrees.
struct TentNormals {
  Point left, right;
  double dihedral_deg() const { return std::acos(OpenMesh::dot(left, right)) * 180.0 / kPi; }
};
TentNormals tent_normals(double h) {
  return {triangle_unit_normal(Point(-1, 0, 0), Point(0, 0, h), Point(0, 1, h)),
          triangle_unit_normal(Point(0, 0, h), Point(1, 0, 0), Point(1, 1, 0))};
}

TEST(NormalConeAngle, BothSidesOfACreaseAreInTheConeOnTheRidge) {
  const double h = 0.5;
  const Mesh mesh = tent(h);
  const embree::TriangleScene scene(mesh);
  const auto [left, right] = tent_normals(h);
  ASSERT_GT(tent_normals(h).dihedral_deg(), 50.0);
  for (const Point& n : {left, right}) {
    const auto cone = normal_cone_angle(scene, Point(0.0, 0.5, h), n);
    EXPECT_EQ(cone.cone_faces, 2);  // one triangle of each side touches this ridge point
    EXPECT_NEAR(cone.smallest_deg, 0.0, 1e-6);
    EXPECT_NEAR(cone.largest_abs_cosine, 1.0, 1e-12);
    EXPECT_EQ(cone.nearest_distance, 0.0);
  }
  // A point just beside the ridge, within the tolerance: still both sides.
  const auto near = normal_cone_angle(scene, Point(1e-4, 0.5, h * (1.0 - 1e-4)), left);
  EXPECT_NEAR(near.smallest_deg, 0.0, 1e-6);
}

TEST(NormalConeAngle, AwayFromTheCreaseTheConeIsTheFaceBelow) {
  const double h = 0.5;
  const Mesh mesh = tent(h);
  const embree::TriangleScene scene(mesh);
  const auto [left, right] = tent_normals(h);
  // On the right side, far from the ridge, with the left side's normal: the full dihedral.
  const auto cone = normal_cone_angle(scene, Point(0.6, 0.3, h * 0.4), left);
  EXPECT_LE(cone.cone_faces, 2);  // the face below and, at most, its neighbour in the quad
  EXPECT_NEAR(cone.smallest_deg, tent_normals(h).dihedral_deg(), 1e-9);
  // A flipped normal deviates by 180 degrees but agrees fully in |cosine|.
  const auto flipped = normal_cone_angle(scene, Point(0.6, 0.3, h * 0.4), -right);
  EXPECT_NEAR(flipped.smallest_deg, 180.0, 1e-6);
  EXPECT_NEAR(flipped.largest_abs_cosine, 1.0, 1e-12);
}

TEST(NormalConeAngle, AZeroToleranceKeepsOnlyTheNearestFaces) {
  const double h = 0.5;
  const Mesh mesh = tent(h);
  const embree::TriangleScene scene(mesh);
  NormalConeOptions options;
  options.tolerance = 0.0;
  const Point up(0.0, 0.0, 1.0);
  // Straight above the ridge both sides are equally near: both stay in the cone.
  const auto cone = normal_cone_angle(scene, Point(0.0, 0.5, h + 0.1), up, options);
  EXPECT_GE(cone.cone_faces, 2);
  EXPECT_NEAR(cone.nearest_distance, 0.1, 1e-12);
}

}  // namespace
}  // namespace holebench
