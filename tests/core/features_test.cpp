#include "core/features.h"

#include "generators/box_solid.h"
#include "generators/procedural_solids.h"
#include "tests/test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

namespace holebench {
namespace {

std::map<std::string, int> signature_counts(const FeatureAnalysis& analysis) {
  std::map<std::string, int> counts;
  for (const auto& corner : analysis.corners)
    ++counts[corner.signature()];
  return counts;
}

// A box: 12 convex edges (chains between corners), 8 convex corners.
TEST(Features, BoxHasTwelveConvexChainsAndEightConvexCorners) {
  const Mesh box = generators::make_box({Point(2.0, 1.5, 1.0), 0.25});
  const auto analysis = analyse_features(box);
  EXPECT_EQ(analysis.chains.size(), 12u);
  for (const auto& chain : analysis.chains) {
    EXPECT_EQ(chain.convexity, Convexity::Convex);
    EXPECT_FALSE(chain.closed);
  }
  EXPECT_EQ(signature_counts(analysis), (std::map<std::string, int>{{"ccc", 8}}));
}

// Regions taken from the mesh (a B-Rep's faces): the box's top face split in two at x = 1 is
// 7 regions, but the border inside the top face is flat, so no sharp edge and no corner: the
// box's 8 convex corners, and its 12 convex chains plus 2, because the two top edges along x
// change region pair at x = 1 (a chain never does).
TEST(Features, RegionsFromTheMeshWithAFlatBorderKeepTheBoxsFeatures) {
  Mesh box = generators::make_box({Point(2.0, 1.5, 1.0), 0.25});
  int top_left = 0;
  for (auto f : box.faces()) {
    const Point c = box.calc_face_centroid(f);
    if (c[2] > 0.99 && c[0] < 1.0) {
      set_region(box, f, 6);
      ++top_left;
    }
  }
  ASSERT_GT(top_left, 0);
  FeatureOptions options;
  options.regions_from_mesh = true;
  const auto analysis = analyse_features(box, options);
  EXPECT_EQ(analysis.segmentation.region_count, 7);
  EXPECT_EQ(analysis.chains.size(), 14u);
  for (const auto& chain : analysis.chains)
    EXPECT_EQ(chain.convexity, Convexity::Convex);
  EXPECT_EQ(signature_counts(analysis), (std::map<std::string, int>{{"ccc", 8}}));
  EXPECT_EQ(analyse_features(box).segmentation.region_count, 6);  // segmentation merges them
}

// Regions from the mesh: two planar faces meeting at a shallow angle (a draft) are an edge
// of the model, though the angle is below the segmentation's 30 degrees. The box's top, split
// at x = 1, is bent into a valley of 12 degrees: one reflex chain more, and the valley's ends
// on the two side faces are corners with two convex and one reflex edge.
TEST(Features, PlanarRegionsFromTheMeshMeetingAtAShallowAngleAreSharp) {
  const Mesh box = test::box_with_split_top(12.0);
  FeatureOptions options;
  options.regions_from_mesh = true;
  const auto analysis = analyse_features(box, options);
  int reflex = 0;
  for (const auto& chain : analysis.chains)
    reflex += chain.convexity == Convexity::Reflex ? 1 : 0;
  EXPECT_EQ(reflex, 1);
  EXPECT_EQ(signature_counts(analysis), (std::map<std::string, int>{{"ccc", 8}, {"ccr", 2}}));
  // The same border between a curved and a planar region would need 30 degrees: with the
  // planar threshold raised to 30 degrees as well, the valley is no edge.
  options.planar_sharp_angle_degrees = 30.0;
  EXPECT_EQ(signature_counts(analyse_features(box, options)),
            (std::map<std::string, int>{{"ccc", 8}}));
}

// The notched block ([0,2]^3 without [1,2]^3): the notch's inner corner (1,1,1) has three
// reflex edges; (2,1,1), (1,2,1), (1,1,2), where one notch edge meets a block face, have two
// convex and one reflex edge; the 7 remaining block corners and the notch's outer corners
// (2,1,2), (2,2,1), (1,2,2), where two notch walls meet a block face, are convex.
TEST(Features, NotchedBlockHasTheCornerSignaturesOfItsConstruction) {
  const Mesh solid = generators::make_procedural_solid("notched_block");
  const auto analysis = analyse_features(solid);
  EXPECT_EQ(signature_counts(analysis),
            (std::map<std::string, int>{{"ccc", 10}, {"ccr", 3}, {"rrr", 1}}));
  int reflex = 0;
  for (const auto& chain : analysis.chains)
    reflex += chain.convexity == Convexity::Reflex ? 1 : 0;
  EXPECT_EQ(reflex, 3);  // the notch's three inner edges
}

// A block on a plate: where the block's four vertical (convex) edges meet the plate, the
// corners have one convex and two reflex edges.
TEST(Features, BlockOnPlateHasCrrCorners) {
  const auto analysis = analyse_features(generators::make_procedural_solid("block_on_plate"));
  EXPECT_EQ(signature_counts(analysis)["crr"], 4);
}

// A cylinder: the two rims are closed convex chains; there is no corner.
TEST(Features, CylinderRimsAreClosedChains) {
  const auto analysis = analyse_features(generators::make_procedural_solid("cylinder"));
  ASSERT_EQ(analysis.chains.size(), 2u);
  for (const auto& chain : analysis.chains) {
    EXPECT_TRUE(chain.closed);
    EXPECT_EQ(chain.convexity, Convexity::Convex);
    EXPECT_NEAR(chain.length, 2.0 * M_PI, 0.01);  // radius 1, 96 segments
  }
  EXPECT_TRUE(analysis.corners.empty());
}

}  // namespace
}  // namespace holebench
