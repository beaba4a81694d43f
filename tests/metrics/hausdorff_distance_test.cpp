#include "metrics/hausdorff_distance.h"

#include "metrics/evaluation.h"

#include "metrics/embree/triangle_scene.h"

#include "core/geometry.h"
#include "generators/box_holes.h"
#include "generators/box_solid.h"
#include "generators/case_catalog.h"
#include "metrics/kept_faces.h"
#include "tests/metrics/test_repairs.h"
#include "tests/test_meshes.h"

// CGAL's graph traits for OpenMesh must come before any CGAL algorithm header.
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>

#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <string>

namespace holebench {
namespace {

// The reference: CGAL's bounded-error symmetric Hausdorff distance, an independent
// implementation (its own bounds, its own AABB tree).
double cgal_hausdorff(const Mesh& a, const Mesh& b, double error_bound) {
  return CGAL::Polygon_mesh_processing::bounded_error_symmetric_Hausdorff_distance<
      CGAL::Sequential_tag>(a, b, error_bound);
}

// Two results agree when their bound intervals overlap: ours is [lower, upper], CGAL's
// value is within error_bound of the truth.
void expect_agrees_with_cgal(const Mesh& a, const Mesh& b, double error_bound) {
  HausdorffOptions options;
  options.error_bound = error_bound;
  const HausdorffResult ours = hausdorff_distance(a, b, options);
  ASSERT_TRUE(ours.converged());
  EXPECT_LE(ours.upper() - ours.lower(), error_bound);
  const double reference = cgal_hausdorff(a, b, error_bound);
  EXPECT_GE(reference, ours.lower() - error_bound);
  EXPECT_LE(reference, ours.upper() + error_bound);
}

Mesh filled_without_refinement(const Mesh& holed) {
  Mesh mesh = holed;
  for (auto h : mesh.halfedges()) {
    if (!mesh.is_boundary(h))
      continue;
    std::vector<FaceHandle> faces;
    CGAL::Polygon_mesh_processing::triangulate_hole(mesh, h, std::back_inserter(faces));
  }
  return mesh;
}

// Zero up to the rounding of the closest-point arithmetic (a few ulp of the coordinates).
TEST(HausdorffDistance, IdenticalMeshesAreAtZero) {
  const Mesh box = generators::make_box({Point(2.0, 1.5, 1.0), 0.25});
  const auto result = hausdorff_distance(box, box);
  EXPECT_LE(result.lower(), 1e-15);
  EXPECT_LE(result.upper(), 1e-15);
}

// Analytic: a unit grid against itself lifted by 0.3 is exactly 0.3 away everywhere.
TEST(HausdorffDistance, ParallelSquaresAtAKnownDistance) {
  TriangleSoup lifted = test::grid_soup(3);
  for (auto& p : lifted.points)
    p[2] += 0.3;
  const auto result = hausdorff_distance(build_mesh(test::grid_soup(3)), build_mesh(lifted));
  EXPECT_NEAR(result.lower(), 0.3, 1e-12);
  EXPECT_LE(result.upper(), 0.3 + 1e-4);
}

// One flat square triangulated two ways (4 x 4 and 5 x 5 cells) is at distance zero both
// ways. A cell that straddles an edge between two of the other mesh's triangles is bounded
// by their union (bound iii, a convex quadrilateral), so only cells around the other mesh's
// vertices are split: with a bound of 1e-6 the search converges in a few thousand queries
// (with single triangles only, it would split along every edge down to 1e-6 and stop at
// the query limit, unconverged).
TEST(HausdorffDistance, OneFlatSquareTriangulatedTwoWaysConvergesAtZero) {
  const Mesh coarse = build_mesh(test::grid_soup(4));
  TriangleSoup fine = test::grid_soup(5);
  for (auto& p : fine.points)
    p *= 4.0 / 5.0;
  HausdorffOptions options;
  options.error_bound = 1e-6;
  options.max_queries = 200'000;
  const auto result = hausdorff_distance(coarse, build_mesh(fine), options);
  EXPECT_TRUE(result.converged());
  EXPECT_LE(result.lower(), 1e-15);
  EXPECT_LE(result.upper(), 1e-6);
  EXPECT_LT(result.a_to_b.queries + result.b_to_a.queries, 100'000u);
}

// A curved surface against its copy moved by 1e-7 (far less than its edges, about 1): the
// corners' nearest faces are around the copies of the corners, and the matching face (the
// copy of each face, spanned by the corners' nearest vertices) bounds every face within the
// move, so no face needs its centroid queried or a split: one query per vertex and direction.
TEST(HausdorffDistance, ACopyMovedLessThanItsEdgesIsBoundedByItsMatchingFaces) {
  TriangleSoup surface = test::grid_soup(20);
  for (auto& p : surface.points)
    p[2] = 2.0 * std::sin(0.4 * p[0]) * std::cos(0.3 * p[1]);
  const Mesh a = build_mesh(surface);
  Mesh b = a;
  const Point move(1e-7, -1e-7, 1e-7);
  for (auto v : b.vertices())
    b.point(v) += move;
  HausdorffOptions options;
  options.error_bound = 1e-4 * bounding_box_diagonal(a);
  const HausdorffResult result = hausdorff_distance(a, b, options);
  ASSERT_TRUE(result.converged());
  EXPECT_EQ(result.a_to_b.queries, a.n_vertices());
  EXPECT_EQ(result.b_to_a.queries, b.n_vertices());
  EXPECT_LE(result.upper(), move.norm() * (1.0 + 1e-6));
  EXPECT_GT(result.lower(), 0.0);
  expect_agrees_with_cgal(a, b, options.error_bound);
}

// Analytic one-sided distances: a 3x3 grid against its first two columns (x <= 2). The
// farthest point of the full grid from the part is at x = 3: distance 1; the other way 0.
TEST(HausdorffDistance, OneSidedDistancesDiffer) {
  const Mesh full = build_mesh(test::grid_soup(3));
  std::vector<std::pair<int, int>> right;
  for (int j = 0; j < 3; ++j)
    right.emplace_back(2, j);
  const Mesh part = build_mesh(test::grid_without_cells(3, right));
  const auto result = hausdorff_distance(full, part);
  EXPECT_NEAR(result.a_to_b.lower, 1.0, 1e-12);  // the part spans x in [0, 2]
  EXPECT_NEAR(result.b_to_a.lower, 0.0, 1e-12);
}

TEST(HausdorffDistance, AgreesWithCgalOnAPlanarHole) {
  const Case c = generators::make_case("box/face_interior");
  expect_agrees_with_cgal(filled_without_refinement(c.input), c.complete, 1e-3);
}

TEST(HausdorffDistance, AgreesWithCgalOnACornerHole) {
  const Case c = generators::make_case("box/corner");
  expect_agrees_with_cgal(filled_without_refinement(c.input), c.complete, 1e-3);
}

TEST(HausdorffDistance, AgreesWithCgalOnANoisyMesh) {
  const Mesh box = generators::make_box({Point(2.0, 1.5, 1.0), 0.25});
  expect_agrees_with_cgal(test::displaced(box, 0.01), box, 1e-4);
}

TEST(HausdorffDistance, AgreesWithCgalOnIdenticalMeshes) {
  const Mesh box = generators::make_box({Point(2.0, 1.5, 1.0), 0.25});
  expect_agrees_with_cgal(box, box, 1e-4);
}

// The numbers the records carry come from evaluate() (one shared first pass for all the
// distances, scenes of the whole models): they agree with CGAL too, at the default bound.
TEST(HausdorffDistance, TheEvaluationsValueAgreesWithCgal) {
  for (const char* id :
       {"box/face_interior", "box/corner", "brep/k3/inner/convex-convex-reflex/small"}) {
    SCOPED_TRACE(id);
    const Case c = generators::make_case(id);
    MethodResult result;
    result.repaired = filled_without_refinement(c.input);
    const Evaluation e = evaluate(c, result);
    const double diagonal = bounding_box_diagonal(c.complete);
    const double bound = EvaluationOptions{}.hausdorff_error_bound_rel_diag;
    const double lower = e.find("hausdorff_rel_diag")->value;
    const double upper = e.find("hausdorff_upper_rel_diag")->value;
    EXPECT_LE(upper - lower, bound * (1.0 + 1e-9));
    const double reference =
        cgal_hausdorff(result.repaired, c.complete, bound * diagonal) / diagonal;
    EXPECT_GE(reference, lower - bound);
    EXPECT_LE(reference, upper + bound);
  }
}

TEST(HausdorffDistance, SameInputsGiveTheSameNumbers) {
  const Case c = generators::make_case("box/corner");
  const Mesh filled = filled_without_refinement(c.input);
  const auto first = hausdorff_distance(filled, c.complete);
  const auto second = hausdorff_distance(filled, c.complete);
  EXPECT_EQ(first.lower(), second.lower());
  EXPECT_EQ(first.upper(), second.upper());
  EXPECT_EQ(first.a_to_b.queries, second.a_to_b.queries);
}

// The first bounds of the input's faces (HausdorffCellBounds) replayed for a repair of it
// give the same search: the same bounds, queries and convergence, bit for bit, whatever the
// error bound (and so whatever the search takes as settled: the repair's patch can raise
// the largest distance found first above the input's). Noisy, so that no input face lies on
// the complete model and every kept face replays its steps.
TEST(HausdorffCellBounds, ReplayedBoundsGiveTheSameSearch) {
  for (const char* id : {"box/corner", "brep/k3/inner/convex-convex-convex/small"}) {
    const Case c = generators::make_case(id, 0, 25.0);
    const embree::TriangleScene complete_scene(c.complete);
    const HausdorffCellBounds first(c.input, complete_scene,
                                    first_pass(c.input, c.complete, complete_scene));
    EXPECT_EQ(first.size(), c.input.n_faces()) << id;
    const Mesh repaired = filled_without_refinement(c.input);
    const double diagonal = bounding_box_diagonal(c.complete);
    for (double bound : {1e-2, 1e-4, 1e-6}) {
      HausdorffOptions options;
      options.error_bound = bound * diagonal;
      const DirectedHausdorff alone = directed_hausdorff(repaired, complete_scene, options);
      const DirectedHausdorff replayed =
          directed_hausdorff(repaired, complete_scene, options, {}, &first);
      const std::string what = std::string(id) + " bound " + std::to_string(bound);
      EXPECT_EQ(alone.lower, replayed.lower) << what;
      EXPECT_EQ(alone.upper, replayed.upper) << what;
      EXPECT_EQ(alone.queries, replayed.queries) << what;
      EXPECT_EQ(alone.converged, replayed.converged) << what;
    }
  }
}

// The same on a flat square above another triangulated otherwise, where the shared-edge
// bound (iii) of the first cells decides which of them are settled.
TEST(HausdorffCellBounds, ReplayedSharedEdgeBoundsGiveTheSameSearch) {
  const Mesh coarse = build_mesh(test::grid_soup(4));
  TriangleSoup fine = test::grid_soup(5);
  for (auto& p : fine.points) {
    p *= 4.0 / 5.0;
    p[2] += 1e-3;
  }
  const Mesh lifted = build_mesh(fine);
  const embree::TriangleScene coarse_scene(coarse);
  const HausdorffCellBounds first(lifted, coarse_scene, first_pass(lifted, coarse, coarse_scene));
  for (double bound : {1e-2, 1e-4, 1e-6}) {
    HausdorffOptions options;
    options.error_bound = bound;
    options.max_queries = 200'000;
    const DirectedHausdorff alone = directed_hausdorff(lifted, coarse_scene, options);
    const DirectedHausdorff replayed =
        directed_hausdorff(lifted, coarse_scene, options, {}, &first);
    EXPECT_EQ(alone.lower, replayed.lower) << bound;
    EXPECT_EQ(alone.upper, replayed.upper) << bound;
    EXPECT_EQ(alone.queries, replayed.queries) << bound;
  }
}

// The first bounds of the complete model's faces against the input, taken for a search
// against a repair of the input (a fan closing: the input's faces kept, new faces after
// them; or one input face dropped, the others kept in order), where the repair differs from
// the input only outside what each cell's steps read (SurfaceChange): the same search, bit
// for bit; most cells are taken, and the ones whose centroid's ball meets the changes are not
// (without the changed box more would be).
TEST(HausdorffCellBounds, TakenAgainstARepairOfB0GiveTheSameSearch) {
  for (const char* id : {"box/corner", "brep/k3/inner/convex-convex-convex/small"}) {
    const Case c = generators::make_case(id, 0, 25.0);
    const embree::TriangleScene input_scene(c.input);
    const HausdorffCellBounds first(c.complete, input_scene,
                                    first_pass(c.complete, c.input, input_scene));
    EXPECT_EQ(first.size(), c.complete.n_faces()) << id;
    // The input's faces at their own indices, and (an input face dropped) one index lower.
    for (const bool in_place : {true, false}) {
      const Mesh repaired =
          in_place ? test::fan_closing(c.input) : test::drop_in_order_and_fan(c.input);
      const embree::TriangleScene repaired_scene(repaired);
      const KeptFaces kept = kept_faces(c.input, repaired);
      ASSERT_TRUE(kept.order_kept) << id;
      ASSERT_EQ(kept.input_faces_in_place, in_place) << id;
      SurfaceChange change;
      change.b0_face_of_b = &kept.input_face_of_repaired;
      change.b_face_of_b0 = &kept.repaired_face_of_input;
      change.changed = changed_faces_box(c.input, repaired, kept);
      SurfaceChange unchanged = change;
      unchanged.changed = GrowingBox();
      const double diagonal = bounding_box_diagonal(c.complete);
      for (double bound : {1e-2, 1e-4, 1e-6}) {
        HausdorffOptions options;
        options.error_bound = bound * diagonal;
        const DirectedHausdorff alone = directed_hausdorff(c.complete, repaired_scene, options);
        const DirectedHausdorff taken =
            directed_hausdorff(c.complete, repaired_scene, options, {}, &first, &change);
        const std::string what =
            std::string(id) + (in_place ? "" : " dropped") + " bound " + std::to_string(bound);
        EXPECT_EQ(alone.cells_taken, 0u) << what;
        EXPECT_GT(taken.cells_taken, c.complete.n_faces() / 2) << what;
        EXPECT_EQ(alone.lower, taken.lower) << what;
        EXPECT_EQ(alone.upper, taken.upper) << what;
        EXPECT_EQ(alone.queries, taken.queries) << what;
        EXPECT_EQ(alone.converged, taken.converged) << what;
        const DirectedHausdorff careless =
            directed_hausdorff(c.complete, repaired_scene, options, {}, &first, &unchanged);
        EXPECT_LT(taken.cells_taken, careless.cells_taken) << what;
      }
    }
  }
}

}  // namespace
}  // namespace holebench
