// Tests of the crest-line paper's user step beyond pairing (section 3.4.2): the user's
// correction of a crest line near the hole, answered by the oracle from the ground truth.
#include "methods/crest_feature/boundary_edge_split.h"
#include "methods/crest_feature/crest_feature.h"
#include "methods/crest_feature/crest_line_correction.h"

#include "core/geometry.h"
#include "generators/case_catalog.h"

// The oracle user lives in the harness library (linked by methods_tests).
#include "harness/run/oracle_user.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace holebench {
namespace {

using namespace crest_feature;

double distance_to_polyline(const Point& p, const std::vector<Point>& polyline) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < polyline.size(); ++i) {
    const Point a = polyline[i], d = polyline[i + 1] - a;
    const double t = std::clamp(OpenMesh::dot(p - a, d) / OpenMesh::dot(d, d), 0.0, 1.0);
    best = std::min(best, (p - (a + d * t)).norm());
  }
  return best;
}

// The largest distance of a feature line's interpolated points from the true crease.
double worst_distance(const FeatureLines& lines, const std::vector<Point>& crease) {
  double worst = 0.0;
  for (const auto& line : lines.lines)
    for (const Point& p : line.interior)
      worst = std::max(worst, distance_to_polyline(p, crease));
  return worst;
}

int nearest_loop_index(const Mesh& mesh, const Hole& hole, const Point& p) {
  int best = 0;
  for (std::size_t i = 1; i < hole.vertices.size(); ++i)
    if ((mesh.point(hole.vertices[i]) - p).norm() < (mesh.point(hole.vertices[best]) - p).norm())
      best = static_cast<int>(i);
  return best;
}

double diagonal(const Mesh& mesh) {
  Point lo = mesh.point(*mesh.vertices_begin()), hi = lo;
  for (auto v : mesh.vertices()) {
    lo.minimize(mesh.point(v));
    hi.maximize(mesh.point(v));
  }
  return (hi - lo).norm();
}

// The hole of `id` (one hole, one missing sharp edge between two boundary vertices) with a
// feature line between the crease's two ends whose crest-line directions are deliberately
// wrong: each turned 30 degrees off the true crease, within the plane of the crease and the
// hole's centroid, so that the feature line bulges off the crease.
struct WrongCrestLine {
  Case c;
  Hole hole;
  HoleFeatures features;
  std::vector<Point> crease;
};

WrongCrestLine wrong_crest_line(const std::string& id) {
  WrongCrestLine w;
  w.c = generators::make_case(id);
  const auto holes = identify_holes(w.c.input);
  EXPECT_EQ(holes.size(), 1u);
  EXPECT_EQ(w.c.holes.size(), 1u);
  EXPECT_EQ(w.c.holes[0].missing_edges.size(), 1u);
  w.hole = holes.at(0);
  w.crease = w.c.holes.at(0).missing_edges.at(0);
  const Point ends[2] = {w.crease.front(), w.crease.back()};
  const Point side = OpenMesh::cross(ends[1] - ends[0], w.hole.centroid - ends[0]);
  for (int k = 0; k < 2; ++k) {
    FeaturePoint f;
    f.loop_index = nearest_loop_index(w.c.input, w.hole, ends[k]);
    f.position = ends[k];  // where the crease meets the boundary
    const Point along = (ends[1 - k] - ends[k]).normalized();
    const Point off = OpenMesh::cross(side, along).normalized();
    f.tangent = (along * std::cos(M_PI / 6) + off * std::sin(M_PI / 6)).normalized();
    f.crest_line = -1;
    w.features.points.push_back(f);
  }
  w.features.pairs.push_back({0, 1});
  return w;
}

// 3.4.2: an oracle correction of a deliberately wrong crest line restores the crease. The
// oracle replaces both wrong directions by the true crease's (two interventions of kind
// crest_line_direction), and the feature line then lies on the crease: on box/edge, whose
// crease is straight, exactly (Catmull-Rom through evenly spaced collinear points is the
// line; measured 1.7e-16 of the diagonal), with the wrong directions 5.3e-3 of the diagonal
// off; on the fandisk's one-crease hole, whose crease is curved and P0, P3 then lie on the
// corrected tangent lines, within 1e-3 of the diagonal (measured 9.0e-4; the issue's
// tolerance for a feature line on a circular crease), against 2.0e-3 off before.
TEST(CrestLineCorrection, OracleCorrectionOfAWrongCrestLineRestoresTheCrease) {
  struct Expected {
    std::string id;
    double wrong_at_least, right_below;  // relative to the diagonal
  };
  for (const Expected& e :
       {Expected{"box/edge", 5e-3, 1e-12}, Expected{"crease/fandisk/1", 1.5e-3, 1e-3}}) {
    const std::string& id = e.id;
    const WrongCrestLine w = wrong_crest_line(id);
    ASSERT_EQ(w.features.points.size(), 2u);
    const double diag = diagonal(w.c.complete);
    EXPECT_GT(worst_distance(interpolate_feature_lines(w.hole, w.features), w.crease),
              e.wrong_at_least * diag)
        << id;

    harness::OracleUser oracle(w.c);
    const CrestLineCorrection corrected =
        review_crest_lines(w.c.input, w.hole, 0, w.features, oracle);
    EXPECT_EQ(corrected.corrected, 2) << id;
    EXPECT_EQ(oracle.interventions(), 2) << id;
    ASSERT_EQ(oracle.interventions_by_kind().count("crest_line_direction"), 1u) << id;
    EXPECT_EQ(oracle.interventions_by_kind().at("crest_line_direction"), 2) << id;
    EXPECT_LT(worst_distance(interpolate_feature_lines(w.hole, corrected.features), w.crease),
              e.right_below * diag)
        << id;

    // A second review of the corrected lines changes nothing more.
    const CrestLineCorrection again =
        review_crest_lines(w.c.input, w.hole, 0, corrected.features, oracle);
    EXPECT_EQ(again.corrected, 0) << id;
    EXPECT_EQ(oracle.interventions(), 2) << id;
  }
}

