// Invariant: the mean and RMS distances lie within their stated error bound of the exact
// integrals; expected values are computed by hand (integrals over unit grids).
#include "metrics/surface_distance.h"

#include "core/distances.h"
#include "core/geometry.h"
#include "generators/box_solid.h"
#include "generators/case_catalog.h"
#include "metrics/embree/triangle_scene.h"
#include "metrics/face_subset.h"
#include "tests/test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace holebench {
namespace {

// Identical surfaces: every face is shared, so nothing is queried at all.
TEST(MeanDistance, IdenticalMeshesAreAtZeroWithoutRefinement) {
  const Mesh box = generators::make_box({Point(2.0, 1.5, 1.0), 0.25});
  const embree::TriangleScene scene(box);
  const auto d = surface_distance(box, scene, box, scene);
  EXPECT_LE(d.mean(), 1e-15);
  EXPECT_LE(d.rms(), 1e-15);
  EXPECT_LE(d.rms_error(), 1e-15);
  EXPECT_EQ(d.a_to_b.queries, 0u);
  EXPECT_EQ(d.hausdorff.a_to_b.queries, 0u);
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
    options.relative_error_bound = 0.0;  // the absolute bound alone
    const auto d = directed_mean_distance(full, part_scene, options);
    ASSERT_TRUE(d.converged);
    EXPECT_LE(d.rms_error, bound);
    EXPECT_LE(d.mean_error, bound);
    EXPECT_NEAR(d.mean, 1.0 / 6.0, d.mean_error + 1e-15);
    EXPECT_NEAR(d.rms, 1.0 / 3.0, d.rms_error + 1e-15);
  }
  // The default options: each half-width within 1 % of its lower end, the analytic values
  // inside the intervals.
  const auto d = directed_mean_distance(full, part_scene);
  ASSERT_TRUE(d.converged);
  EXPECT_LE(d.mean_error, 0.01 * d.mean_lower + 1e-15);
  EXPECT_LE(d.rms_error, 0.01 * d.rms_lower + 1e-15);
  EXPECT_LE(d.mean_lower, 1.0 / 6.0);
  EXPECT_GE(d.mean_upper, 1.0 / 6.0);
  EXPECT_LE(d.rms_lower, 1.0 / 3.0);
  EXPECT_GE(d.rms_upper, 1.0 / 3.0);
  const auto back = directed_mean_distance(part, full_scene);
  EXPECT_LE(back.mean, 1e-15);
}

// The mean and RMS of the distance from a 3x3 grid to a small triangle hovering above it,
// against an independent midpoint-rule integral (600 x 600 samples, exact point-triangle
// distances): the distance is curved there, which the second-order bounds must follow.
TEST(MeanDistance, CurvedDistanceFieldMatchesAnIndependentIntegral) {
  const Mesh grid = build_mesh(test::grid_soup(3));
  TriangleSoup hovering;
  hovering.points = {Point(1.2, 1.1, 0.8), Point(1.9, 1.3, 1.1), Point(1.4, 1.8, 0.9)};
  hovering.triangles = {{0, 1, 2}};
  const Mesh target = build_mesh(hovering);
  const embree::TriangleScene target_scene(target);
  const auto& t = target_scene.triangle_of_face(0);
  const int n = 600;
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const Point x(3.0 * (i + 0.5) / n, 3.0 * (j + 0.5) / n, 0.0);
      const double d = (closest_point_on_triangle(x, t[0], t[1], t[2]) - x).norm();
      sum += d;
      sum2 += d * d;
    }
  }
  const double mean = sum / (n * n), rms = std::sqrt(sum2 / (n * n));
  for (double bound : {1e-2, 1e-3, 1e-4}) {
    MeanDistanceOptions options;
    options.error_bound = bound;
    options.relative_error_bound = 0.0;  // the absolute bound alone
    const auto d = directed_mean_distance(grid, target_scene, options);
    ASSERT_TRUE(d.converged);
    EXPECT_LE(d.mean_error, bound);
    EXPECT_LE(d.rms_error, bound);
    EXPECT_NEAR(d.mean, mean, d.mean_error + 1e-6);  // 1e-6: the midpoint rule's own error
    EXPECT_NEAR(d.rms, rms, d.rms_error + 1e-6);
  }
}

// A quadrature with a guaranteed error, independent of the search: every triangle of A cut
// into n x n similar pieces, d(., B) taken exactly (Embree closest point) at each piece's
// centroid; the distance is 1-Lipschitz, so the area-weighted mean is within the largest
// piece radius of the true mean.
struct Quadrature {
  double mean = 0.0;
  double error = 0.0;
};

