// Invariants of feature recovery on generated cases: the complete model recovers every
// feature exactly; the unrepaired input recovers no missing edge and leaves each missing
// corner at the distance of the nearest kept vertex.
#include "metrics/feature_recovery.h"

#include "core/geometry.h"
#include "core/region_segmentation.h"
#include "generators/case_catalog.h"
#include "metrics/embree/triangle_scene.h"
#include "metrics/kept_faces.h"
#include "tests/metrics/test_repairs.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

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

// With what a case knows of the input (FeatureRecoveryShortcuts: the input's regions, the kept
// faces, a scene of the repair), the sharp edges near each missing edge are looked for about
// the edge's segments, not over the whole repaired mesh's analysis; the recovery is the same,
// field for field, whatever the tolerance and the search radius (a tolerance past the radius
// included).
TEST(FeatureRecovery, TheInputsShortcutsGiveTheWholeMeshsRecovery) {
  for (const char* id :
       {"box/corner", "brep/k3/inner/convex-convex-convex/small",
        "brep/k2/outer/reflex/inner-inner/large", "solid/l_block/edge_convex/small"}) {
    SCOPED_TRACE(id);
    const Case c = generators::make_case(id);
    const Mesh repaired = test::fan_closing(c.input);
    const embree::TriangleScene complete_scene(c.complete);
    const embree::TriangleScene repaired_scene(repaired);
    const KeptFaces kept = kept_faces(c.input, repaired);
    ASSERT_TRUE(kept.every_input_face_kept());
    const double diagonal = bounding_box_diagonal(c.complete);
    for (const auto& [tolerance, radius] : std::vector<std::pair<double, double>>{
             {5e-3, 5e-2}, {5e-2, 5e-3}, {2e-2, 2e-2}, {1e-3, 0.5}, {0.3, 1e-3}}) {
      SCOPED_TRACE(testing::Message() << "tolerance " << tolerance << ", radius " << radius);
      FeatureRecoveryOptions options = options_for(c);
      options.edge_tolerance = tolerance * diagonal;
      options.edge_search_radius = radius * diagonal;
      const std::vector<int> regions =
          segment_regions(c.input, options.features.segmentation).face_region;
      FeatureRecoveryShortcuts shortcuts;
      shortcuts.input_face_regions = &regions;
      shortcuts.kept = &kept;
      shortcuts.repaired_scene = &repaired_scene;
      const FeatureRecovery whole = feature_recovery(c, repaired, complete_scene, options);
      const FeatureRecovery from_input =
          feature_recovery(c, repaired, complete_scene, options, shortcuts);
      ASSERT_FALSE(whole.edges.empty());
      ASSERT_EQ(from_input.edges.size(), whole.edges.size());
      for (std::size_t i = 0; i < whole.edges.size(); ++i) {
        EXPECT_EQ(from_input.edges[i].covered_fraction, whole.edges[i].covered_fraction) << i;
        EXPECT_EQ(from_input.edges[i].present, whole.edges[i].present) << i;
        EXPECT_EQ(from_input.edges[i].distance, whole.edges[i].distance) << i;
      }
    }
  }
}

}  // namespace
}  // namespace holebench
