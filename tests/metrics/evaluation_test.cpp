// Invariants of evaluate(): names carry units, metrics that do not apply are absent, the
// complete model scores zero distance, the unrepaired input is open and far in the hole,
// and the same inputs give the same numbers.
#include "metrics/evaluation.h"

#include "metrics/case_evaluation.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"
#include "generators/case_catalog.h"

#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

namespace holebench {
namespace {

bool has(const Evaluation& e, const char* name) {
  return e.find(name) != nullptr;
}

// The complete model as the repair, its hole's removed faces marked new: an exact patch.
MethodResult complete_model_as_repair(const Case& c) {
  MethodResult result;
  result.repaired = c.complete;
  for (int f : c.holes[0].removed_faces)
    result.repaired.data(result.repaired.face_handle(f)).provenance = Provenance::New;
  return result;
}

TEST(Evaluation, NamesCarryTheirUnit) {
  const Case c = generators::make_case("box/corner");
  MethodResult result;
  result.repaired = c.input;
  const std::regex unit(R"(.*(_rel_diag|_rel_diag2|_deg|_count|_fraction|_s|_ok)$|^is_.*)");
  for (const auto& v : evaluate(c, result).values)
    EXPECT_TRUE(std::regex_match(v.name, unit)) << v.name;
}

// The complete model itself, with the removed faces playing the patch: zero distance
// everywhere, closed, valid; no classification or arrow metrics (nothing to judge).
TEST(Evaluation, CompleteModelScoresZero) {
  const Case c = generators::make_case("box/corner");
  MethodResult result = complete_model_as_repair(c);
  const Evaluation e = evaluate(c, result);
  for (const char* name : {"hausdorff_upper_rel_diag", "mean_distance_rel_diag",
                           "rms_distance_rel_diag", "hole_hausdorff_upper_rel_diag",
                           "hole_mean_distance_rel_diag", "missing_corner_error_max_rel_diag"}) {
    ASSERT_TRUE(has(e, name)) << name;
    EXPECT_LE(e.find(name)->value, 1e-12) << name;
  }
  EXPECT_EQ(e.find("is_closed")->value, 1.0);
  EXPECT_EQ(e.find("is_manifold")->value, 1.0);
  EXPECT_EQ(e.find("self_intersections_count")->value, 0.0);
  EXPECT_EQ(e.find("distance_converged_ok")->value, 1.0);
  EXPECT_EQ(e.find("valid_repair_ok")->value, 1.0);
  // The literature's metrics of an exact repair: no distance, full agreement.
  for (const char* name : {"chamfer_l1_upper_rel_diag", "chamfer_l2_upper_rel_diag2",
                           "hole_chamfer_l1_upper_rel_diag", "hole_edge_chamfer_rel_diag"}) {
    ASSERT_TRUE(has(e, name)) << name;
    EXPECT_LE(e.find(name)->value, 1e-12) << name;
  }
  for (const char* name : {"f_score_0_5pct_fraction", "f_score_1pct_fraction",
                           "normal_consistency_fraction", "hole_f_score_0_5pct_fraction",
                           "hole_f_score_1pct_fraction", "hole_normal_consistency_fraction"}) {
    ASSERT_TRUE(has(e, name)) << name;
    EXPECT_NEAR(e.find(name)->value, 1.0, 1e-12) << name;
  }
  EXPECT_FALSE(has(e, "classification_k_correct_fraction"));
  EXPECT_FALSE(has(e, "arrow_visible_fraction"));
}

// Nothing repaired: the hole stays open; its region is as far as the hole's removed
// surface is from the kept mesh (> 0); no new vertices, so no Table 2 error.
TEST(Evaluation, UnrepairedInputIsOpenAndFar) {
  const Case c = generators::make_case("box/corner");
  MethodResult result;
  result.repaired = c.input;
  const Evaluation e = evaluate(c, result);
  EXPECT_EQ(e.find("is_closed")->value, 0.0);
  EXPECT_EQ(e.find("open_boundary_loops_count")->value, 1.0);
  EXPECT_GT(e.find("hole_hausdorff_rel_diag")->value, 0.0);
  EXPECT_FALSE(has(e, "new_vertex_mean_error_rel_diag"));
  EXPECT_FALSE(has(e, "patch_normal_deviation_mean_deg"));
  EXPECT_EQ(e.find("original_faces_unchanged_ok")->value, 1.0);
  EXPECT_EQ(e.find("valid_repair_ok")->value, 0.0);  // open
}

// A patch that crosses the model is not a valid repair, though every hole is closed: the
// removed faces play the patch, one of their vertices pushed through the opposite side.
TEST(Evaluation, ASelfIntersectingPatchIsNotAValidRepair) {
  const Case c = generators::make_case("box/corner");
  MethodResult result = complete_model_as_repair(c);
  HoleReport report;
  report.closed = true;
  result.holes.push_back(report);
  // A vertex that only new faces use, moved through the box to beyond its far side.
  const Point centre = bounding_box(c.complete).center();
  bool moved = false;
  for (auto v : result.repaired.vertices()) {
    bool only_new = !result.repaired.is_isolated(v);
    for (auto f : result.repaired.vf_range(v))
      only_new = only_new && is_new(result.repaired, f);
    if (only_new && !moved) {
      const Point p = result.repaired.point(v);
      result.repaired.set_point(v, centre + (centre - p) * 1.5);
      moved = true;
    }
  }
  ASSERT_TRUE(moved);
  const Evaluation e = evaluate(c, result);
  EXPECT_EQ(e.find("is_closed")->value, 1.0);
  EXPECT_GT(e.find("patch_self_intersections_count")->value, 0.0);
  EXPECT_EQ(e.find("valid_repair_ok")->value, 0.0);
}

// The slice paper's Table 2 error on a known answer: the complete model with the vertices
// inside a face-interior hole marked new and lifted off the face by d along its normal.
// Each is then exactly d from the complete model, so the mean is d (relative to the
// diagonal); the whole-model Hausdorff distance is d too.
TEST(Evaluation, NewVertexErrorIsTheOffsetOfTheNewVertices) {
  const Case c = generators::make_case("box/face_interior");
  MethodResult result;
  result.repaired = c.complete;
  Mesh& mesh = result.repaired;
  std::vector<char> removed(mesh.n_faces(), 0);
  for (int f : c.holes[0].removed_faces)
    removed[f] = 1;
  const Point normal = face_normal(mesh, mesh.face_handle(c.holes[0].removed_faces.front()));
  const double diagonal = bounding_box_diagonal(c.complete);
  const double d = 1e-3 * diagonal;
  std::size_t lifted = 0;
  for (auto v : mesh.vertices()) {
    bool inside = true;
    for (auto f : mesh.vf_range(v))
      inside = inside && removed[f.idx()];
    if (!inside)
      continue;
    mesh.data(v).provenance = Provenance::New;
    mesh.point(v) += normal * d;
    ++lifted;
  }
  for (int f : c.holes[0].removed_faces)
    mesh.data(mesh.face_handle(f)).provenance = Provenance::New;
  ASSERT_GT(lifted, 0u);
  const Evaluation e = evaluate(c, result);
  ASSERT_TRUE(has(e, "new_vertex_mean_error_rel_diag"));
  EXPECT_NEAR(e.find("new_vertex_mean_error_rel_diag")->value, 1e-3, 1e-12);
  EXPECT_NEAR(e.find("hausdorff_rel_diag")->value, 1e-3, 1e-12);
  EXPECT_LE(e.find("hausdorff_upper_rel_diag")->value, 1e-3 + 1e-4);
}

// An arrow straight above a face-interior hole, and a classification: both are judged.
TEST(Evaluation, ArrowsAndClassificationsAreJudged) {
  const Case c = generators::make_case("brep/k1/inner/small");
  ASSERT_TRUE(c.holes[0].labels.has_value());
  MethodResult result;
  result.repaired = c.input;
  HoleReport report;
  const auto loops = find_boundary_loops(c.input);
  report.centroid = loop_centroid(c.input, loops[0]);
  // The removed faces' normal (they lie in one plane).
  const FaceHandle f = c.complete.face_handle(c.holes[0].removed_faces[0]);
  const Point n = face_normal(c.complete, f);
  report.arrow = GuidanceArrow{report.centroid + n * bounding_box_diagonal(c.complete), -n};
  report.classification = c.holes[0].labels;
  result.holes.push_back(report);
  const Evaluation e = evaluate(c, result);
  EXPECT_EQ(e.find("classification_all_correct_fraction")->value, 1.0);
  EXPECT_EQ(e.find("arrow_position_outside_ok")->value, 1.0);
  EXPECT_EQ(e.find("arrow_shaft_free_ok")->value, 1.0);
  EXPECT_EQ(e.find("arrow_visible_fraction")->value, 1.0);
  EXPECT_EQ(e.find("arrow_direction_error_deg")->value, 0.0);
}

// An arrow with a NaN direction (a zero fan normal, as on a loop around a pin) cannot be ray
// cast: it is counted as undefined, not judged, and the evaluation does not abort in Embree.
TEST(Evaluation, UndefinedArrowIsCountedNotCast) {
  const Case c = generators::make_case("brep/k1/inner/small");
  MethodResult result;
  result.repaired = c.input;
  HoleReport report;
  report.centroid = loop_centroid(c.input, find_boundary_loops(c.input)[0]);
  const Point zero(0.0, 0.0, 0.0);
  report.arrow = GuidanceArrow{report.centroid, zero / zero.norm()};
  EXPECT_FALSE(is_finite(*report.arrow));
  result.holes.push_back(report);
  const Evaluation e = evaluate(c, result);
  ASSERT_TRUE(has(e, "arrows_undefined_count"));
  EXPECT_EQ(e.find("arrows_undefined_count")->value, 1.0);
  EXPECT_FALSE(has(e, "arrows_count"));
  EXPECT_FALSE(has(e, "arrow_visible_fraction"));
}

// fallback_holes_fraction = reports with a fallback / reports: 1 of 4 is 0.25, none is 0, and
// without hole reports the metric is absent (it does not apply).
TEST(Evaluation, FallbackHolesFractionCountsTheReportsWithAStandIn) {
  const Case c = generators::make_case("box/corner");
  MethodResult result;
  result.repaired = c.input;
  EXPECT_FALSE(has(evaluate(c, result), "fallback_holes_fraction"));

  result.holes.resize(4);
  const Evaluation none = evaluate(c, result);
  ASSERT_TRUE(has(none, "fallback_holes_fraction"));
  EXPECT_EQ(none.find("fallback_holes_fraction")->value, 0.0);

  result.holes[2].fallback = "one_portion_without_features";
  EXPECT_EQ(evaluate(c, result).find("fallback_holes_fraction")->value, 0.25);
}

std::vector<std::string> phase_names(const Evaluation& e) {
  std::vector<std::string> names;
  for (const auto& phase : e.phases) {
    EXPECT_GE(phase.seconds, 0.0) << phase.phase;
    names.push_back(phase.phase);
  }
  return names;
}

// The evaluation times each of its steps once, in the order they run; a step that does not
// run (the distances of an empty repair) is not timed.
TEST(Evaluation, EachStepThatRunsIsTimedOnce) {
  const Case c = generators::make_case("box/corner");
  MethodResult result;
  result.repaired = c.input;
  EXPECT_EQ(phase_names(evaluate(c, result)),
            (std::vector<std::string>{"complete_scene", "repaired_scene", "patch_mean_distance",
                                      "whole_model_distances", "hole_region_distances",
                                      "new_vertex_error", "literature_metrics", "feature_recovery",
                                      "validity", "classification", "arrow_visibility"}));
  MethodResult nothing;
  EXPECT_EQ(phase_names(evaluate(c, nothing)),
            (std::vector<std::string>{"complete_scene", "validity", "classification",
                                      "arrow_visibility"}));
  // With the case's shared work: no scene of its own; what the repair kept is found first.
  const CaseEvaluation shared(c, EvaluationOptions{});
  EXPECT_EQ(phase_names(evaluate(c, result, EvaluationOptions{}, shared)),
            (std::vector<std::string>{"kept_faces", "repaired_scene", "patch_mean_distance",
                                      "whole_model_distances", "hole_region_distances",
                                      "new_vertex_error", "literature_metrics", "feature_recovery",
                                      "validity", "classification", "arrow_visibility"}));
  EXPECT_EQ(
      phase_names(evaluate(c, nothing, EvaluationOptions{}, shared)),
      (std::vector<std::string>{"kept_faces", "validity", "classification", "arrow_visibility"}));
}

TEST(Evaluation, SameInputsGiveTheSameNumbers) {
  const Case c = generators::make_case("brep/k2/inner/convex/small");
  MethodResult result;
  result.repaired = c.input;
  const Evaluation first = evaluate(c, result);
  const Evaluation second = evaluate(c, result);
  ASSERT_EQ(first.values.size(), second.values.size());
  for (std::size_t i = 0; i < first.values.size(); ++i) {
    EXPECT_EQ(first.values[i].name, second.values[i].name);
    EXPECT_EQ(first.values[i].value, second.values[i].value) << first.values[i].name;
  }
}

}  // namespace
}  // namespace holebench
