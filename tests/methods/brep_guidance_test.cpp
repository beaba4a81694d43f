#include "methods/brep_guidance/brep_guidance.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"
#include "generators/case_catalog.h"
#include "metrics/embree/triangle_scene.h"

#include <gtest/gtest.h>

#include <algorithm>

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

MethodResult run_on(const Case& c) {
  NoUser user;
  MethodParameters parameters;
  parameters.structure_size = c.parameters.structure_size;
  return BrepGuidanceMethod().run(c.input, parameters, user);
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

// A hole the paper closes (case a) whose exact closing fails is guided instead, and its
// report names that stand-in; the holes guided by the paper's own decision (case c) have no
// fallback. The case is one of the nightly baseline's "exact closing failed" holes: the first
// hole's closing triangle would make the mesh non-manifold.
TEST(BrepGuidance, FailedExactClosingIsAGuidanceFallback) {
  const Case c =
      generators::make_case("brep/k3/outer/convex-convex-reflex/inner-inner-outer/small");
  const MethodResult result = run_on(c);
  EXPECT_EQ(result.status, MethodStatus::Partial);
  std::size_t stood_in = 0, guided_by_decision = 0;
  for (const auto& hole : result.holes) {
    ASSERT_TRUE(hole.classification.has_value());
    if (hole.classification->expected_decision == Decision::CloseAutomatically) {
      EXPECT_FALSE(hole.closed);
      EXPECT_TRUE(hole.arrow.has_value());
      EXPECT_NE(hole.note.find("exact closing failed"), std::string::npos) << hole.note;
      EXPECT_EQ(hole.fallback, "guided_instead_of_closed");
      ++stood_in;
    } else {
      EXPECT_EQ(hole.fallback, "") << hole.note;
      ++guided_by_decision;
    }
  }
  EXPECT_EQ(stood_in, 1u);
  EXPECT_GT(guided_by_decision, 0u);
}

// The paper's weak spots (section 4): "If the half edges of the hole lie in more than one
// inner boundary, the resulting user guidance is not very helpful ... The same problem occurs
// with models in which one face is twisted around another."
//  - A face twisted around another meets it convex on one side of their common line and
//    reflex on the other; projected onto the plane pi (figure 3) the hole half-edges lie on
//    the wrong sides at both transitions, so the method reads both convexities reversed and,
//    through equation 1, calls the outer hole inner.
//  - A loop through several inner boundaries: near a transition the hole half-edges of one
//    face run along the other face's inner boundary, so figure 3 misjudges at least one
//    transition's convexity (and for k = 3, through equation 2, the orientation).
// The expected outcome pinned down here: k is right everywhere; the convexities or the
// orientation are wrong, except on the reflex inner-inner k = 2 hole (a bridge over an
// opening), which figure 3 and equation 1 happen to read right, and on the inner-inner-inner
// k = 3 holes (three thin frames through a corner): there both faces' hole half-edges leave
// the common line at right angles at every transition (the tongues' corners), so figure 3
// sees each face on its true side and equation 2 follows; only equation 4's direction (all
// a_i = +1) is left of the weak spot. See docs/methods.md.
TEST(BrepGuidance, WeakSpotsAreMisreadAsTheDocsSay) {
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
      align(regions, truth.labels->regions, transitions);
      const bool convexity_wrong = transitions != truth.labels->transitions;
      const bool orientation_wrong = got.orientation != truth.labels->orientation;
      const bool read_right = descriptor.id.rfind("brep/k2/outer/reflex/inner-inner/", 0) == 0 ||
                              descriptor.id.find("/inner-inner-inner/") != std::string::npos;
      EXPECT_EQ(convexity_wrong || orientation_wrong, !read_right);
      if (truth.labels->known_weak_spot == "twisted_face") {
        EXPECT_TRUE(convexity_wrong);
        EXPECT_EQ(got.orientation, Orientation::Inner);
      }
      ++checked;
    }
  }
  EXPECT_GE(checked, 22);  // the twisted face, the multiple-inner-boundary cases, 2 sizes each
}

}  // namespace
}  // namespace holebench
