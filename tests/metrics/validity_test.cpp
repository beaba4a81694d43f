// Invariants of the validity checks on meshes whose answer is known by construction.
#include "metrics/validity.h"

#include "core/mesh_builder.h"
#include "generators/case_catalog.h"
#include "tests/test_meshes.h"

#include <gtest/gtest.h>

namespace holebench {
namespace {

// The complete model of a generated case is closed, manifold, oriented and free of
// self-intersections (the generators guarantee it; tests/generators check it).
TEST(Validity, CompleteModelIsValid) {
  const Case c = generators::make_case("box/corner");
  const Validity v = validity(c.input, c.complete);
  EXPECT_EQ(v.open_boundary_loops, 0u);
  EXPECT_EQ(v.non_manifold_vertices, 0u);
  EXPECT_EQ(v.orientation_conflicts, 0u);
  EXPECT_TRUE(v.self_intersections_tested);
  EXPECT_EQ(v.self_intersections, 0u);
  EXPECT_EQ(v.new_degenerate_faces, 0u);  // nothing is new
  // Every input face away from the hole is a face of the complete model, bit for bit.
  EXPECT_EQ(v.original_faces_changed, 0u);
}

// The holed input has exactly its case's holes open.
TEST(Validity, HoledInputIsOpen) {
  const Case c = generators::make_case("box/corner");
  const Validity v = validity(c.input, c.input);
  EXPECT_EQ(v.open_boundary_loops, c.holes.size());
  EXPECT_EQ(v.original_faces_changed, 0u);
}

// Moving one vertex away from the hole changes exactly the faces around it.
TEST(Validity, MovedVertexChangesItsFaces) {
  const Mesh input = build_mesh(test::grid_without_cells(6, {{0, 0}}));
  Mesh repaired = input;
  const VertexHandle v =
      repaired.vertex_handle(3 * 7 + 3);  // vertex (3, 3): no neighbour on a boundary
  ASSERT_FALSE(repaired.is_boundary(v));
  repaired.point(v)[2] += 0.1;
  std::size_t around = 0;
  for (auto f : repaired.vf_range(v)) {
    (void)f;
    ++around;
  }
  EXPECT_EQ(validity(input, repaired).original_faces_changed, around);
}

// Two tetrahedra pushed into each other intersect; a new zero-area face is degenerate.
TEST(Validity, IntersectionsAndDegenerateNewFaces) {
  TriangleSoup soup = test::tetrahedron_soup();
  const auto first = soup;
  for (const Point& p : first.points)
    soup.points.push_back(p + Point(0.2, 0.2, 0.2));
  for (auto t : first.triangles)
    soup.triangles.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
  const Mesh two = build_mesh(soup);
  const Validity v = validity(two, two);
  EXPECT_GT(v.self_intersections, 0u);
  EXPECT_EQ(v.patch_self_intersections, 0u);  // every face is original

  Mesh grid = build_mesh(test::grid_soup(1));
  const auto a = grid.add_vertex(Point(2, 0, 0));
  const auto b = grid.add_vertex(Point(3, 0, 0));
  const auto m = grid.add_vertex(Point(2.5, 0, 0));
  grid.add_face(a, b, m);  // collinear: zero area; new by default
  EXPECT_EQ(validity(grid, grid).new_degenerate_faces, 1u);
}

}  // namespace
}  // namespace holebench
