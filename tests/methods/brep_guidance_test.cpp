#include "methods/brep_guidance/brep_guidance.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"
#include "core/plane_fit.h"
#include "generators/case_catalog.h"
#include "methods/brep_guidance/brep_faces.h"
#include "methods/brep_guidance/exact_closing.h"
#include "methods/brep_guidance/hole_classification.h"
#include "methods/brep_guidance/hole_detection.h"
#include "methods/common/patch_intersections.h"
#include "methods/registry.h"
#include "metrics/embree/triangle_scene.h"
#include "tests/core/occt/test_parts.h"
#include "tests/methods/method_invariants.h"
#include "tests/test_meshes.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

namespace holebench {
namespace {

std::vector<generators::CaseDescriptor> brep_cases() {
  generators::CatalogOptions options;
  options.include_cad = false;
  std::vector<generators::CaseDescriptor> cases;
  const generators::CaseCatalog catalog(options);
  for (const auto& c : catalog.cases()) {
    if (c.family == "brep")
      cases.push_back(c);
  }
  return cases;
}

MethodResult run_on(const Case& c, const BrepGuidanceOptions& options = {}) {
  NoUser user;
  MethodParameters parameters;
  parameters.structure_size = c.parameters.structure_size;
  return BrepGuidanceMethod(options).run(c.input, parameters, user);
}

// The method's hole for a ground-truth hole: the generators' convention (docs/cases.md) is
// that holes[i] describes the input's i-th boundary loop; the report whose centroid is
// nearest that loop's centroid is the method's view of it.
const HoleReport* report_for(const Case& c, const MethodResult& result, const HoleTruth& truth) {
  const auto loops = find_boundary_loops(c.input);
  const std::size_t index = static_cast<std::size_t>(&truth - c.holes.data());
  if (loops.size() != c.holes.size() || index >= loops.size())
    return nullptr;
  const Point centre = loop_centroid(c.input, loops[index]);
  const HoleReport* best = nullptr;
  double best_distance = 1e300;
  for (const auto& report : result.holes) {
    const double d = (report.centroid - centre).norm();
    if (d < best_distance) {
      best_distance = d;
      best = &report;
    }
  }
  return best;
}

// Rotates `values` so that `regions` starts like `reference` (both cyclic sequences).
template <typename T>
bool align(const std::vector<int>& regions, const std::vector<int>& reference,
           std::vector<T>& values) {
  const std::size_t k = regions.size();
  for (std::size_t shift = 0; shift < k; ++shift) {
    bool same = true;
    for (std::size_t i = 0; i < k && same; ++i)
      same = regions[(i + shift) % k] == reference[i];
    if (!same)
      continue;
    if (!values.empty())
      std::rotate(values.begin(), values.begin() + shift, values.end());
    return true;
  }
  return false;
}

TEST(BrepGuidance, ClassificationEqualsTheLabelsOnEverySyntheticCase) {
  for (const auto& descriptor : brep_cases()) {
    SCOPED_TRACE(descriptor.id);
    const Case c = generators::make_case(descriptor.id);
    const MethodResult result = run_on(c);
    ASSERT_EQ(result.holes.size(), c.holes.size());
    for (const auto& truth : c.holes) {
      if (!truth.labels || !truth.labels->known_weak_spot.empty())
        continue;
      const HoleLabels& expected = *truth.labels;
      const HoleReport* report = report_for(c, result, truth);
      ASSERT_NE(report, nullptr);
      ASSERT_TRUE(report->classification.has_value());
      HoleLabels got = *report->classification;
      EXPECT_EQ(got.k, expected.k);
      if (got.k != expected.k)
        continue;
      std::vector<int> regions = got.regions;
      auto transitions = got.transitions;
      auto kinds = got.boundary_kinds;
      ASSERT_TRUE(align(regions, expected.regions, transitions)) << "region order differs";
      align(got.regions, expected.regions, kinds);
      EXPECT_EQ(transitions, expected.transitions);
      if (expected.orientation_known && got.orientation_known) {
        EXPECT_EQ(to_string(got.orientation), std::string(to_string(expected.orientation)));
      }
      if (expected.orientation == Orientation::Outer && got.orientation == Orientation::Outer &&
          got.orientation_known) {
        EXPECT_EQ(kinds, expected.boundary_kinds);
      }
      EXPECT_EQ(to_string(got.expected_decision),
                std::string(to_string(expected.expected_decision)));
    }
  }
}

// The faces: the input's B-Rep face ids where it carries them (the paper's input), and the
// variant brep_guidance_segmented, run by name only, segments even then. On a clean planar
// B-Rep case both read the same k and the same decision.
TEST(BrepGuidance, TheSegmentedVariantSegmentsEvenWhereTheInputCarriesFaces) {
  const Case c = generators::make_case("brep/k2/inner/convex/small");
  for (auto f : c.input.faces())
    ASSERT_NE(region(c.input, f), kNoRegion);
  const auto segmented = make_method("brep_guidance_segmented");
  EXPECT_EQ(segmented->id(), "brep_guidance_segmented");
  for (const auto& method : make_all_methods())
    EXPECT_NE(method->id(), "brep_guidance_segmented") << "run by name only";
  NoUser user;
  MethodParameters parameters;
  parameters.structure_size = c.parameters.structure_size;
  const MethodResult exact = run_on(c);
  const MethodResult by_segmentation = segmented->run(c.input, parameters, user);
  auto phase_names = [](const MethodResult& result) {
    std::set<std::string> names;
    for (const auto& phase : result.phases)
      names.insert(phase.phase);
    return names;
  };
  EXPECT_TRUE(phase_names(exact).count("faces (input regions)"));
  EXPECT_TRUE(phase_names(by_segmentation).count("faces (planar segmentation)"));
  ASSERT_EQ(exact.holes.size(), 1u);
  ASSERT_EQ(by_segmentation.holes.size(), 1u);
  ASSERT_TRUE(exact.holes[0].classification && by_segmentation.holes[0].classification);
  EXPECT_EQ(exact.holes[0].classification->k, c.holes[0].labels->k);
  EXPECT_EQ(by_segmentation.holes[0].classification->k, c.holes[0].labels->k);
  EXPECT_EQ(to_string(by_segmentation.holes[0].classification->expected_decision),
            std::string(to_string(exact.holes[0].classification->expected_decision)));
}

// Exactness (section 3.3): closing an inner k <= 3 hole below delta_s on clean input gives
// back the complete model. Checked independently of the method's own geometry: every new
// vertex and every new triangle's centroid and edge midpoints lie on the complete model
// (distance <= 1e-9 of the diagonal), the patch's area equals the removed faces' area, the
// mesh is closed, and every removed vertex of the complete model (the lost corner among
// them) lies on the repaired mesh.
TEST(BrepGuidance, ExactClosingReproducesTheCompleteModel) {
  int closed_cases = 0;
  for (const auto& descriptor : brep_cases()) {
    const Case c = generators::make_case(descriptor.id);
    if (c.holes.size() != 1 || !c.holes[0].labels)
      continue;
    const HoleLabels& labels = *c.holes[0].labels;
    if (labels.expected_decision != Decision::CloseAutomatically)
      continue;
    SCOPED_TRACE(descriptor.id);
    const MethodResult result = run_on(c);
    ASSERT_EQ(result.holes.size(), 1u);
    ASSERT_TRUE(result.holes[0].closed) << result.holes[0].note;
    EXPECT_TRUE(find_boundary_loops(result.repaired).empty());
    const double diagonal = bounding_box_diagonal(c.complete);
    const double tolerance = 1e-9 * diagonal;
    const embree::TriangleScene complete(c.complete);
    const embree::TriangleScene repaired(result.repaired);
    double patch_area = 0.0;
    for (auto f : result.repaired.faces()) {
      if (!is_new(result.repaired, f))
        continue;
      patch_area += face_area(result.repaired, f);
      std::vector<Point> corners;
      for (auto v : result.repaired.fv_range(f))
        corners.push_back(result.repaired.point(v));
      std::vector<Point> probes = corners;
      probes.push_back((corners[0] + corners[1] + corners[2]) / 3.0);
      for (int e = 0; e < 3; ++e)
        probes.push_back((corners[e] + corners[(e + 1) % 3]) * 0.5);
      for (const Point& p : probes)
        EXPECT_LE(complete.closest_point(p).distance, tolerance);
    }
    double removed_area = 0.0;
    for (int f : c.holes[0].removed_faces) {
      const FaceHandle face = c.complete.face_handle(f);
      removed_area += face_area(c.complete, face);
      for (auto v : c.complete.fv_range(face)) {
        EXPECT_LE(repaired.closest_point(c.complete.point(v)).distance, tolerance);
      }
    }
    EXPECT_NEAR(patch_area, removed_area, 1e-9 * removed_area);
    ++closed_cases;
  }
  EXPECT_EQ(closed_cases, 7);  // k1; k2 convex, reflex; k3 ccc, ccr, crr, rrr (all small inner)
}

// Equations 3-5 on examples computed by hand.
TEST(BrepGuidance, ArrowsFollowEquationsThreeToFive) {
  auto arrow_of = [](const std::string& id) {
    const Case c = generators::make_case(id);
    const MethodResult result = run_on(c);
    EXPECT_EQ(result.holes.size(), 1u);
    EXPECT_TRUE(result.holes[0].arrow.has_value()) << id;
    return std::make_pair(c, *result.holes[0].arrow);
  };
  auto expect_direction = [](const Point& got, const Point& expected) {
    const Point unit = expected / expected.norm();
    EXPECT_NEAR((got - unit).norm(), 0.0, 1e-9) << got << " vs " << unit;
  };
  // Equation 3, k = 1: the hole is in the box's +z face (n = (0,0,1)): r = -(0,0,1), and
  // P = Ps - d r lies d above the hole's centroid.
  {
    const auto [c, arrow] = arrow_of("brep/k1/inner/large");
    expect_direction(arrow.direction, Point(0, 0, -1));
    const double d = 0.3 * bounding_box_diagonal(c.input);
    Point centroid(0, 0, 0);
    int n = 0;
    for (auto h : c.input.halfedges()) {
      if (!c.input.is_boundary(h))
        continue;
      centroid += c.input.point(c.input.from_vertex_handle(h));
      ++n;
    }
    centroid /= n;
    EXPECT_NEAR((arrow.position - (centroid + Point(0, 0, d))).norm(), 0.0, 1e-9 * d);
  }
  // Equation 3, k = 3 at the box's corner where +x, +y, +z meet: r = -(1,1,1)/sqrt(3).
  expect_direction(arrow_of("brep/k3/inner/convex-convex-convex/large").second.direction,
                   Point(-1, -1, -1));
  // Equation 5, the apex of a regular pyramid standing on z = 0 with its apex up: by
  // symmetry the fan's normals sum along z, and r = -(sum of Delta_i) looks down, (0,0,-1).
  for (const char* id :
       {"brep/k4/pyramid-apex/large", "brep/k5/pyramid-apex/large", "brep/k6/pyramid-apex/large"}) {
    SCOPED_TRACE(id);
    expect_direction(arrow_of(id).second.direction, Point(0, 0, -1));
  }
}

// Equation 4 on outer holes, from the case's own planes: r = sum a_i n_i, normalised, with
// a_i = +1 for a face whose inner boundary holds the loop and -1 for an outer boundary.
TEST(BrepGuidance, OuterHoleArrowsWeighNormalsByBoundaryKind) {
  int checked = 0;
  for (const auto& descriptor : brep_cases()) {
    const Case c = generators::make_case(descriptor.id);
    if (c.holes.size() != 1 || !c.holes[0].labels)
      continue;
    const HoleLabels& labels = *c.holes[0].labels;
    if (labels.orientation != Orientation::Outer || labels.k > 3 || labels.linearly_dependent_faces)
      continue;
    SCOPED_TRACE(descriptor.id);
    const MethodResult result = run_on(c);
    ASSERT_TRUE(result.holes[0].arrow.has_value());
    // The region normals from the complete model's faces (exact: the faces are planar).
    Point expected(0, 0, 0);
    for (std::size_t i = 0; i < labels.regions.size(); ++i) {
      for (auto f : c.complete.faces()) {
        if (region(c.complete, f) != labels.regions[i])
          continue;
        expected += face_normal(c.complete, f) *
                    (labels.boundary_kinds[i] == BoundaryKind::Inner ? 1.0 : -1.0);
        break;
      }
    }
    if (expected.norm() < 1e-9)
      continue;  // the normals cancel: equation 5 takes over
    expected /= expected.norm();
    EXPECT_NEAR((result.holes[0].arrow->direction - expected).norm(), 0.0, 1e-9);
    ++checked;
  }
  EXPECT_GT(checked, 10);
}

// The user step (cases a and b): with no user every closable hole is closed; an oracle that
// knows a hole should not be closed refuses, and the method guides instead.
TEST(BrepGuidance, NoUserAgreesAndTheRecordCountsRefusals) {
  const Case c = generators::make_case("brep/k2/inner/convex/small");
  NoUser agreeing;
  MethodParameters parameters;
  parameters.structure_size = c.parameters.structure_size;
  const MethodResult closed = BrepGuidanceMethod().run(c.input, parameters, agreeing);
  EXPECT_TRUE(closed.holes[0].closed);
  EXPECT_EQ(agreeing.interventions(), 0);

  struct Refusing final : User {
    std::string kind() const override { return "refusing"; }
    bool agree_to_closing(const ClosingProposal&) override {
      count_intervention();
      return false;
    }
  } refusing;
  const MethodResult guided = BrepGuidanceMethod().run(c.input, parameters, refusing);
  EXPECT_FALSE(guided.holes[0].closed);
  EXPECT_TRUE(guided.holes[0].arrow.has_value());
  EXPECT_EQ(refusing.interventions(), 1);
  EXPECT_EQ(count_new_faces(guided.repaired), 0u);
  // Both are the paper's path (cases a and b): no fallback.
  EXPECT_EQ(closed.holes[0].fallback, "");
  EXPECT_EQ(guided.holes[0].fallback, "");
}

// A k = 3 hole whose loop passes through the corner itself: on the faceted cylinder's rim
// the hole leaves one facet's edge along the common line of two facets and S is a loop
// vertex. That vertex is v_s, the facet whose run lies on its two common lines has nothing to
// fill, and the hole closes (under noise the segmentation may see k = 2; it closes too).
TEST(BrepGuidance, ACornerOnTheLoopIsTheNewCorner) {
  for (double noise : {0.0, 5.0, 25.0}) {
    SCOPED_TRACE(noise);
    const Case c = generators::make_case("solid/cylinder/edge_convex/small", 0, noise);
    const MethodResult result = run_on(c);
    ASSERT_EQ(result.holes.size(), 1u);
    if (noise == 0.0)
      ASSERT_EQ(result.holes[0].classification->k, 3);  // under noise the facets may merge
    EXPECT_TRUE(result.holes[0].closed) << result.holes[0].note;
    EXPECT_TRUE(find_boundary_loops(result.repaired).empty());
  }
}

// A hole the paper closes (case a) whose exact closing fails is guided instead, and its
// report names that stand-in and the reason. The failure is made by hand: one loop vertex of
// the k = 1 hole in the box's top face is moved, in the face's plane, past the far side of
// the hole, so the loop intersects itself in its plane and no planar polygon closes it; delta_s
// is the whole diagonal, so the decision stays "close".
TEST(BrepGuidance, FailedExactClosingIsAGuidanceFallback) {
  const Case c = generators::make_case("brep/k1/inner/small");
  Mesh input = c.input;
  const auto loops = find_boundary_loops(input);
  ASSERT_EQ(loops.size(), 1u);
  const Point centre = loop_centroid(input, loops[0]);
  const VertexHandle moved = input.from_vertex_handle(loops[0].halfedges[0]);
  input.point(moved) = centre + (centre - input.point(moved)) * 1.5;
  NoUser user;
  MethodParameters parameters;
  parameters.structure_size = bounding_box_diagonal(input);
  const MethodResult result = BrepGuidanceMethod().run(input, parameters, user);
  EXPECT_EQ(result.status, MethodStatus::Partial);
  ASSERT_EQ(result.holes.size(), 1u);
  const HoleReport& hole = result.holes[0];
  ASSERT_TRUE(hole.classification.has_value());
  EXPECT_EQ(hole.classification->expected_decision, Decision::CloseAutomatically);
  EXPECT_FALSE(hole.closed);
  EXPECT_TRUE(hole.arrow.has_value());
  EXPECT_NE(hole.note.find("exact closing failed"), std::string::npos) << hole.note;
  EXPECT_NE(hole.note.find("intersects itself"), std::string::npos) << hole.note;
  EXPECT_EQ(hole.fallback, "guided_instead_of_closed");
  EXPECT_EQ(count_new_faces(result.repaired), 0u);
}

// The holes guided by the paper's own decision (case c) have no fallback.
TEST(BrepGuidance, HolesGuidedByTheDecisionHaveNoFallback) {
  const Case c =
      generators::make_case("brep/k3/outer/convex-convex-reflex/inner-inner-outer/small");
  const MethodResult result = run_on(c);
  EXPECT_EQ(result.status, MethodStatus::Ok);
  for (const auto& hole : result.holes) {
    ASSERT_TRUE(hole.classification.has_value());
    EXPECT_EQ(hole.classification->expected_decision, Decision::Guide);
    EXPECT_EQ(hole.fallback, "") << hole.note;
  }
}

// The paper's weak spots (section 4): "If the half edges of the hole lie in more than one
// inner boundary, the resulting user guidance is not very helpful ... The same problem occurs
// with models in which one face is twisted around another." Both come from reading a face's
// side of the other face's plane from its hole half-edges, which near such a transition run
// along the other face's boundary or on the far side of the common line. Figure 3 reads the
// side from the transition half-edges h_i, h_j instead (each face lies to its left), which
// follow the faces' shared edge whatever the hole does around it; on clean input the weak-spot
// holes are then read right: k, every convexity and the orientation. See docs/methods.md.
TEST(BrepGuidance, WeakSpotsAreReadRightFromTheTransitionHalfEdges) {
  int checked = 0;
  for (const auto& descriptor : brep_cases()) {
    const Case c = generators::make_case(descriptor.id);
    const MethodResult result = run_on(c);
    for (const auto& truth : c.holes) {
      if (!truth.labels || truth.labels->known_weak_spot.empty())
        continue;
      SCOPED_TRACE(descriptor.id);
      const HoleReport* report = report_for(c, result, truth);
      ASSERT_NE(report, nullptr);
      ASSERT_TRUE(report->classification.has_value());
      const HoleLabels& got = *report->classification;
      EXPECT_EQ(got.k, truth.labels->k);
      std::vector<int> regions = got.regions;
      auto transitions = got.transitions;
      ASSERT_TRUE(align(regions, truth.labels->regions, transitions));
      EXPECT_EQ(transitions, truth.labels->transitions);
      EXPECT_EQ(got.orientation, truth.labels->orientation);
      ++checked;
    }
  }
  EXPECT_GE(checked, 22);  // the twisted face, the multiple-inner-boundary cases, 2 sizes each
}

// The earlier reading of figure 3, kept as an option: on the twisted face it reads both
// convexities reversed and, through equation 1, calls the outer hole inner (the weak spot as
// the paper describes it).
TEST(BrepGuidance, TheNearestHoleVerticesRuleMisreadsTheTwistedFace) {
  const Case c = generators::make_case("brep/weak/twisted-face/large");
  BrepGuidanceOptions options;
  options.figure_3_rule = brep_guidance::Figure3Rule::NearestHoleVertices;
  NoUser user;
  MethodParameters parameters;
  parameters.structure_size = c.parameters.structure_size;
  const MethodResult result = BrepGuidanceMethod(options).run(c.input, parameters, user);
  int checked = 0;
  for (const auto& truth : c.holes) {
    if (!truth.labels || truth.labels->known_weak_spot != "twisted_face")
      continue;
    const HoleReport* report = report_for(c, result, truth);
    ASSERT_NE(report, nullptr);
    std::vector<int> regions = report->classification->regions;
    auto transitions = report->classification->transitions;
    ASSERT_TRUE(align(regions, truth.labels->regions, transitions));
    EXPECT_NE(transitions, truth.labels->transitions);
    EXPECT_EQ(report->classification->orientation, Orientation::Inner);
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

// Figure 3 built by hand. Face f_i lies in the plane z = 0 with n_i = (0,0,1), face f_j in
// the plane x = 0 with n_j = (1,0,0); they meet along the y axis through T = 0. pi has the
// normal n_i x n_j = (0,1,0): projecting onto it drops y, so g_i is the x axis and g_j the z
// axis of pi. A face lies to the left of its transition half-edge: n_i x (0,1,0) = (-1,0,0),
// so h_i = +y puts f_i on x < 0 (below g_j) and h_i = -y on x > 0 (above); n_j x (0,1,0) =
// (0,0,1), so h_j = +y puts f_j on z > 0 (above g_i) and h_j = -y on z < 0 (below).
TEST(BrepGuidanceFigure3, TheFourCasesAndTheOverlaps) {
  using brep_guidance::figure_3;
  const Point T(0, 0, 0), n_i(0, 0, 1), n_j(1, 0, 0), up(0, 1, 0), down(0, -1, 0);
  // (a) twins h_i = +y, h_j = -y: f_i on x < 0, f_j on z < 0, the convex edge of a box whose
  // top is f_i and whose +x side is f_j.
  {
    const auto f = figure_3(T, n_i, n_j, up, down, {Point(-1, 0.5, 0)}, {Point(0, 0.5, -1)});
    EXPECT_EQ(f.convexity, Convexity::Convex);
    EXPECT_FALSE(f.decided_by_overlap);
    EXPECT_EQ(f.side_i, -1);
    EXPECT_EQ(f.side_j, -1);
  }
  // (b) twins h_i = -y, h_j = +y: f_i on x > 0, f_j on z > 0, a floor and the wall it meets:
  // reflex.
  {
    const auto f = figure_3(T, n_i, n_j, down, up, {Point(1, 0.5, 0)}, {Point(0, 0.5, 1)});
    EXPECT_EQ(f.convexity, Convexity::Reflex);
    EXPECT_FALSE(f.decided_by_overlap);
    EXPECT_EQ(f.side_i, 1);
    EXPECT_EQ(f.side_j, 1);
  }
  // (c) h_i = h_j = +y (not twins): f_i below g_j, f_j above g_i, undefined. a_i = 2 (two
  // half-edges of projected lengths 1 and 1 at x < 0), a_j = 0.5 (at z > 0): f_i decides,
  // convex.
  {
    const auto f =
        figure_3(T, n_i, n_j, up, up, {Point(-1, 0.2, 0), Point(-2, 0.4, 0)}, {Point(0, 0.5, 0.5)});
    EXPECT_TRUE(f.decided_by_overlap);
    EXPECT_EQ(f.side_i, -1);
    EXPECT_EQ(f.side_j, 1);
    EXPECT_NEAR(f.a_i, 2.0, 1e-15);
    EXPECT_NEAR(f.a_j, 0.5, 1e-15);
    EXPECT_EQ(f.convexity, Convexity::Convex);
  }
  // (d) h_i = h_j = -y: f_i above g_j, f_j below g_i, undefined. a_i = 3, a_j = 1: f_i
  // decides, reflex.
  {
    const auto f = figure_3(T, n_i, n_j, down, down, {Point(3, 0.1, 0)}, {Point(0, 0.2, -1)});
    EXPECT_TRUE(f.decided_by_overlap);
    EXPECT_EQ(f.side_i, 1);
    EXPECT_EQ(f.side_j, -1);
    EXPECT_NEAR(f.a_i, 3.0, 1e-15);
    EXPECT_NEAR(f.a_j, 1.0, 1e-15);
    EXPECT_EQ(f.convexity, Convexity::Reflex);
  }
  // The same undefined cases with the other face's overlap larger: f_j decides.
  EXPECT_EQ(figure_3(T, n_i, n_j, up, up, {Point(-0.5, 0, 0)}, {Point(0, 0, 2)}).convexity,
            Convexity::Reflex);
  EXPECT_EQ(figure_3(T, n_i, n_j, down, down, {Point(0.5, 0, 0)}, {Point(0, 0, -2)}).convexity,
            Convexity::Convex);
  // Overlaps: a hole half-edge along the common line projects onto T and adds nothing; a
  // projected half-edge that crosses g_j counts for its part beyond it: T -> (-3,0) is 3,
  // (-3,0) -> (1,0) has 3 of its 4 at x < 0, (1,0) -> (-1,0) 1 of its 2: a_i = 7.
  {
    const auto f =
        figure_3(T, n_i, n_j, up, up, {Point(0, 1, 0), Point(-1, 1, 0)}, {Point(0, 0, 1)});
    EXPECT_NEAR(f.a_i, 1.0, 1e-15);
    const auto g = figure_3(T, n_i, n_j, up, up, {Point(-3, 0, 0), Point(1, 0, 0), Point(-1, 0, 0)},
                            {Point(0, 0, 5)});
    EXPECT_NEAR(g.a_i, 7.0, 1e-12);
    EXPECT_NEAR(g.a_j, 5.0, 1e-12);
    EXPECT_EQ(g.convexity, Convexity::Convex);
  }
}

// The B-Rep edit under noise (section 3.3): the planes are the faces' least-squares planes
// (recomputed here from the noisy input's region ids, as the method does); every new vertex
// of a k = 2 closing lies on both planes, the rebuilt edge; a k = 3 closing has a new vertex
// at S, the three planes' intersection, and every other new vertex on two of the planes.
TEST(BrepGuidance, ExactClosingRebuildsTheEdgeAndTheCornerOnTheFittedPlanes) {
  for (double noise : {0.0, 5.0, 25.0}) {
    for (const char* id :
         {"brep/k2/inner/convex/small", "brep/k2/inner/reflex/small",
          "brep/k3/inner/convex-convex-convex/small", "brep/k3/inner/convex-reflex-reflex/small"}) {
      SCOPED_TRACE(std::string(id) + " at " + std::to_string(noise) + " %");
      const Case c = generators::make_case(id, 0, noise);
      const MethodResult result = run_on(c);
      ASSERT_EQ(result.holes.size(), 1u);
      ASSERT_TRUE(result.holes[0].closed) << result.holes[0].note;
      EXPECT_TRUE(find_boundary_loops(result.repaired).empty());
      const auto& labels = *result.holes[0].classification;
      const auto planes = fit_region_planes(c.input);
      const double tolerance = 1e-9 * bounding_box_diagonal(c.input);
      std::vector<Plane> involved;
      for (int r : labels.regions)
        involved.push_back(planes[r].plane);
      std::optional<Point> S;
      if (labels.k == 3) {
        Eigen::Matrix3d a;
        Eigen::Vector3d b;
        for (int r = 0; r < 3; ++r) {
          a.row(r) << involved[r].normal[0], involved[r].normal[1], involved[r].normal[2];
          b[r] = OpenMesh::dot(involved[r].normal, involved[r].point);
        }
        const Eigen::Vector3d x = a.partialPivLu().solve(b);
        S = Point(x[0], x[1], x[2]);
      }
      int new_vertices = 0, at_S = 0;
      for (auto v : result.repaired.vertices()) {
        if (!is_new(result.repaired, v))
          continue;
        ++new_vertices;
        const Point& p = result.repaired.point(v);
        int on = 0;
        for (const Plane& plane : involved)
          on += std::abs(plane.signed_distance(p)) <= tolerance;
        EXPECT_GE(on, 2) << p;
        if (S && (p - *S).norm() <= tolerance)
          ++at_S;
      }
      if (noise > 0.0)
        EXPECT_GT(new_vertices, 0);  // at least the rebuilt edge's ends Q_i
      if (S)
        EXPECT_EQ(at_S, 1);
    }
  }
}

// A k = 2 hole whose loop touches the faces' common line between the rebuilt edge's ends, made
// by hand: an L-shaped sheet (face 0 in z = 0, y >= 0; face 1 in y = 0, z <= 0; unit grid
// cells, each split into two triangles) folded along the x axis. The hole removes face 1's
// cells x in [2, 7], z in [-1, 0] and face 0's cells x in [2, 4] and [5, 7], y in [0, 1]: face
// 0 keeps the cell x in [4, 5] on the fold, so the loop runs along the fold from (4, 0, 0) to
// (5, 0, 0) between the transitions (2, 0, 0) and (7, 0, 0). Face 0's part (two lobes joined by
// that stretch, closed by the rebuilt edge from x = 7 back to x = 2) overlaps itself along the
// stretch, and its new points at x = 4 and 5 coincide with the loop's vertices there: the
// Delaunay triangulation of the part failed ("two points of the polygon project onto the same
// point") and the hole was guided. Those loop vertices are now the rebuilt edge's corners, the
// part splits there into its two lobes, and the closing is the complete sheet: every new face in
// its face's plane, every new vertex on the fold, the patch's area the removed 9 cells.
TEST(BrepGuidanceExactClosing, ALoopTouchingTheCommonLineIsSplitThere) {
  Mesh mesh;
  auto point = [](int x, int s) { return s >= 0 ? Point(x, s, 0) : Point(x, 0, s); };
  std::vector<std::vector<VertexHandle>> grid(10, std::vector<VertexHandle>(9));
  for (int x = 0; x <= 9; ++x) {
    for (int s = -4; s <= 4; ++s)
      grid[x][s + 4] = mesh.add_vertex(point(x, s));
  }
  auto removed = [](int x, int s) {
    return (s == -1 && x >= 2 && x < 7) || (s == 0 && ((x >= 2 && x < 4) || (x >= 5 && x < 7)));
  };
  for (int x = 0; x < 9; ++x) {
    for (int s = -4; s < 4; ++s) {
      if (removed(x, s))
        continue;
      const VertexHandle a = grid[x][s + 4], b = grid[x + 1][s + 4], c = grid[x + 1][s + 5],
                         d = grid[x][s + 5];
      for (const FaceHandle f : {mesh.add_face(a, b, c), mesh.add_face(a, c, d)}) {
        ASSERT_TRUE(f.is_valid());
        set_region(mesh, f, s >= 0 ? 0 : 1);
      }
    }
  }
  mark_all_original(mesh);
  const brep_guidance::BrepFaces faces = brep_guidance::extract_brep_faces(mesh);
  ASSERT_TRUE(faces.from_input);
  const auto holes = brep_guidance::detect_holes(mesh, faces);
  const auto hole = std::find_if(holes.begin(), holes.end(), [](const auto& h) {
    return h.k() == 2 && h.halfedges.size() < 30;  // not the sheet's border
  });
  ASSERT_NE(hole, holes.end());
  // The split is one of the later attempts (brep_guidance_plus).
  const auto closing = brep_guidance::close_hole_exactly(mesh, faces, *hole, true);
  ASSERT_TRUE(closing.closed) << closing.error;
  EXPECT_NE(closing.note.find("loop vertices on the rebuilt edges"), std::string::npos)
      << closing.note;
  EXPECT_EQ(find_boundary_loops(mesh).size(), 1u);  // the sheet's border only
  double area = 0.0;
  for (auto f : mesh.faces()) {
    if (!is_new(mesh, f))
      continue;
    area += face_area(mesh, f);
    for (auto v : mesh.fv_range(f)) {
      const Point& p = mesh.point(v);
      // Region 0 is the plane z = 0, region 1 the plane y = 0.
      EXPECT_LE(std::abs(region(mesh, f) == 0 ? p[2] : p[1]), 1e-9) << p;
    }
  }
  EXPECT_NEAR(area, 9.0, 1e-9);  // the 9 removed unit cells
  for (auto v : mesh.vertices()) {
    if (!is_new(mesh, v))
      continue;
    const Point& p = mesh.point(v);
    EXPECT_LE(std::abs(p[1]) + std::abs(p[2]), 1e-9) << p;  // on the fold
  }
}

// The holes whose decision is "close" that the plan and the first attempts after it
// (loop vertices on the rebuilt edges, the loop's order) left open, guided instead (issue 17),
// each closed now by one of the later attempts (docs/methods.md, "Exact closing"):
// - cad/fandisk/edge_reflex/small at 0 %: k = 3, but face 3's part is one loop edge and the
//   three planes' corner S lies beyond it, outside the hole; the plan's rebuilt edges ran out
//   to S and crossed face 3's triangle there. Face 3's run goes to face 9 and the hole is
//   closed as k = 2 on the common line of faces 1 and 9.
// Two more cases, cad/turbine/corner_rrr/small at 5 % ("triangulated in its own least-squares
// plane") and cad/turbine/corner_crrrr/small at 25 % ("the loop closed as one part in its own
// least-squares plane"), were holes that cut a turbine blade through; since 2026-12-03 such
// holes are punched smaller, and no built-in case reaches those two attempts any more (all
// brep_guidance jobs of the nightly's cases at 0, 5 and 25 % measured). The second is tested
// on a generated B-Rep part below; the first has no case now.
// Each hole is closed without fallback, named in the note, the input's faces unchanged, no
// boundary left and no new face intersecting another or the mesh around it.
struct LaterAttemptCase {
  const char* id;
  double noise;
  const char* step;  ///< the words of the note that name the step
};

void PrintTo(const LaterAttemptCase& c, std::ostream* os) {
  *os << c.id << " at " << c.noise << " % noise";
}

class BrepGuidanceLaterClosingAttempts : public ::testing::TestWithParam<LaterAttemptCase> {};

// Every hole whose decision is "close" is closed without fallback, one hole's note names
// `step`, the input's faces are unchanged, no boundary is left and no new face intersects
// another or the mesh around it.
// The later attempts are the project's, in the variant brep_guidance_plus.
void expect_closed_by_a_later_attempt(const Case& c, const std::string& step) {
  const MethodResult result = run_on(c, BrepGuidanceMethod::plus());
  EXPECT_EQ(result.status, MethodStatus::Ok) << result.message;
  bool named = false;
  for (const auto& hole : result.holes) {
    ASSERT_TRUE(hole.classification.has_value());
    if (hole.classification->expected_decision != Decision::CloseAutomatically)
      continue;
    EXPECT_TRUE(hole.closed) << hole.note;
    EXPECT_EQ(hole.fallback, "") << hole.note;
    named = named || hole.note.find(step) != std::string::npos;
  }
  EXPECT_TRUE(named) << "no hole's note names \"" << step << "\"";
  test::expect_input_faces_unchanged(c.input, result.repaired);
  EXPECT_TRUE(find_boundary_loops(result.repaired).empty());
  std::vector<FaceHandle> patch;
  for (auto f : result.repaired.faces()) {
    if (is_new(result.repaired, f))
      patch.push_back(f);
  }
  ASSERT_FALSE(patch.empty());
  EXPECT_EQ(patch_intersections(result.repaired, patch), 0u);
}

TEST_P(BrepGuidanceLaterClosingAttempts, CloseTheHoleWithoutIntersections) {
  const LaterAttemptCase param = GetParam();
  expect_closed_by_a_later_attempt(generators::make_case(param.id, 0, param.noise), param.step);
}

// The generated plate with bosses (tests/core/occt/test_parts.h, written as STEP), its small
// reflex edge hole at 25 % noise: the loop is closed as one part in its own least-squares
// plane (measured 2026-12-03; no built-in case reaches that attempt).
TEST(BrepGuidanceLaterClosingAttempts, PlateWithBossesEdgeHoleClosedAsOnePart) {
  const auto dir = occt::test::fresh_temp_dir("brep_guidance_plate");
  for (const auto& part : occt::test::test_parts()) {
    if (part.name == "plate_with_bosses")
      occt::test::write_step(part.shape, dir / (part.name + ".step"));
  }
  generators::CatalogOptions options;
  options.include_cad = false;
  options.families = {"file"};
  options.user_meshes = {dir};
  const generators::CaseCatalog catalog(options);
  expect_closed_by_a_later_attempt(
      catalog.make("file/plate_with_bosses/edge_reflex/small", 0, 25.0),
      "the loop closed as one part in its own least-squares plane");
}

INSTANTIATE_TEST_SUITE_P(Issue17, BrepGuidanceLaterClosingAttempts,
                         ::testing::Values(LaterAttemptCase{
                             "cad/fandisk/edge_reflex/small", 0.0,
                             "face 3's run of 1 edge given to face 9, closed as k = 2"}),
                         [](const ::testing::TestParamInfo<LaterAttemptCase>& info) {
                           std::string name = info.param.id;
                           for (char& ch : name) {
                             if (ch == '/')
                               ch = '_';
                           }
                           return name + "_noise_" +
                                  std::to_string(static_cast<int>(info.param.noise));
                         });

}  // namespace
}  // namespace holebench

namespace holebench {
namespace {

// The two halves of a split face are one face of the B-Rep, named by the smaller id; a
// valley of 3 degrees keeps them two faces, and the other five faces keep their ids. Under
// vertex noise the default (exactly coplanar only) keeps them apart; a noise-tolerant ratio
// unites them.
TEST(BrepFaces, CoplanarNeighboursAreOneFaceAndABendIsNot) {
  const std::vector<int> united = {0, 1, 2, 3, 4, 5, 5}, apart = {0, 1, 2, 3, 4, 5, 6};
  const Mesh exact = test::box_with_split_top(0.0);
  EXPECT_EQ(brep_guidance::unite_coplanar_faces(exact, fit_region_planes(exact)), united);
  const Mesh noisy = test::displaced(exact, 0.002);
  EXPECT_EQ(brep_guidance::unite_coplanar_faces(noisy, fit_region_planes(noisy)), apart);
  brep_guidance::UniteCoplanarOptions tolerant;
  tolerant.residual_ratio = 1.25;
  EXPECT_EQ(brep_guidance::unite_coplanar_faces(noisy, fit_region_planes(noisy), tolerant), united);
  const Mesh bent = test::box_with_split_top(3.0);
  EXPECT_EQ(brep_guidance::unite_coplanar_faces(bent, fit_region_planes(bent)), apart);
  const brep_guidance::BrepFaces faces = brep_guidance::extract_brep_faces(exact);
  ASSERT_TRUE(faces.from_input);
  for (auto f : exact.faces()) {
    const int id = region(exact, f);
    EXPECT_EQ(faces.face_region[f.idx()], id == 6 ? 5 : id);
  }
  EXPECT_TRUE(faces.planes[5].valid);
  EXPECT_NEAR(std::abs(faces.planes[5].plane.normal[2]), 1.0, 1e-12);
}

}  // namespace
}  // namespace holebench
