// Sharp creases as crest lines (not in the crest-line paper; docs/crest_feature.md, "Sharp
// creases"), and where a crest line that reaches a hole gives its feature point (3.4.1).
#include "methods/crest_feature/crest_feature.h"
#include "methods/crest_feature/sharp_creases.h"

#include "generators/case_catalog.h"
#include "metrics/evaluation.h"
#include "tests/methods/metric_lookup.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace holebench {
namespace {

using namespace crest_feature;

using test::metric;

double angle_degrees(const Point& a, const Point& b) {
  const double c = OpenMesh::dot(a, b) / (a.norm() * b.norm());
  return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI;
}

// A square hole of side 2 with 8 boundary vertices, in loop order: (1,2) (0,2) (0,1) (0,0)
// (1,0) (2,0) (2,1) (2,2); mean edge length 1.
struct SquareHole {
  Mesh mesh;
  Hole hole;
};

SquareHole square_hole() {
  SquareHole s;
  const double xy[8][2] = {{1, 2}, {0, 2}, {0, 1}, {0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}};
  for (const auto& p : xy)
    s.hole.vertices.push_back(s.mesh.add_vertex(Point(p[0], p[1], 0)));
  s.hole.centroid = Point(1, 1, 0);
  s.hole.radius = std::sqrt(2.0);
  s.hole.average_edge_length = 1.0;
  return s;
}

// A straight crest line from `from` to `to` (its end), one point per unit length.
CrestLines one_line(const Point& from, const Point& to) {
  CrestLines crest;
  crest.mean_edge_length = 1.0;
  CrestLine line;
  const int n = static_cast<int>(std::lround((to - from).norm()));
  for (int k = 0; k <= n; ++k)
    line.points.push_back(from + (to - from) * (static_cast<double>(k) / n));
  line.mean_curvature = 1.0;
  crest.lines.push_back(line);
  return crest;
}

// A crest line that ends at a boundary vertex and runs straight on across the hole passes the
// crease's other end on a small hole, exactly so on a CAD mesh: the feature point is the first
// vertex along the line, its own end (here (1,0), after (1,2) in loop order).
TEST(CrestFeatureFeaturePoints, RayThroughBothEndsOfACreaseGivesTheNearerVertex) {
  const SquareHole s = square_hole();
  const HoleFeatures f = detect_feature_points(
      s.mesh, s.hole, one_line(Point(1, -5, 0), Point(1, 0, 0)), FeaturePointOptions{});
  ASSERT_EQ(f.points.size(), 1u);
  EXPECT_EQ(f.points[0].loop_index, 4);
}

// Where the hole's boundary follows the crease for some edges before the crease enters the
// hole (a line along y = 0 from the left reaches the boundary at (0,0), which then runs along
// it to (2,0)), the feature point is the last boundary vertex on the line: a feature line from
// the first would run along the boundary's own edges and fold the sub-hole beside it.
// So it is with the paper's boundary crossings (on_boundary_edges, the default) and with the
// nearest vertex (crest_feature_plus): the boundary's edges along the line hold no crossing.
TEST(CrestFeatureFeaturePoints, BoundaryAlongTheCreaseGivesTheVertexWhereItEntersTheHole) {
  const SquareHole s = square_hole();
  for (bool on_edges : {true, false}) {
    FeaturePointOptions options;
    options.on_boundary_edges = on_edges;
    const HoleFeatures f =
        detect_feature_points(s.mesh, s.hole, one_line(Point(-5, 0, 0), Point(0, 0, 0)), options);
    ASSERT_EQ(f.points.size(), 1u) << on_edges;
    EXPECT_EQ(f.points[0].loop_index, 5) << on_edges;
    EXPECT_FALSE(f.points[0].edge_parameter) << on_edges;
  }
}

// cad/joint/edge_convex/small: the jet-fitted ridges beside this convex crease reach the hole
// up to 47 degrees off it, so without a user the automatic rule (35 degrees) paired nothing
// and the crease was lost. The crease's own crest line gives both of its ends on the boundary,
// with the crease's direction, one pair, and the crease is restored exactly.
TEST(CrestFeatureSharpCreases, CrestLineOfACadCreaseIsTheCreaseItself) {
  const Case c = generators::make_case("cad/joint/edge_convex/small");
  ASSERT_EQ(c.holes.size(), 1u);
  ASSERT_EQ(c.holes[0].missing_edges.size(), 1u);
  const std::vector<Point>& crease = c.holes[0].missing_edges[0];
  const auto holes = identify_holes(c.input);
  ASSERT_EQ(holes.size(), 1u);
  const HoleFeatures f = detect_feature_points(c.input, holes[0], detect_crest_lines(c.input));
  ASSERT_EQ(f.points.size(), 2u);
  ASSERT_EQ(f.pairs.size(), 1u);
  for (const auto& p : f.points) {
    const double to_end =
        std::min((p.position - crease.front()).norm(), (p.position - crease.back()).norm());
    EXPECT_LT(to_end, 1e-9);
    EXPECT_LT(std::min(angle_degrees(p.tangent, crease.back() - crease.front()),
                       angle_degrees(p.tangent, crease.front() - crease.back())),
              1.0);
  }
  NoUser no_user;
  const MethodResult r = CrestFeatureMethod().run(c.input, {}, no_user);
  const Evaluation e = evaluate(c, r);
  EXPECT_EQ(metric(e, "missing_edge_present_fraction"), 1.0);
  EXPECT_LT(metric(e, "hole_hausdorff_rel_diag"), 1e-6);
}

// The fandisk's corner hole without a user: the three creases' own crest lines give the three
// true feature points (one where the crease leaves the boundary, which follows it for an
// edge), the automatic rule names the corner triple, every crease is restored and no patch
// face intersects another (a feature line from the first vertex on the crease ran along the
// boundary's edge and folded a sub-hole).
TEST(CrestFeatureSharpCreases, CornerHoleIsRestoredWithoutAUser) {
  const Case c = generators::make_case("crease/fandisk/3");
  ASSERT_EQ(c.holes.size(), 1u);
  const auto holes = identify_holes(c.input);
  ASSERT_EQ(holes.size(), 1u);
  const HoleFeatures f = detect_feature_points(c.input, holes[0], detect_crest_lines(c.input));
  ASSERT_EQ(f.points.size(), 3u);
  EXPECT_TRUE(f.corner);
  for (const auto& p : f.points) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& edge : c.holes[0].missing_edges)
      for (const Point& end : {edge.front(), edge.back()})
        nearest = std::min(nearest, (p.position - end).norm());
    EXPECT_LT(nearest, 1e-9);
  }
  NoUser no_user;
  const MethodResult r = CrestFeatureMethod().run(c.input, {}, no_user);
  ASSERT_EQ(r.holes.size(), 1u);
  EXPECT_EQ(r.holes[0].fallback, "") << r.holes[0].note;
  const Evaluation e = evaluate(c, r);
  EXPECT_EQ(metric(e, "missing_edge_present_fraction"), 1.0);
  EXPECT_EQ(metric(e, "patch_self_intersections_count"), 0.0);
}

