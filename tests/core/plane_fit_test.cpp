#include "core/plane_fit.h"

#include "tests/test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace holebench {
namespace {

TEST(PlaneFit, PointsOnATiltedPlaneGiveThatPlane) {
  // Points on x + 2y + 2z = 3 (unit normal (1, 2, 2) / 3).
  std::vector<Point> points;
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 4; ++j) {
      const double x = i, y = j;
      points.emplace_back(x, y, (3.0 - x - 2.0 * y) / 2.0);
    }
  }
  const PlaneFit fit = fit_plane(points);
  ASSERT_TRUE(fit.valid);
  const Point expected(1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0);
  EXPECT_NEAR(std::abs(OpenMesh::dot(fit.plane.normal, expected)), 1.0, 1e-12);
  EXPECT_NEAR(fit.plane.rms_residual, 0.0, 1e-12);
  for (const Point& p : points)
    EXPECT_NEAR(fit.plane.signed_distance(p), 0.0, 1e-12);
}

TEST(PlaneFit, ResidualOfTwoParallelLayers) {
  // Every grid point twice, at z = +0.1 and z = -0.1: the plane is z = 0, rms 0.1.
  std::vector<Point> points;
  for (int i = 0; i < 12; ++i) {
    points.emplace_back(i % 4, i / 4, 0.1);
    points.emplace_back(i % 4, i / 4, -0.1);
  }
  const PlaneFit fit = fit_plane(points);
  ASSERT_TRUE(fit.valid);
  EXPECT_NEAR(std::abs(fit.plane.normal[2]), 1.0, 1e-9);
  EXPECT_NEAR(fit.plane.rms_residual, 0.1, 1e-9);
}

TEST(PlaneFit, CollinearPointsAreRejected) {
  EXPECT_FALSE(fit_plane({Point(0, 0, 0), Point(1, 1, 1), Point(2, 2, 2)}).valid);
  EXPECT_FALSE(fit_plane({Point(0, 0, 0), Point(1, 0, 0)}).valid);
}

TEST(PlaneFit, RegionPlanesAreOrientedLikeTheirFaces) {
  TriangleSoup soup = test::grid_soup(3);
  for (auto& t : soup.triangles)
    std::swap(t[1], t[2]);  // normals now -z
  soup.regions.assign(soup.triangles.size(), 0);
  const auto fits = fit_region_planes(build_mesh(soup));
  ASSERT_EQ(fits.size(), 1u);
  ASSERT_TRUE(fits[0].valid);
  EXPECT_NEAR(fits[0].plane.normal[2], -1.0, 1e-12);
}

}  // namespace
}  // namespace holebench
