#include "core/region_segmentation.h"

#include "generators/box_solid.h"
#include "tests/test_meshes.h"

#include <gtest/gtest.h>

#include <set>

namespace holebench {
namespace {

TEST(RegionSegmentation, BoxHasSixRegionsMatchingItsFaces) {
  const Mesh box = generators::make_box({Point(2.0, 1.5, 1.0), 0.25});
  const auto segmentation = segment_regions(box);
  EXPECT_EQ(segmentation.region_count, 6);
  // The segmentation and the generator's region ids partition the faces the same way.
  std::set<std::pair<int, int>> pairs;
  for (auto f : box.faces())
    pairs.insert({segmentation.face_region[f.idx()], region(box, f)});
  EXPECT_EQ(pairs.size(), 6u);
  // The sharp edges are the box's 12 edges: 4 * (8 + 6 + 4) grid edges at cell 0.25.
  EXPECT_EQ(segmentation.sharp_edges.size(), 4u * (8 + 6 + 4));
}

TEST(RegionSegmentation, ThresholdAboveTheFoldMergesEverything) {
  const Mesh box = generators::make_box({Point(1.0, 1.0, 1.0), 0.5});
  SegmentationOptions options;
  options.sharp_angle_degrees = 95.0;  // the box's edges fold by 90 degrees
  EXPECT_EQ(segment_regions(box, options).region_count, 1);
}

TEST(RegionSegmentation, AssignWritesRegionIds) {
  Mesh mesh = build_mesh(test::grid_soup(2));
  const auto segmentation = segment_regions(mesh);
  assign_regions(mesh, segmentation);
  EXPECT_EQ(segmentation.region_count, 1);
  for (auto f : mesh.faces())
    EXPECT_EQ(region(mesh, f), 0);
}

}  // namespace
}  // namespace holebench
