// The no-truth metrics of a patch (metrics/patch_quality.h) against values worked out by hand.
#include "metrics/patch_quality.h"

#include "core/mesh.h"
#include "generators/box_solid.h"

#include <gtest/gtest.h>

#include <cmath>

namespace holebench {
namespace {

// A unit cube of 12 right triangles; the two of the top face (+z) marked new, as a patch that
// closes a hole of that face exactly.
Mesh cube_with_new_top() {
  generators::BoxOptions options;
  options.size = Point(1.0, 1.0, 1.0);
  options.cell = 1.0;
  Mesh cube = generators::make_box(options);
  for (auto f : cube.faces()) {
    if (region(cube, f) == 5) {
      cube.data(f).provenance = Provenance::New;
    }
  }
  return cube;
}

TEST(PatchQuality, AFlatPatchOnACubeFace) {
  const PatchQuality q = patch_quality(cube_with_new_top());
  // The top's four edges meet the sides at 90 degrees; its diagonal is flat.
  ASSERT_TRUE(q.boundary_normal_jump_mean_deg && q.boundary_normal_jump_max_deg);
  EXPECT_NEAR(*q.boundary_normal_jump_mean_deg, 90.0, 1e-9);
  EXPECT_NEAR(*q.boundary_normal_jump_max_deg, 90.0, 1e-9);
  ASSERT_TRUE(q.dihedral_mean_deg && q.dihedral_max_deg);
  EXPECT_NEAR(*q.dihedral_max_deg, 0.0, 1e-6);
  // A right isosceles triangle with legs 1: 4 sqrt(3) (1/2) / (1 + 1 + 2) = sqrt(3) / 2.
  ASSERT_TRUE(q.triangle_quality_min && q.triangle_quality_mean);
  EXPECT_NEAR(*q.triangle_quality_min, std::sqrt(3.0) / 2.0, 1e-12);
  EXPECT_NEAR(*q.triangle_quality_mean, std::sqrt(3.0) / 2.0, 1e-12);
}

TEST(PatchQuality, NoPatchNoValues) {
  generators::BoxOptions options;
  options.size = Point(1.0, 1.0, 1.0);
  options.cell = 1.0;
  const PatchQuality q = patch_quality(generators::make_box(options));
  EXPECT_FALSE(q.boundary_normal_jump_mean_deg.has_value());
  EXPECT_FALSE(q.dihedral_mean_deg.has_value());
  EXPECT_FALSE(q.triangle_quality_min.has_value());
}

}  // namespace
}  // namespace holebench