// Faces outside `faces` are known (from the construction) to lie on B: they add area only.
Quadrature mean_by_quadrature(const Mesh& a, const std::vector<int>& faces,
                              const embree::TriangleScene& b_scene, int n) {
  double sum = 0.0, area = 0.0, radius = 0.0;
  for (auto f : a.faces()) {
    if (std::find(faces.begin(), faces.end(), f.idx()) == faces.end()) {
      area += a.calc_face_area(f);
      continue;
    }
    std::array<Point, 3> c;
    int k = 0;
    for (auto v : f.vertices())
      c[k++] = a.point(v);
    const Point e1 = (c[1] - c[0]) / n, e2 = (c[2] - c[0]) / n;
    const double piece_area = 0.5 * OpenMesh::cross(e1, e2).norm();
    for (int i = 0; i < n; ++i) {
      for (int j = 0; i + j < n; ++j) {
        const Point p = c[0] + e1 * i + e2 * j;
        // The upright piece (p, p + e1, p + e2) and, where it exists, the inverted one.
        for (int inverted = 0; inverted < (i + j + 1 < n ? 2 : 1); ++inverted) {
          const std::array<Point, 3> piece = inverted
                                                 ? std::array<Point, 3>{p + e1, p + e1 + e2, p + e2}
                                                 : std::array<Point, 3>{p, p + e1, p + e2};
          const Point g = (piece[0] + piece[1] + piece[2]) / 3.0;
          for (const Point& corner : piece)
            radius = std::max(radius, (corner - g).norm());
          sum += piece_area * b_scene.closest_point(g).distance;
          area += piece_area;
        }
      }
    }
  }
  return {sum / area, radius};
}

