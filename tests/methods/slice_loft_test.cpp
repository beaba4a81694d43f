// Tests of methods/slice_loft: the steps of section 4 of the slice paper on tiny generated
// cases, and the method's invariants (closed, manifold, original faces kept).
#include "methods/slice_loft/slice_loft.h"
#include "methods/slice_loft/slice_loft_variants.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"
#include "generators/case_catalog.h"
#include "methods/slice_loft/discrete_curvature.h"
#include "methods/slice_loft/holes_and_islands.h"
#include "metrics/evaluation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace holebench {
namespace {

MethodResult run_loft(const Case& c) {
  NoUser user;
  return SliceLoftMethod().run(c.input, MethodParameters{}, user);
}

double metric(const Evaluation& evaluation, const std::string& name) {
  const MetricValue* value = evaluation.find(name);
  return value ? value->value : std::nan("");
}

std::string notes(const MethodResult& result) {
  std::string text = result.message;
  for (const auto& hole : result.holes)
    text += " | " + hole.note;
  return text;
}

// Equations 1-3: equal forward and backward discrete curvature continue a circle as the same
// circle (and a line as a line).
TEST(SliceLoftCurvature, TracingContinuesACircleExactly) {
  const double r = 2.0, step_angle = 0.1;
  auto circle = [&](double a) { return Point(r * std::cos(a), r * std::sin(a), 0.5); };
  slice_loft::TraceOptions options;
  options.step = 2.0 * r * std::sin(step_angle / 2.0);  // the chord of the same angle
  options.max_steps = 20;
  options.max_turn_rad = 1.0;
  const auto traced = slice_loft::trace_curvature_continuous(
      circle(-2 * step_angle), circle(-step_angle), circle(0.0), options, nullptr);
  ASSERT_EQ(traced.size(), 21u);
  for (const Point& p : traced) {
    EXPECT_NEAR(std::hypot(p[0], p[1]), r, 1e-9 * r);
    EXPECT_NEAR(p[2], 0.5, 1e-12);
  }
}

// 4.1: the outer loop of an island case develops to a hole, the inner one to an island,
// and the island is clustered to the hole (its influencing area includes the island).
TEST(SliceLoftHolesAndIslands, AnnulusGivesOneHoleWithOneIsland) {
  const Case c = generators::make_case("solid/l_block/island/small");
  const auto found = slice_loft::identify_holes_and_islands(c.input);
  ASSERT_EQ(found.contours.size(), 2u);
  ASSERT_EQ(found.holes.size(), 1u);
  EXPECT_FALSE(found.holes[0].orphan_island);
  ASSERT_EQ(found.holes[0].islands.size(), 1u);
  EXPECT_TRUE(found.contours[found.holes[0].islands[0]].island);
  EXPECT_FALSE(found.contours[found.holes[0].contour].island);
}

// The box corner hole (three regions): three segments, three missing edges meeting at a
// recovered corner; the patch's vertex nearest the true corner is within 0.2 % of the
// diagonal (the construction is exact for planes up to the tracing of the boundary edges).
TEST(SliceLoft, CornerHoleRecoversTheCorner) {
  const Case c = generators::make_case("box/corner");
  const MethodResult result = run_loft(c);
  ASSERT_EQ(result.status, MethodStatus::Ok) << notes(result);
  ASSERT_EQ(result.holes.size(), 1u);
  EXPECT_NE(result.holes[0].note.find("missing corner"), std::string::npos) << notes(result);
  const double diagonal = bounding_box_diagonal(c.complete);
  ASSERT_EQ(c.holes.size(), 1u);
  ASSERT_EQ(c.holes[0].missing_corners.size(), 1u);
  const Point corner = c.holes[0].missing_corners[0];
  double nearest = 1e300;
  for (auto v : result.repaired.vertices()) {
    if (is_new(result.repaired, v))
      nearest = std::min(nearest, (result.repaired.point(v) - corner).norm());
  }
  EXPECT_LT(nearest, 2e-3 * diagonal);
  const Evaluation evaluation = evaluate(c, result);
  EXPECT_EQ(metric(evaluation, "missing_edge_present_fraction"), 1.0);
}

// The box edge hole: the missing edge is rebuilt (a sharp edge of the result along every
// missing edge, metrics/feature_recovery) and the patch lies on the two faces.
TEST(SliceLoft, EdgeHoleRebuildsItsEdge) {
  const Case c = generators::make_case("box/edge");
  const MethodResult result = run_loft(c);
  ASSERT_EQ(result.status, MethodStatus::Ok) << notes(result);
  const Evaluation evaluation = evaluate(c, result);
  EXPECT_EQ(metric(evaluation, "missing_edge_present_fraction"), 1.0);
  EXPECT_LT(metric(evaluation, "hole_hausdorff_rel_diag"), 1e-6);
}

// A hole inside a planar face is filled in that plane: every new vertex lies on it (to
// rounding).
TEST(SliceLoft, PlanarHoleStaysPlanar) {
  const Case c = generators::make_case("box/face_interior");
  const MethodResult result = run_loft(c);
  ASSERT_EQ(result.status, MethodStatus::Ok) << notes(result);
  const auto loops = find_boundary_loops(c.input);
  ASSERT_EQ(loops.size(), 1u);
  const Point a = c.input.point(c.input.from_vertex_handle(loops[0].halfedges[0]));
  const Point n = face_normal(
      c.input, c.input.face_handle(c.input.opposite_halfedge_handle(loops[0].halfedges[0])));
  const double diagonal = bounding_box_diagonal(c.complete);
  std::size_t new_vertices = 0;
  for (auto v : result.repaired.vertices()) {
    if (!is_new(result.repaired, v))
      continue;
    ++new_vertices;
    EXPECT_LT(std::abs(OpenMesh::dot(result.repaired.point(v) - a, n)), 1e-12 * diagonal);
  }
  EXPECT_GT(new_vertices, 0u);
}

// A hole with an island: the island's triangles are kept (every input face is still there,
// the island's boundary is sewn to the patch) and the result is closed.
TEST(SliceLoft, IslandIsKeptAndFilledAround) {
  const Case c = generators::make_case("solid/l_block/island/small");
  const MethodResult result = run_loft(c);
  ASSERT_EQ(result.status, MethodStatus::Ok) << notes(result);
  EXPECT_NE(result.holes[0].note.find("1 island"), std::string::npos) << notes(result);
  EXPECT_EQ(result.repaired.n_faces() - count_new_faces(result.repaired), c.input.n_faces());
  EXPECT_TRUE(find_boundary_loops(result.repaired).empty());
}

// HoleReport::fallback: empty where the paper's decomposition produced the patch (the box
// corner: three portions bounded by the rebuilt edges); "one_portion_without_features" where
// the whole hole was filled as one portion instead, both when step III rebuilds no features
// (three linearly dependent faces: the traced edges do not meet at one corner) and when the
// decomposition with features fails later and the hole is filled again as one portion. The
// cases are those of the nightly baseline whose notes say so.
TEST(SliceLoft, FallbackNamesTheOnePortionFill) {
  const MethodResult corner = run_loft(generators::make_case("box/corner"));
  ASSERT_EQ(corner.holes.size(), 1u);
  EXPECT_TRUE(corner.holes[0].closed);
  EXPECT_EQ(corner.holes[0].fallback, "") << notes(corner);

  // With the project's guard on the corner, the three missing edges of this hole (its faces'
  // planes share no point) do not meet, and it is filled as one portion.
  SliceLoftOptions guarded;
  guarded.features.reject_far_corner = true;
  const MethodResult dependent = run_slice_loft(
      generators::make_case("brep/k3/linearly-dependent/small", 0, 5.0).input, guarded);
  ASSERT_EQ(dependent.holes.size(), 1u);
  EXPECT_NE(dependent.holes[0].note.find("missing features not rebuilt"), std::string::npos)
      << notes(dependent);
  EXPECT_EQ(dependent.holes[0].fallback, "one_portion_without_features") << notes(dependent);

  // Without the developed disc, a portion of this hole folds in every trimming domain left,
  // and the hole is filled again as one portion.
  SliceLoftOptions no_disc;
  no_disc.tessellation.developed_disc = false;
  const MethodResult refilled = run_slice_loft(
      generators::make_case("brep/k3/outer/reflex-reflex-reflex/inner-outer-outer/small").input,
      no_disc);
  ASSERT_FALSE(refilled.holes.empty());
  std::size_t refills = 0;
  for (const auto& hole : refilled.holes) {
    const bool refill =
        hole.note.find("filled as one portion without features") != std::string::npos;
    refills += refill ? 1 : 0;
    if (refill) {
      EXPECT_EQ(hole.fallback, "one_portion_without_features") << hole.note;
    }
  }
  EXPECT_GT(refills, 0u) << notes(refilled);
}

// Away from the hole nothing changes: every input vertex keeps its position bit for bit,
// and every input face is still there with the same vertices.
TEST(SliceLoft, InputUnchangedAwayFromTheHole) {
  for (const char* id : {"box/corner", "solid/stepped_block/corner_ccr/small"}) {
    SCOPED_TRACE(id);
    const Case c = generators::make_case(id);
    const MethodResult result = run_loft(c);
    ASSERT_GE(result.repaired.n_vertices(), c.input.n_vertices());
    for (auto v : c.input.vertices())
      EXPECT_EQ(result.repaired.point(v), c.input.point(v));
    for (auto f : c.input.faces()) {
      std::vector<int> before, after;
      for (auto v : f.vertices())
        before.push_back(v.idx());
      for (auto v : result.repaired.fv_range(f))
        after.push_back(v.idx());
      EXPECT_EQ(before, after);
    }
  }
}

// Both methods close every hole of the box and of a spread of solid cases, with a manifold
// result (OpenMesh's add_face refuses faces against the orientation, so the patch is
// consistently oriented by construction).
TEST(SliceLoft, OutputIsClosedAndManifold) {
  for (const char* id :
       {"box/face_interior", "box/edge", "box/corner", "solid/l_block/edge_reflex/small",
        "solid/notched_block/corner_rrr/small", "solid/cylinder/curved_face/small",
        "solid/cone/cone_apex/small", "solid/cylinder/island/small"}) {
    SCOPED_TRACE(id);
    const Case c = generators::make_case(id);
    NoUser user;
    // The project's departures (slice_loft_plus, slice_direct_plus): on the paper's 10 %
    // influencing area some of these holes find no section (docs/slice_loft.md).
    for (const MethodResult& result :
         {run_slice_loft(c.input, slice_loft::plus_options(false)),
          SliceLoftMethod(slice_loft::plus_options(true)).run(c.input, MethodParameters{}, user)}) {
      EXPECT_EQ(result.status, MethodStatus::Ok) << notes(result);
      EXPECT_TRUE(find_boundary_loops(result.repaired).empty()) << notes(result);
      for (auto v : result.repaired.vertices())
        EXPECT_TRUE(result.repaired.is_manifold(v));
    }
  }
}

// Trimming on the surface (4.5): a corner hole one of whose portions folds over in its own
// plane (the traced missing edges cross its segment there) is trimmed in the lofted
// surface's (u, s) domain and filled on the paper's path, without a fallback. The fold
// comes from missing edges running along the boundary, which the snapping of
// missing-feature points onto boundary vertices removes (pinched_portions.h): without it,
// the surface domain must do.
TEST(SliceLoft, PortionFoldedInItsPlaneIsTrimmedOnTheSurface) {
  const Case c = generators::make_case("brep/k3/inner/convex-reflex-reflex/small");
  SliceLoftOptions no_snapping = slice_loft::plus_options(false);  // slice_loft_plus
  no_snapping.tessellation.feature_snap_edges = 0.0;
  const MethodResult result = run_slice_loft(c.input, no_snapping);
  ASSERT_EQ(result.holes.size(), 1u);
  const HoleReport& hole = result.holes[0];
  EXPECT_TRUE(hole.closed) << notes(result);
  EXPECT_EQ(hole.fallback, "") << notes(result);
  EXPECT_NE(hole.note.find("trimmed on the surface"), std::string::npos) << notes(result);
  EXPECT_TRUE(find_boundary_loops(result.repaired).empty()) << notes(result);
  for (auto v : result.repaired.vertices())
    EXPECT_TRUE(result.repaired.is_manifold(v));
  for (auto v : c.input.vertices())
    EXPECT_EQ(result.repaired.point(v), c.input.point(v));
}

// A missing edge whose feature line ends at the hole (the traces from both ends lead away
// from each other) is joined straight and the hole is filled on the paper's path.
// Section 4.3: "the corner point is determined by finding the closest point on each extracted
// missing edge to the other extracted edges and taking the average of these points", with no
// test of how close the edges come. The hole whose faces' planes share no point gets its
// corner that way and is filled on the paper's path, as the guarded option's test above
// fills it without features.
TEST(SliceLoft, MissingCornerIsTheAverageOfTheClosestPoints) {
  for (const double noise : {0.0, 5.0}) {
    const MethodResult result =
        run_loft(generators::make_case("brep/k3/linearly-dependent/small", 0, noise));
    ASSERT_EQ(result.holes.size(), 1u);
    EXPECT_TRUE(result.holes[0].closed) << notes(result);
    EXPECT_EQ(result.holes[0].fallback, "") << notes(result);
    EXPECT_NE(result.holes[0].note.find("3 missing edge(s) and a missing corner"),
              std::string::npos)
        << notes(result);
  }
}

TEST(SliceLoft, MissingEdgeEndingAtTheHoleIsJoinedStraight) {
  const MethodResult result =
      run_slice_loft(generators::make_case("brep/k2/outer/convex/inner-outer/small").input,
                     slice_loft::plus_options(false));  // slice_loft_plus
  ASSERT_EQ(result.holes.size(), 1u);
  EXPECT_TRUE(result.holes[0].closed) << notes(result);
  EXPECT_EQ(result.holes[0].fallback, "") << notes(result);
  EXPECT_NE(result.holes[0].note.find("joined straight"), std::string::npos) << notes(result);
}

}  // namespace
}  // namespace holebench
