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

// Two tetrahedra pushed into each other: they intersect.
TriangleSoup two_tetrahedra_soup() {
  TriangleSoup soup = test::tetrahedron_soup();
  const auto first = soup;
  for (const Point& p : first.points)
    soup.points.push_back(p + Point(0.2, 0.2, 0.2));
  for (auto t : first.triangles)
    soup.triangles.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
  return soup;
}

// Two tetrahedra pushed into each other intersect; a new zero-area face is degenerate.
TEST(Validity, IntersectionsAndDegenerateNewFaces) {
  const Mesh two = build_mesh(two_tetrahedra_soup());
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

// The self-intersections of a repair counted from the input's own pairs (as a group of jobs
// on one case counts them) are the whole test's: an input that intersects itself, a patch
// that closes its hole, one new face that pierces an input face and one that crosses the
// patch.
TEST(Validity, SelfIntersectionsFromTheInputsPairsAreTheWholeTests) {
  TriangleSoup soup = two_tetrahedra_soup();
  const TriangleSoup grid = test::grid_without_cells(3, {{1, 1}});
  const int offset = static_cast<int>(soup.points.size());
  for (const Point& p : grid.points)
    soup.points.push_back(p + Point(5, 0, 0));
  for (auto t : grid.triangles)
    soup.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  const Mesh input = build_mesh(soup);
  const InputSelfIntersections known = input_self_intersections(input);
  ASSERT_FALSE(known.pairs.empty());

  Mesh repaired = input;
  const auto grid_vertex = [&](int i, int j) { return repaired.vertex_handle(offset + j * 4 + i); };
  repaired.add_face(grid_vertex(1, 1), grid_vertex(2, 1), grid_vertex(2, 2));  // the patch
  repaired.add_face(grid_vertex(1, 1), grid_vertex(2, 2), grid_vertex(1, 2));
  const auto a = repaired.add_vertex(Point(0.1, 0.1, -0.5));  // through the first tetrahedron
  const auto b = repaired.add_vertex(Point(0.1, 0.2, 0.5));
  const auto c = repaired.add_vertex(Point(0.3, 0.1, 0.5));
  repaired.add_face(a, b, c);
  const auto d = repaired.add_vertex(Point(6.5, 1.5, -0.5));  // through the patch
  const auto e = repaired.add_vertex(Point(6.5, 1.6, 0.5));
  const auto f = repaired.add_vertex(Point(6.6, 1.5, 0.5));
  repaired.add_face(d, e, f);

  const Validity whole = validity(input, repaired);
  const cgal::SelfIntersections from_input = self_intersections_from_input(input, repaired, known);
  EXPECT_EQ(from_input.pairs, whole.self_intersections);
  EXPECT_EQ(from_input.patch_pairs, whole.patch_self_intersections);
  EXPECT_EQ(whole.self_intersections, known.pairs.size() + whole.patch_self_intersections);
  EXPECT_GE(whole.patch_self_intersections, 2u);  // a tetrahedron's face and the patch
  ValidityShortcuts shortcuts;
  shortcuts.input_pairs = &known;
  EXPECT_EQ(validity(input, repaired, {}, shortcuts).self_intersections, whole.self_intersections);

  // A repair that moved an input vertex: its faces are not the input's any more, and are
  // tested again.
  Mesh moved = repaired;
  moved.point(moved.vertex_handle(4)) += Point(0.3, 0.3, 0.3);
  const Validity moved_whole = validity(input, moved);
  const cgal::SelfIntersections moved_from_input =
      self_intersections_from_input(input, moved, known);
  EXPECT_EQ(moved_from_input.pairs, moved_whole.self_intersections);
  EXPECT_EQ(moved_from_input.patch_pairs, moved_whole.patch_self_intersections);
}

}  // namespace
}  // namespace holebench
