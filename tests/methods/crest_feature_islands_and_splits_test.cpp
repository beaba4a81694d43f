// Tests of what crest_feature adds to its paper's steps so that the paper's own filling
// (equation 6's projection) serves every hole: islands attached to the hole around them
// (hole_identification.h), chords the mesh already has split (hole_filling.h), and sub-holes
// cut into more planar pieces for equation 6 (planarity_split.h).
#include "core/boundary_loops.h"
#include "core/plane_fit.h"
#include "generators/case_catalog.h"
#include "methods/crest_feature/crest_feature.h"
#include "methods/crest_feature/hole_filling.h"
#include "methods/crest_feature/hole_identification.h"
#include "methods/crest_feature/planarity_split.h"
#include "metrics/evaluation.h"
#include "tests/test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace holebench {
namespace {

using namespace crest_feature;

double metric(const Evaluation& e, const std::string& name) {
  const MetricValue* v = e.find(name);
  return v ? v->value : std::nan("");
}

// An island case has two boundary loops: the hole's and the island's. The island's loop is
// attached to the hole (and is no hole of its own); the relation is not symmetric; with the
// option off every loop is a hole, as in the paper.
TEST(CrestFeatureIslands, IslandLoopIsAttachedToTheHoleAroundIt) {
  for (const std::string id :
       {"solid/l_block/island/small", "solid/cylinder/island/small", "cad/fandisk/island/small"}) {
    const Case c = generators::make_case(id);
    const auto loops = find_boundary_loops(c.input);
    ASSERT_EQ(loops.size(), 2u) << id;
    const std::size_t outer = loops[0].size() > loops[1].size() ? 0 : 1;
    EXPECT_TRUE(is_island_of(c.input, loops[1 - outer], loops[outer])) << id;
    EXPECT_FALSE(is_island_of(c.input, loops[outer], loops[1 - outer])) << id;

    const auto holes = identify_holes(c.input);
    ASSERT_EQ(holes.size(), 1u) << id;
    EXPECT_EQ(holes[0].vertices.size(), loops[outer].size()) << id;
    ASSERT_EQ(holes[0].islands.size(), 1u) << id;
    EXPECT_EQ(holes[0].islands[0], loop_vertices(c.input, loops[1 - outer])) << id;

    HoleIdentificationOptions paper;
    paper.attach_islands = false;
    EXPECT_EQ(identify_holes(c.input, paper).size(), 2u) << id;
  }
}

// Two holes side by side in an open sheet are no islands of each other nor of the sheet's
// border (which runs the island's way round and contains both); on the box cases, a hole is
// no island either.
TEST(CrestFeatureIslands, SeparateHolesAreNoIslands) {
  TriangleSoup soup = test::grid_soup(8);
  std::vector<std::array<int, 3>> kept;
  for (const auto& t : soup.triangles) {
    Point c(0, 0, 0);
    for (int v : t)
      c += soup.points[v];
    c /= 3.0;
    const bool in_first = c[0] > 1 && c[0] < 3 && c[1] > 1 && c[1] < 3;
    const bool in_second = c[0] > 5 && c[0] < 7 && c[1] > 5 && c[1] < 7;
    if (!in_first && !in_second)
      kept.push_back(t);
  }
  soup.triangles = kept;
  const Mesh sheet = build_mesh(soup);
  ASSERT_EQ(find_boundary_loops(sheet).size(), 3u);
  const auto holes = identify_holes(sheet);
  EXPECT_EQ(holes.size(), 3u);
  for (const auto& hole : holes)
    EXPECT_TRUE(hole.islands.empty());
  for (const std::string id : {"box/face_interior", "box/edge", "box/corner"}) {
    const Case c = generators::make_case(id);
    for (const auto& hole : identify_holes(c.input))
      EXPECT_TRUE(hole.islands.empty()) << id;
  }
}

// The hole around an island is filled as the region between the two loops, by equation 6
// (no fallback), and on a planar face that filling is exact: before, the island's loop was
// filled as a second hole on top of the first patch.
TEST(CrestFeatureIslands, HoleAroundAnIslandIsFilledAsTheRegionBetween) {
  for (const std::string id :
       {"solid/l_block/island/small", "cad/fandisk/island/small", "solid/cylinder/island/small"}) {
    const Case c = generators::make_case(id);
    NoUser user;
    const MethodResult result = CrestFeatureMethod().run(c.input, {}, user);
    ASSERT_EQ(result.holes.size(), 1u) << id;
    EXPECT_TRUE(result.holes[0].closed) << id;
    EXPECT_EQ(result.holes[0].fallback, "") << id << ": " << result.holes[0].note;
    const Evaluation e = evaluate(c, result);
    EXPECT_EQ(metric(e, "is_closed"), 1.0) << id;
    EXPECT_EQ(metric(e, "is_manifold"), 1.0) << id;
    EXPECT_EQ(metric(e, "self_intersections_count"), 0.0) << id;
    EXPECT_EQ(metric(e, "original_faces_unchanged_ok"), 1.0) << id;
    if (id != "solid/cylinder/island/small") {
      EXPECT_LT(metric(e, "hole_hausdorff_rel_diag"), 1e-12) << id;
    }
  }
}

// A square A B C D made of the triangles A B C and A C D: its boundary loop, seen as a hole,
// filled by the same diagonal A C would give that edge three faces. The chord is split at its
// midpoint; no triangle edge is then an edge the mesh has inside, and every loop edge is
// still used once.
TEST(CrestFeatureSplitChords, ChordTheMeshAlreadyHasIsSplitAtItsMidpoint) {
  TriangleSoup soup;
  soup.points = {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0)};
  soup.triangles = {{0, 1, 2}, {0, 2, 3}};
  const Mesh mesh = build_mesh(soup);
  const Node A = 0, B = 1, C = 2, D = 3;
  std::vector<std::array<Node, 3>> triangles{{B, A, C}, {D, C, A}};
  std::vector<Point> new_points;
  EXPECT_EQ(split_chords_the_mesh_has(mesh, triangles, new_points), 1u);
  ASSERT_EQ(new_points.size(), 1u);
  EXPECT_EQ(new_points[0], Point(0.5, 0.5, 0));
  EXPECT_EQ(triangles.size(), 4u);
  int loop_edges = 0;
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      const Node a = t[k], b = t[(k + 1) % 3];
      if (a < 0 || b < 0)
        continue;
      const auto h = mesh.find_halfedge(mesh.vertex_handle(a), mesh.vertex_handle(b));
      ASSERT_TRUE(h.is_valid()) << a << " " << b;
      EXPECT_TRUE(mesh.is_boundary(h)) << a << " " << b;
      ++loop_edges;
    }
  }
  EXPECT_EQ(loop_edges, 4);
}

