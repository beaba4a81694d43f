// Tests of methods/slice_loft/developed_disc.h (the last trimming domain) and of the holes
// it lets slice_loft close on its own path.
#include "methods/slice_loft/developed_disc.h"

#include "generators/case_catalog.h"
#include "methods/slice_loft/boundary_segmentation.h"
#include "tests/methods/slice_loft_papers_path.h"

#include <gtest/gtest.h>

#include <cmath>

namespace holebench {
namespace {

TEST(SliceLoftDevelopedDisc, PointsLieOnTheCircleByArcLength) {
  // A 3 x 1 rectangle in space, with a midpoint on the long sides: perimeter 8.
  const std::vector<Point> loop = {Point(0, 0, 1), Point(1.5, 0, 1), Point(3, 0, 1),
                                   Point(3, 1, 1), Point(1.5, 1, 1), Point(0, 1, 1)};
  const slice_loft::DevelopedDisc disc = slice_loft::develop_onto_disc(loop);
  ASSERT_EQ(disc.points.size(), loop.size());
  EXPECT_NEAR(disc.radius, 8.0 / (2.0 * M_PI), 1e-12);
  const double arc[] = {0.0, 1.5, 3.0, 4.0, 5.5, 7.0};
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const double angle = 2.0 * M_PI * arc[i] / 8.0;
    EXPECT_NEAR(disc.points[i][0], disc.radius * std::cos(angle), 1e-12);
    EXPECT_NEAR(disc.points[i][1], disc.radius * std::sin(angle), 1e-12);
  }
  // The disc's area (16 / pi) over the rectangle's (3): the interior points go farther apart.
  EXPECT_NEAR(disc.spacing_scale, std::sqrt(16.0 / M_PI / 3.0), 1e-12);
}

// Mean value coordinates: positive inside a convex polygon, a partition of unity, and they
// reproduce linear functions (so a planar boundary maps the disc onto its own plane).
TEST(SliceLoftDevelopedDisc, MeanValueCoordinatesReproduceLinearFunctions) {
  std::vector<std::array<double, 2>> polygon;
  for (int i = 0; i < 7; ++i)
    polygon.push_back({std::cos(2 * M_PI * i / 7.0), std::sin(2 * M_PI * i / 7.0)});
  auto linear = [](std::array<double, 2> p) { return 0.3 + 2.0 * p[0] - 1.5 * p[1]; };
  for (const std::array<double, 2> x :
       {std::array<double, 2>{0.0, 0.0}, {0.5, 0.2}, {-0.3, -0.6}, {0.85, 0.0}}) {
    const std::vector<double> w = slice_loft::mean_value_coordinates(polygon, x);
    double sum = 0.0, value = 0.0, px = 0.0, py = 0.0;
    for (std::size_t i = 0; i < w.size(); ++i) {
      EXPECT_GT(w[i], 0.0);
      sum += w[i];
      value += w[i] * linear(polygon[i]);
      px += w[i] * polygon[i][0];
      py += w[i] * polygon[i][1];
    }
    EXPECT_NEAR(sum, 1.0, 1e-12);
    EXPECT_NEAR(value, linear(x), 1e-12);
    EXPECT_NEAR(px, x[0], 1e-12);
    EXPECT_NEAR(py, x[1], 1e-12);
  }
}

// Single faces that exceed the thresholds on every side (as under vertex noise) join the
// region around them; a region of enough faces stays.
TEST(SliceLoftRegions, SmallRegionsJoinTheirNeighbour) {
  const Case c = generators::make_case("box/face_interior");
  std::vector<int> face_region(c.input.n_faces(), 0);
  face_region[5] = 7;  // one face on its own
  face_region[9] = 7;
  face_region[10] = 3;
  std::vector<int> merged = face_region;
  slice_loft::merge_small_regions(c.input, 4, merged);
  for (int r : merged)
    EXPECT_EQ(r, 0);
  std::vector<int> kept = face_region;
  slice_loft::merge_small_regions(c.input, 1, kept);
  EXPECT_EQ(kept, face_region);
}

// A corner hole of the turbine whose boundary folds in the portion's plane and on the lofted
// surface, trimmed on the developed disc. The hole is closed on the paper's path, the output
// has no boundary edge left. (Until 2026-12-03 this hole cut a blade through and came with an
// island; punched holes that cut a part through are now made smaller.)
TEST(SliceLoftDevelopedDisc, FoldedHoleIsClosedOnThePapersPath) {
  expect_closed_on_the_papers_path("cad/turbine/corner_ccr/small", "developed disc",
                                   slice_loft::plus_options(false));
}

}  // namespace
}  // namespace holebench
