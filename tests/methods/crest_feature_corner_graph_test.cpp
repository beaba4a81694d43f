// The user's corner graph (not in the crest-line paper, whose user names one corner triple):
// further corners, each reached by two or more feature lines, and feature lines between two
// corners. Tests of the partition it gives and of the oracle that answers with it.
#include "methods/crest_feature/crest_feature.h"
#include "methods/crest_feature/hole_partitioning.h"

#include "generators/case_catalog.h"
#include "metrics/evaluation.h"

// The oracle user lives in the harness library (linked by methods_tests).
#include "harness/run/oracle_user.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace holebench {
namespace {

using namespace crest_feature;

double metric(const Evaluation& e, const std::string& name) {
  const MetricValue* v = e.find(name);
  return v ? v->value : -1.0;
}

// A square hole of 8 boundary vertices: (0,0) (1,0) (2,0) (2,1) (2,2) (1,2) (0,2) (0,1).
Hole square_hole() {
  Mesh mesh;
  Hole hole;
  const double xy[8][2] = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
  for (const auto& p : xy)
    hole.vertices.push_back(mesh.add_vertex(Point(p[0], p[1], 0)));
  hole.centroid = Point(1, 1, 0);
  hole.radius = 1.5;
  hole.average_edge_length = 1.0;
  return hole;
}

// Two corners joined by a link, each reached by two feature lines (the shape of the fandisk's
// multi-feature hole: an H) split the square into four sub-holes (left, right, bottom, top),
// each corner a node of three of them, and no line is dropped.
TEST(CrestFeatureCornerGraph, TwoLinkedCornersSplitTheHoleIntoFourSubHoles) {
  const Hole hole = square_hole();
  FeatureLines lines;
  lines.corners = {Point(0.6, 1, 0), Point(1.4, 1, 0)};
  auto to_corner = [](int from, int corner) {
    FeatureLine line{from, -1, {}};
    line.to_corner = corner;
    return line;
  };
  lines.lines = {to_corner(0, 0), to_corner(6, 0), to_corner(2, 1), to_corner(4, 1)};
  FeatureLine link{-1, -1, {Point(1, 1, 0)}};
  link.from_corner = 0;
  link.to_corner = 1;
  lines.lines.push_back(link);

  const HolePartition partition = partition_hole(hole, lines);
  EXPECT_TRUE(partition.dropped.empty());
  ASSERT_EQ(partition.sub_holes.size(), 4u);
  // The two corners and the link's point are new points, each on two or three sub-holes.
  ASSERT_EQ(partition.new_points.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    int on = 0;
    for (const auto& sub : partition.sub_holes)
      on += std::find(sub.begin(), sub.end(), new_point_node(i)) != sub.end() ? 1 : 0;
    EXPECT_GE(on, 2) << "new point " << i;
  }
  // Every boundary vertex is on some sub-hole. The pieces: (6 7 0 C0), (2 3 4 C1),
  // (C0 0 1 2 C1 L) and (C1 4 5 6 C0 L), with L the link's inner point.
  std::set<int> boundary;
  std::size_t total = 0;
  for (const auto& sub : partition.sub_holes) {
    total += sub.size();
    for (Node n : sub)
      if (n >= 0)
        boundary.insert(n);
  }
  EXPECT_EQ(boundary.size(), 8u);
  EXPECT_EQ(total, 4u + 4u + 6u + 6u);
}

// A corner with a line whose other end is a corner that was left out is dropped, with its
// reason, and the rest of the graph still partitions the hole.
TEST(CrestFeatureCornerGraph, LinkToACornerWithOneLineIsDropped) {
  const Hole hole = square_hole();
  FeatureLines lines;
  lines.corners = {Point(0.6, 1, 0), Point(1.4, 1, 0)};
  FeatureLine a{0, -1, {}}, b{6, -1, {}}, c{2, -1, {}};
  a.to_corner = b.to_corner = 0;
  c.to_corner = 1;  // one line only: no corner node
  FeatureLine link{-1, -1, {}};
  link.from_corner = 0;
  link.to_corner = 1;
  lines.lines = {a, b, c, link};
  const HolePartition partition = partition_hole(hole, lines);
  EXPECT_EQ(partition.sub_holes.size(), 2u);
  EXPECT_EQ(partition.dropped.size(), 2u);
}

// The fandisk's multi-feature hole has two missing corners joined by a missing edge, each
// reached by two missing edges from the boundary: the paper's user (pairs and one corner
// triple) can express none of it, and the hole is filled without feature lines. With the
// corner graph the oracle names both corners and their link, and every missing edge is
// restored.
TEST(CrestFeatureCornerGraph, OracleRestoresTwoLinkedCornersOnTheFandisk) {
  const Case c = generators::make_case("cad/fandisk/multi_feature/small");
  ASSERT_EQ(c.holes.size(), 1u);
  ASSERT_EQ(c.holes[0].missing_corners.size(), 2u);

  harness::OracleOptions paper_only;
  paper_only.corner_graph = false;
  harness::OracleUser paper_user(c, paper_only);
  const MethodResult paper = CrestFeatureMethod().run(c.input, {}, paper_user);
  EXPECT_EQ(metric(evaluate(c, paper), "missing_edge_present_fraction"), 0.0);

  harness::OracleUser oracle(c);
  const MethodResult graph = CrestFeatureMethod().run(c.input, {}, oracle);
  ASSERT_EQ(graph.holes.size(), 1u);
  EXPECT_TRUE(graph.holes[0].closed);
  EXPECT_EQ(graph.holes[0].fallback, "") << graph.holes[0].note;
  EXPECT_NE(graph.holes[0].note.find("further corners 2; corner links 1"), std::string::npos)
      << graph.holes[0].note;
  EXPECT_EQ(oracle.interventions_by_kind().at("corner_named"), 2);
  EXPECT_EQ(oracle.interventions_by_kind().at("corner_link"), 1);
  const Evaluation e = evaluate(c, graph);
  EXPECT_EQ(metric(e, "missing_edge_present_fraction"), 1.0);
  EXPECT_EQ(metric(e, "patch_self_intersections_count"), 0.0);
  EXPECT_LT(metric(e, "hole_hausdorff_rel_diag"),
            metric(evaluate(c, paper), "hole_hausdorff_rel_diag"));
}

// Where the corner graph's sub-holes cannot be stitched (a turbine corner hole, measured:
// "a patch triangle could not be stitched (non-manifold)"), the hole is filled again with
// the paper's features alone, before any stand-in: the hole is closed by the method and
// its record names no fallback.
TEST(CrestFeatureCornerGraph, GraphThatCannotBeStitchedIsLeftOutBeforeAnyStandIn) {
  const Case c = generators::make_case("cad/turbine/corner_ccrr/small");
  harness::OracleUser oracle(c);
  const MethodResult result = CrestFeatureMethod().run(c.input, {}, oracle);
  bool left_out = false;
  for (const auto& hole : result.holes) {
    EXPECT_TRUE(hole.closed) << hole.note;
    if (hole.note.find("corner graph left out") != std::string::npos) {
      left_out = true;
      EXPECT_EQ(hole.fallback, "") << hole.note;
    }
  }
  EXPECT_TRUE(left_out);
}

}  // namespace
}  // namespace holebench