// A loop folded over a right angle: half on the plane z = 0, half on x = 0, meeting along
// the y axis. No projection of the whole is simple where its two halves overlap (here the
// projector accepts planar loops only), so the loop is cut once, along the fold, into two
// planar pieces that run the loop's way round.
TEST(CrestFeaturePlanaritySplit, FoldedLoopIsCutAlongTheFold) {
  std::vector<Point> corners{Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0),
                             Point(0, 1, 1), Point(0, 0, 1), Point(0, 0, 0)};
  std::vector<Point> points;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    for (int s = 0; s < 4; ++s)
      points.push_back(corners[k] + (corners[(k + 1) % corners.size()] - corners[k]) * (s / 4.0));
  }
  std::vector<Node> loop;
  for (std::size_t k = 0; k < points.size(); ++k)
    loop.push_back(static_cast<Node>(k));
  std::vector<Point> new_points;
  auto point = [&](Node n) { return n >= 0 ? points[n] : new_points[new_point_index(n)]; };
  auto planar_only = [&](const std::vector<Node>& piece) {
    std::vector<Point> p;
    for (Node n : piece)
      p.push_back(point(n));
    const PlaneFit fit = fit_plane(p);
    PolygonTriangulation t;
    if (fit.valid && fit.plane.rms_residual < 1e-9)
      t = triangulate_planar_polygon(p, fit.plane);
    return t;
  };
  ASSERT_FALSE(planar_only(loop).ok);
  const PlanaritySplit split = split_for_equation_6(loop, new_points, point, planar_only);
  ASSERT_TRUE(split.ok);
  EXPECT_EQ(split.chords, 1);
  ASSERT_EQ(split.pieces.size(), 2u);
  for (const Point& p : new_points) {  // the chord's points: on the fold
    EXPECT_NEAR(p[0], 0.0, 1e-15);
    EXPECT_NEAR(p[2], 0.0, 1e-15);
  }
  std::size_t triangles = 0;
  for (const auto& piece : split.pieces) {
    EXPECT_TRUE(piece.triangulation.ok);
    triangles += piece.triangulation.triangles.size();
    // The piece keeps the loop's direction: where it follows two consecutive loop points,
    // they come in the loop's order.
    for (std::size_t k = 0; k + 1 < piece.nodes.size(); ++k) {
      const Node a = piece.nodes[k], b = piece.nodes[k + 1];
      if (a >= 0 && b >= 0) {
        EXPECT_EQ((a + 1) % static_cast<Node>(loop.size()), b);
      }
    }
  }
  // Two planar polygons with n1 + n2 = loop + 2 * (chord points + 2) - 2 shared ... every
  // triangle count of a simple polygon is its point count minus two.
  std::size_t piece_points = 0;
  for (const auto& piece : split.pieces)
    piece_points += piece.nodes.size();
  EXPECT_EQ(triangles, piece_points - 4);
}

}  // namespace
}  // namespace holebench
