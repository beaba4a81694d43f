#include "methods/cgal_triangulate/cgal_triangulate.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"
#include "generators/case_catalog.h"
#include "methods/registry.h"
#include "tests/methods/method_invariants.h"

#include <gtest/gtest.h>

#include <cmath>

namespace holebench {
namespace {

class CgalTriangulateOnBoxCases : public ::testing::TestWithParam<std::string> {};

TEST_P(CgalTriangulateOnBoxCases, ClosesEveryHoleAndKeepsTheRestOfTheMesh) {
  const Case c = generators::make_case(GetParam());
  NoUser user;
  const MethodResult result = CgalTriangulateMethod().run(c.input, {}, user);
  EXPECT_EQ(result.status, MethodStatus::Ok);
  test::expect_closed_manifold(result.repaired);
  test::expect_input_faces_unchanged(c.input, result.repaired);
  ASSERT_EQ(result.holes.size(), 1u);
  EXPECT_TRUE(result.holes[0].closed);
  EXPECT_EQ(result.holes[0].fallback, "");
  EXPECT_EQ(result.holes[0].new_faces, count_new_faces(result.repaired));
  EXPECT_GT(result.holes[0].new_faces, 0u);
  // triangulate_hole adds no vertex: the patch's corners are the loop's own.
  EXPECT_EQ(result.holes[0].new_vertices, 0u);
  EXPECT_EQ(result.repaired.n_vertices(), c.input.n_vertices());
  ASSERT_EQ(result.phases.size(), 1u);
  EXPECT_EQ(result.phases[0].phase, "triangulate_hole");
  EXPECT_EQ(user.interventions(), 0);
}

INSTANTIATE_TEST_SUITE_P(SkeletonCases, CgalTriangulateOnBoxCases,
                         ::testing::Values("box/face_interior", "box/edge", "box/corner"),
                         test::case_test_name);

// A hole in the box's top face (the plane z = 1): the patch's corners are the loop's
// vertices, which lie on that plane, so every new face lies on it exactly (to 1e-12 of the
// diagonal, i.e. up to the coordinates' rounding).
TEST(CgalTriangulate, PlanarHoleIsFilledFlat) {
  const Case c = generators::make_case("box/face_interior");
  const MethodResult result = fill_holes_cgal_triangulate(c.input);
  const double tolerance = 1e-12 * bounding_box_diagonal(c.input);
  std::size_t new_faces = 0;
  for (auto f : result.repaired.faces()) {
    if (!is_new(result.repaired, f))
      continue;
    ++new_faces;
    for (auto v : result.repaired.fv_range(f))
      EXPECT_NEAR(result.repaired.point(v)[2], 1.0, tolerance);
  }
  EXPECT_GT(new_faces, 0u);
}

TEST(CgalTriangulate, IsRegisteredAndDeterministic) {
  EXPECT_EQ(make_method("cgal_triangulate")->id(), "cgal_triangulate");
  const Case c = generators::make_case("box/corner");
  const MethodResult a = fill_holes_cgal_triangulate(c.input);
  const MethodResult b = fill_holes_cgal_triangulate(c.input);
  ASSERT_EQ(a.repaired.n_faces(), b.repaired.n_faces());
  for (auto f : a.repaired.faces()) {
    auto corner = b.repaired.cfv_begin(b.repaired.face_handle(f.idx()));
    for (auto v : a.repaired.fv_range(f)) {
      EXPECT_EQ(corner->idx(), v.idx());
      ++corner;
    }
  }
}

}  // namespace
}  // namespace holebench