// The mean distance of a real case (the complete model of an outer k = 3 hole against its
// holed input, as if a method had left it open) against the quadrature over the faces the
// construction removed.
TEST(MeanDistance, MatchesAGuaranteedQuadratureOnAnOpenHole) {
  const Case c =
      generators::make_case("brep/k3/outer/convex-convex-convex/outer-outer-outer/small");
  const embree::TriangleScene input_scene(c.input);
  const double diagonal = bounding_box_diagonal(c.complete);
  MeanDistanceOptions options;
  options.error_bound = 1e-3 * diagonal;
  const auto d = directed_mean_distance(c.complete, input_scene, options);
  ASSERT_TRUE(d.converged);
  std::vector<int> removed;
  for (const auto& hole : c.holes)
    removed.insert(removed.end(), hole.removed_faces.begin(), hole.removed_faces.end());
  const Quadrature q = mean_by_quadrature(c.complete, removed, input_scene, 64);
  EXPECT_LT(q.error, 1e-3 * diagonal);
  EXPECT_NEAR(d.mean, q.mean, d.mean_error + q.error);
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

namespace holebench {
namespace {

// The clamps of distance_summary(): intervals that hold separately (mean in [0.1, 0.5], RMS
// in [0.05, 0.6], Hausdorff in [0.2, 0.3]) are narrowed by mean <= RMS <= Hausdorff:
// RMS in [0.1, 0.3], mean in [0.1, 0.3]; estimates above those ends come down to them.
TEST(DistanceSummary, ClampsByMeanBelowRmsBelowHausdorff) {
  DirectedHausdorff h;
  h.lower = 0.2;
  h.upper = 0.3;
  DirectedMeanDistance m;
  m.mean_lower = 0.1, m.mean = 0.45, m.mean_upper = 0.5;
  m.rms_lower = 0.05, m.rms = 0.4, m.rms_upper = 0.6;
  const DistanceSummary s = distance_summary(h, m);
  EXPECT_DOUBLE_EQ(s.rms.lower, 0.1);
  EXPECT_DOUBLE_EQ(s.rms.upper, 0.3);
  EXPECT_DOUBLE_EQ(s.rms.value, 0.3);
  EXPECT_DOUBLE_EQ(s.mean.upper, 0.3);
  EXPECT_DOUBLE_EQ(s.mean.value, 0.3);
  EXPECT_LE(s.mean.value, s.rms.value);
  EXPECT_DOUBLE_EQ(s.hausdorff.value, 0.2);
}

// The larger of two directions keeps the order of each.
TEST(DistanceSummary, MaxOfTwoDirectionsKeepsTheOrder) {
  const DistanceSummary a{{0.1, 0.2, 0.3}, {0.2, 0.25, 0.35}, {0.4, 0.4, 0.5}};
  const DistanceSummary b{{0.0, 0.3, 0.4}, {0.3, 0.31, 0.45}, {0.3, 0.3, 0.46}};
  const DistanceSummary s = max_of(a, b);
  EXPECT_DOUBLE_EQ(s.mean.value, 0.3);
  EXPECT_DOUBLE_EQ(s.rms.value, 0.31);
  EXPECT_DOUBLE_EQ(s.hausdorff.upper, 0.5);
  EXPECT_LE(s.mean.value, s.rms.value);
  EXPECT_LE(s.rms.value, s.hausdorff.upper);
}

// Where B is flat under A the plane bounds are exact: a tilted square over a plane (the
// distance affine on it, 0.1 to 0.4) has mean 0.25 and mean square (0.1^2 + 0.1 * 0.4 +
// 0.4^2) / 3 = 0.07 (a linear ramp), found without splitting the two triangles far.
TEST(MeanDistance, AffineDistanceIsExactFromThePlaneBounds) {
  TriangleSoup ramp = test::grid_soup(1);
  for (auto& p : ramp.points)
    p[2] = 0.1 + 0.3 * p[0];
  TriangleSoup floor = test::grid_soup(1);
  for (auto& p : floor.points)
    p = Point(p[0] * 4.0 - 1.5, p[1] * 4.0 - 1.5, 0.0);
  const Mesh a = build_mesh(ramp);
  const Mesh b = build_mesh(floor);
  const embree::TriangleScene b_scene(b);
  MeanDistanceOptions options;
  options.error_bound = 1e-12;
  options.relative_error_bound = 0.0;
  const auto d = directed_mean_distance(a, b_scene, options);
  ASSERT_TRUE(d.converged);
  EXPECT_NEAR(d.mean, 0.25, 1e-12);
  EXPECT_NEAR(d.rms, std::sqrt(0.07), 1e-12);
  EXPECT_LT(d.queries, 100u);
}

}  // namespace
}  // namespace holebench

namespace holebench {
namespace {

// The steps one search recorded (MeanSearchSteps), taken by another search against the same
// surface for the cells the two share: the same numbers and the same count of queries as
// computing them, and steps recorded with other error bounds are not taken. Here the removed
// faces of a real case against its input record, and the whole complete model, which holds
// them, takes their steps.
TEST(MeanDistance, StepsRecordedByAnotherSearchGiveTheSameNumbers) {
  const Case c =
      generators::make_case("brep/k3/outer/convex-convex-convex/outer-outer-outer/small", 0, 5.0);
  const embree::TriangleScene input_scene(c.input);
  const double diagonal = bounding_box_diagonal(c.complete);
  MeanDistanceOptions options;
  options.error_bound = 1e-5 * diagonal;
  std::vector<int> removed;
  for (const auto& hole : c.holes)
    removed.insert(removed.end(), hole.removed_faces.begin(), hole.removed_faces.end());
  std::sort(removed.begin(), removed.end());
  const Mesh part = face_subset(c.complete, removed);

  const DirectedMeanDistance computed = directed_mean_distance(c.complete, input_scene, options);
  MeanSearchSteps steps;
  directed_mean_distance(part, input_scene, options, {}, nullptr, &steps);
  ASSERT_GT(steps.size(), 0u);
  FirstBounds first;
  first.steps = &steps;
  const DirectedMeanDistance taken =
      directed_mean_distance(c.complete, input_scene, options, {}, &first);
  EXPECT_EQ(computed.steps_taken, 0u);
  EXPECT_GT(taken.steps_taken, 0u);
  EXPECT_EQ(taken.mean, computed.mean);
  EXPECT_EQ(taken.mean_lower, computed.mean_lower);
  EXPECT_EQ(taken.mean_upper, computed.mean_upper);
  EXPECT_EQ(taken.rms, computed.rms);
  EXPECT_EQ(taken.rms_lower, computed.rms_lower);
  EXPECT_EQ(taken.rms_upper, computed.rms_upper);
  EXPECT_EQ(taken.queries, computed.queries);
  EXPECT_EQ(taken.converged, computed.converged);

  MeanDistanceOptions other = options;
  other.error_bound = 2e-5 * diagonal;
  EXPECT_EQ(directed_mean_distance(c.complete, input_scene, other, {}, &first).steps_taken, 0u);
}

}  // namespace
}  // namespace holebench
