// Invariant: the mean and RMS distances lie within their stated error bound of the exact
// integrals; expected values are computed by hand (integrals over unit grids).
#include "metrics/surface_distance.h"

#include "generators/box_solid.h"
#include "metrics/embree/triangle_scene.h"
#include "tests/test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace holebench {
namespace {

// Identical surfaces: every cell's upper bound is 0 at once (bound through one triangle).
TEST(MeanDistance, IdenticalMeshesAreAtZeroWithoutRefinement) {
  const Mesh box = generators::make_box({Point(2.0, 1.5, 1.0), 0.25});
  const embree::TriangleScene scene(box);
  const auto d = surface_distance(box, scene, box, scene);
  EXPECT_LE(d.mean(), 1e-15);
  EXPECT_LE(d.rms(), 1e-15);
  EXPECT_LE(d.rms_error(), 1e-15);
  EXPECT_EQ(d.a_to_b.queries, box.n_vertices() + box.n_faces());  // no cell was split
  EXPECT_DOUBLE_EQ(d.a_to_b.area, 2.0 * (2.0 * 1.5 + 2.0 * 1.0 + 1.5 * 1.0));
}

// Analytic: a 3x3 grid lifted by 0.3 is 0.3 from the grid everywhere: mean = RMS = 0.3.
TEST(MeanDistance, ParallelSquaresAtAKnownDistance) {
  TriangleSoup lifted = test::grid_soup(3);
  for (auto& p : lifted.points)
    p[2] += 0.3;
  const Mesh a = build_mesh(test::grid_soup(3));
  const Mesh b = build_mesh(lifted);
  const embree::TriangleScene a_scene(a), b_scene(b);
  SurfaceDistanceOptions options;
  options.mean.error_bound = 1e-4;
  const auto d = surface_distance(a, a_scene, b, b_scene, options);
  ASSERT_TRUE(d.converged());
  EXPECT_NEAR(d.mean(), 0.3, 1e-4);
  EXPECT_NEAR(d.rms(), 0.3, 1e-4);
}

// Analytic one-sided values: the 3x3 grid against its part x <= 2. Points of the full grid
// with x in [2, 3] are x - 2 away, the rest 0; over the area 9:
//   mean = (3 * integral_0^1 t dt) / 9 = 1/6,  RMS = sqrt((3 * integral_0^1 t^2 dt) / 9) = 1/3.
// The other direction is 0.
TEST(MeanDistance, OneSidedIntegralsMatchTheAnalyticValues) {
  const Mesh full = build_mesh(test::grid_soup(3));
  std::vector<std::pair<int, int>> right;
  for (int j = 0; j < 3; ++j)
    right.emplace_back(2, j);
  const Mesh part = build_mesh(test::grid_without_cells(3, right));
  const embree::TriangleScene part_scene(part), full_scene(full);
  for (double bound : {1e-2, 1e-3}) {
    MeanDistanceOptions options;
    options.error_bound = bound;
    const auto d = directed_mean_distance(full, part_scene, options);
    ASSERT_TRUE(d.converged);
    EXPECT_LE(d.rms_error, bound);
    EXPECT_LE(d.mean_error, d.rms_error);
    EXPECT_NEAR(d.mean, 1.0 / 6.0, d.mean_error + 1e-15);
    EXPECT_NEAR(d.rms, 1.0 / 3.0, d.rms_error + 1e-15);
  }
  const auto back = directed_mean_distance(part, full_scene);
  EXPECT_LE(back.mean, 1e-15);
}

// Determinism: the same inputs give the same numbers and the same work.
TEST(MeanDistance, SameInputsGiveTheSameNumbers) {
  const Mesh full = build_mesh(test::grid_soup(3));
  const Mesh part = build_mesh(test::grid_without_cells(3, {{2, 0}, {2, 1}}));
  const embree::TriangleScene part_scene(part);
  const auto first = directed_mean_distance(full, part_scene);
  const auto second = directed_mean_distance(full, part_scene);
  EXPECT_EQ(first.mean, second.mean);
  EXPECT_EQ(first.rms, second.rms);
  EXPECT_EQ(first.queries, second.queries);
}

}  // namespace
}  // namespace holebench