// Without a user nothing is corrected and nothing is counted.
TEST(CrestLineCorrection, NoUserKeepsTheDetectedDirections) {
  const WrongCrestLine w = wrong_crest_line("box/edge");
  NoUser none;
  const CrestLineCorrection kept = review_crest_lines(w.c.input, w.hole, 0, w.features, none);
  EXPECT_EQ(kept.corrected, 0);
  EXPECT_EQ(none.interventions(), 0);
  EXPECT_TRUE(none.interventions_by_kind().empty());
  for (std::size_t i = 0; i < w.features.points.size(); ++i)
    EXPECT_EQ(kept.features.points[i].tangent, w.features.points[i].tangent);
}

// 3.4.1: a crest line crossing a boundary edge at a known point gives a feature point there.
// On the planar face around box/face_interior's hole, a straight crest line is laid on the
// face towards the hole so that its extension crosses the boundary edge k at 0.4 of its
// length (X). The detected feature point is X, inside that edge (parameter 0.4); inserting
// it splits the edge and its input face: X becomes a vertex of the hole's loop between the
// edge's ends, the two halves and X are patch (Provenance::New), and no input vertex moves.
TEST(FeaturePointsOnBoundaryEdges, CrestLineCrossingABoundaryEdgeGivesAFeaturePointThere) {
  const Case c = generators::make_case("box/face_interior");
  const auto holes = identify_holes(c.input);
  ASSERT_EQ(holes.size(), 1u);
  const Hole& hole = holes[0];
  const int n = static_cast<int>(hole.vertices.size());
  const double a = hole.average_edge_length;
  const int k = 0;
  const Point p = c.input.point(hole.vertices[k]), q = c.input.point(hole.vertices[(k + 1) % n]);
  const Point x = p + (q - p) * 0.4;
  const Point normal = face_normal(c.input, c.input.opposite_face_handle(hole.loop.halfedges[k]));
  Point into = hole.centroid - x;
  into -= normal * OpenMesh::dot(into, normal);
  into.normalize();
  CrestLines crest;
  CrestLine line;
  line.mean_curvature = 1.0;
  for (int m = 1; m <= 8; ++m)  // from near the boundary outwards, on the face
    line.points.push_back(x - into * (0.5 * a * m));
  crest.lines.push_back(line);

  const HoleFeatures features = detect_feature_points(c.input, hole, crest);  // the paper's
  ASSERT_EQ(features.points.size(), 1u);
  const FeaturePoint& f = features.points[0];
  EXPECT_EQ(f.loop_index, k);
  ASSERT_TRUE(f.edge_parameter);
  EXPECT_NEAR(*f.edge_parameter, 0.4, 1e-9);
  EXPECT_LT((f.position - x).norm(), 1e-9 * a);

  Mesh mesh = c.input;
  const InsertedFeaturePoints inserted = insert_feature_points(mesh, hole, features);
  EXPECT_EQ(inserted.inserted, 1);
  ASSERT_EQ(static_cast<int>(inserted.hole.vertices.size()), n + 1);
  const FeaturePoint& g = inserted.features.points[0];
  EXPECT_FALSE(g.edge_parameter);
  EXPECT_EQ(g.loop_index, k + 1);
  const VertexHandle v = inserted.hole.vertices[g.loop_index];
  EXPECT_EQ(mesh.point(v), f.position);
  EXPECT_TRUE(is_new(mesh, v));
  EXPECT_EQ(inserted.hole.vertices[k], hole.vertices[k]);
  EXPECT_EQ(inserted.hole.vertices[k + 2], hole.vertices[(k + 1) % n]);
  int new_faces = 0;
  for (auto face : mesh.faces())
    new_faces += is_new(mesh, face) ? 1 : 0;
  EXPECT_EQ(new_faces, 2);
  EXPECT_EQ(mesh.n_faces(), c.input.n_faces() + 1);
  for (auto u : c.input.vertices())
    EXPECT_EQ(mesh.point(u), c.input.point(u));  // bit for bit
  // The new loop is a boundary loop of the mesh, each halfedge the next of the one before.
  const auto& loop = inserted.hole.loop.halfedges;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    EXPECT_TRUE(mesh.is_boundary(loop[i]));
    EXPECT_EQ(mesh.next_halfedge_handle(loop[i]), loop[(i + 1) % loop.size()]);
  }

  // Off (crest_feature_plus): the boundary vertex nearest the ray, nothing to insert.
  FeaturePointOptions on_vertices;
  on_vertices.on_boundary_edges = false;
  const HoleFeatures snapped = detect_feature_points(c.input, hole, crest, on_vertices);
  ASSERT_EQ(snapped.points.size(), 1u);
  EXPECT_FALSE(snapped.points[0].edge_parameter);
  EXPECT_EQ(snapped.points[0].position, c.input.point(hole.vertices[snapped.points[0].loop_index]));
}

}  // namespace
}  // namespace holebench
