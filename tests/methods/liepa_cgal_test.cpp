#include "methods/liepa_cgal/liepa_cgal.h"

#include "core/boundary_loops.h"
#include "generators/case_catalog.h"
#include "methods/registry.h"
#include "tests/methods/method_invariants.h"

#include <gtest/gtest.h>

#include <cmath>

namespace holebench {
namespace {

class LiepaCgalOnBoxCases : public ::testing::TestWithParam<std::string> {};

TEST_P(LiepaCgalOnBoxCases, ClosesEveryHoleAndKeepsTheRestOfTheMesh) {
  const Case c = generators::make_case(GetParam());
  NoUser user;
  const MethodResult result = LiepaCgalMethod().run(c.input, {}, user);
  EXPECT_EQ(result.status, MethodStatus::Ok);
  test::expect_closed_manifold(result.repaired);
  test::expect_input_faces_unchanged(c.input, result.repaired);
  ASSERT_EQ(result.holes.size(), 1u);
  EXPECT_TRUE(result.holes[0].closed);
  EXPECT_EQ(result.holes[0].fallback, "");  // triangulated, refined and faired: no stand-in
  EXPECT_EQ(result.holes[0].new_faces, count_new_faces(result.repaired));
  EXPECT_GT(result.holes[0].new_faces, 0u);
  // Original vertices keep their index and position; only new ones are added.
  for (auto v : c.input.vertices()) {
    EXPECT_EQ(result.repaired.point(result.repaired.vertex_handle(v.idx())), c.input.point(v));
  }
  EXPECT_EQ(user.interventions(), 0);
}

INSTANTIATE_TEST_SUITE_P(SkeletonCases, LiepaCgalOnBoxCases,
                         ::testing::Values("box/face_interior", "box/edge", "box/corner"),
                         test::case_test_name);

// A planar hole filled by minimum-weight triangulation, refinement and fairing stays in
// its plane: the harmonic/biharmonic solution with planar boundary data is planar.
TEST(LiepaCgal, PlanarHoleStaysPlanar) {
  const Case c = generators::make_case("box/face_interior");
  const MethodResult result = fill_holes_liepa_cgal(c.input);
  for (auto v : result.repaired.vertices()) {
    if (!is_new(result.repaired, v))
      continue;
    EXPECT_NEAR(result.repaired.point(v)[2], 1.0, 1e-6);
  }
}

TEST(LiepaCgal, WithoutRefinementAddsNoVertices) {
  const Case c = generators::make_case("box/corner");
  LiepaCgalOptions options;
  options.refine = false;
  options.fair = false;
  const MethodResult result = fill_holes_liepa_cgal(c.input, options);
  EXPECT_EQ(result.repaired.n_vertices(), c.input.n_vertices());
  EXPECT_EQ(result.holes[0].new_vertices, 0u);
  EXPECT_TRUE(find_boundary_loops(result.repaired).empty());
}

TEST(MethodRegistry, KnowsTheBaselineAndRejectsUnknownIds) {
  EXPECT_EQ(make_method("liepa_cgal")->id(), "liepa_cgal");
  EXPECT_THROW(make_method("no_such_method"), std::invalid_argument);
}

}  // namespace
}  // namespace holebench