// A crease's chain ends at the hole's boundary vertices, where the crease runs out into the
// hole (the fandisk's corner hole: three of them). Sharp creases can be turned off
// (sharp_crease_angle_degrees 180).
TEST(CrestFeatureSharpCreases, CreaseChainsRunOutAtTheHolesBoundary) {
  const Case c = generators::make_case("crease/fandisk/3");
  std::vector<char> everywhere(c.input.n_vertices(), 1);
  CrestLineOptions options;
  const std::vector<CrestLine> creases = trace_sharp_creases(c.input, everywhere, 1.0, options);
  ASSERT_FALSE(creases.empty());
  int at_boundary = 0;
  for (const auto& line : creases) {
    for (int end = 0; end < 2; ++end) {
      const Point p = end == 0 ? line.points.front() : line.points.back();
      for (auto v : c.input.vertices()) {
        if (c.input.is_boundary(v) && (c.input.point(v) - p).norm() == 0.0) {
          ++at_boundary;
          EXPECT_TRUE(line.runs_out[end]);
        }
      }
    }
  }
  EXPECT_GE(at_boundary, 3);
  options.sharp_crease_angle_degrees = 180.0;
  EXPECT_TRUE(trace_sharp_creases(c.input, everywhere, 1.0, options).empty());
}

}  // namespace
}  // namespace holebench
