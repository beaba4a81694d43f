// Invariants of feature recovery on generated cases: the complete model recovers every
// feature exactly; the unrepaired input recovers no missing edge and leaves each missing
// corner at the distance of the nearest kept vertex.
#include "metrics/feature_recovery.h"

#include "core/geometry.h"
#include "generators/case_catalog.h"
#include "metrics/embree/triangle_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace holebench {
namespace {

FeatureRecoveryOptions options_for(const Case& c) {
  const double diagonal = bounding_box_diagonal(c.complete);
  FeatureRecoveryOptions options;
  options.edge_sample_spacing = 1e-3 * diagonal;
  options.edge_tolerance = 5e-3 * diagonal;
  options.edge_search_radius = 5e-2 * diagonal;
  return options;
}

TEST(FeatureRecovery, CompleteModelRecoversEverything) {
  const Case c = generators::make_case("brep/k3/inner/convex-convex-convex/small");
  ASSERT_FALSE(c.holes[0].missing_corners.empty());
  ASSERT_FALSE(c.holes[0].missing_edges.empty());
  const embree::TriangleScene scene(c.complete);
  Mesh repaired = c.complete;
  for (int f : c.holes[0].removed_faces)  // the removed faces play the patch
    repaired.data(repaired.face_handle(f)).provenance = Provenance::New;
  const auto r = feature_recovery(c, repaired, scene, options_for(c));
  // The corner is a vertex of the complete model: distance 0.
  for (double e : r.corner_errors)
    EXPECT_EQ(e, 0.0);
  // The true edges are edges of the complete model, which its segmentation finds sharp.
  for (const auto& e : r.edges) {
    EXPECT_TRUE(e.present);
    EXPECT_DOUBLE_EQ(e.covered_fraction, 1.0);
    ASSERT_TRUE(e.distance.has_value());
    EXPECT_LE(*e.distance, 1e-12);
  }
  // The patch is the true surface: no normal deviation.
  ASSERT_TRUE(r.normal_deviation_max_deg.has_value());
  EXPECT_LE(*r.normal_deviation_max_deg, 1e-6);
}

TEST(FeatureRecovery, UnrepairedInputRecoversNothing) {
  const Case c = generators::make_case("brep/k3/inner/convex-convex-convex/small");
  const embree::TriangleScene scene(c.complete);
  const auto r = feature_recovery(c, c.input, scene, options_for(c));
  // Expected corner error: the nearest vertex the input kept, computed directly.
  ASSERT_EQ(r.corner_errors.size(), 1u);
  double nearest = std::numeric_limits<double>::infinity();
  for (auto v : c.input.vertices()) {
    if (!c.input.is_isolated(v))
      nearest = std::min(nearest, (c.input.point(v) - c.holes[0].missing_corners[0]).norm());
  }
  EXPECT_GT(r.corner_errors[0], 0.0);
  EXPECT_LE(r.corner_errors[0], nearest);
  // The holed mesh has no sharp edge in the middle of the hole.
  for (const auto& e : r.edges)
    EXPECT_LT(e.covered_fraction, 1.0);
  EXPECT_FALSE(r.normal_deviation_mean_deg.has_value());  // no new faces
}

// The complete model moved by t (|t| = d along (1, 1, 1)/sqrt(3)) as the repair: for a
// small d each missing corner's nearest vertex is the moved corner, exactly d away; every sample of
// a missing edge is between d sqrt(2/3) (its distance to the moved edge's line) and d (to the moved
// corner) from the moved sharp edges; whether the edges count as present follows the tolerance.
TEST(FeatureRecovery, AMovedModelIsChargedItsOffset) {
  const Case c = generators::make_case("brep/k3/inner/convex-convex-convex/small");
  const embree::TriangleScene scene(c.complete);
  const auto options = options_for(c);
  for (const double d : {0.2 * options.edge_tolerance, 3.0 * options.edge_tolerance}) {
    SCOPED_TRACE(d);
    Mesh repaired = c.complete;
    const Point t = Point(1.0, 1.0, 1.0) * (d / std::sqrt(3.0));
    for (auto v : repaired.vertices())
      repaired.point(v) += t;
    const auto r = feature_recovery(c, repaired, scene, options);
    ASSERT_EQ(r.corner_errors.size(), 1u);
    // Exactly d while no other vertex comes nearer (the mesh spacing is well above the
    // small offset); at most d always.
    if (d < options.edge_tolerance)
      EXPECT_NEAR(r.corner_errors[0], d, 1e-12 * d);
    EXPECT_LE(r.corner_errors[0], d * (1.0 + 1e-12));
    ASSERT_FALSE(r.edges.empty());
    for (const auto& e : r.edges) {
      const bool within = d < options.edge_tolerance;
      EXPECT_EQ(e.present, within);
      EXPECT_DOUBLE_EQ(e.covered_fraction, within ? 1.0 : 0.0);
      ASSERT_TRUE(e.distance.has_value());
      EXPECT_GE(*e.distance, d * std::sqrt(2.0 / 3.0) * (1.0 - 1e-9));
      EXPECT_LE(*e.distance, d * (1.0 + 1e-9));
    }
  }
}

}  // namespace
}  // namespace holebench
