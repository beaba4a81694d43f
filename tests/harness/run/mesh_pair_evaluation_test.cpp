// One pair of meshes scored (`holebench evaluate --complete --repaired [--holed]`): with the
// holed mesh, the holes found from the two meshes are the case's and every distance equals the
// run's evaluation of the same repair; without it, the whole-model metrics alone, the same.
#include "harness/run/mesh_pair_evaluation.h"
#include "core/mesh_builder.h"
#include "generators/case_catalog.h"
#include "methods/registry.h"
#include "methods/user.h"
#include "metrics/evaluation.h"

#include <gtest/gtest.h>

#include <string>

namespace holebench::harness {
namespace {

const MetricValue* find(const std::vector<MetricValue>& metrics, const std::string& name) {
  for (const auto& metric : metrics)
    if (metric.name == name)
      return &metric;
  return nullptr;
}

class MeshPairEvaluation : public ::testing::TestWithParam<const char*> {};

TEST_P(MeshPairEvaluation, EqualsTheRunsEvaluationOfTheSameRepair) {
  const Case c = generators::make_case(GetParam());
  NoUser user;
  const MethodResult result = make_method("liepa_cgal")->run(c.input, {}, user);
  ASSERT_NE(result.status, MethodStatus::Failed) << result.message;
  const Evaluation run = evaluate(c, result);
  const TriangleSoup repaired = to_soup(result.repaired);

  const auto pair = evaluate_mesh_pair(c.complete, repaired, &c.input);
  EXPECT_TRUE(pair.note.empty()) << pair.note;
  EXPECT_EQ(pair.holes, c.holes.size());
  std::size_t removed = 0;
  for (const auto& hole : c.holes)
    removed += hole.removed_faces.size();
  EXPECT_EQ(pair.removed_faces, removed);
  for (const char* name :
       {"hausdorff_rel_diag", "hausdorff_upper_rel_diag", "mean_distance_rel_diag",
        "rms_distance_upper_rel_diag", "hole_hausdorff_rel_diag", "hole_mean_distance_rel_diag",
        "hole_rms_distance_upper_rel_diag", "f_score_1pct_fraction",
        "hole_normal_consistency_fraction", "is_closed", "self_intersections_count",
        "patch_self_intersections_count", "new_faces_count", "valid_repair_ok"}) {
    SCOPED_TRACE(name);
    const MetricValue* ours = find(pair.metrics, name);
    const MetricValue* theirs = run.find(name);
    ASSERT_NE(theirs, nullptr);
    ASSERT_NE(ours, nullptr);
    EXPECT_EQ(ours->value, theirs->value);
  }
  EXPECT_EQ(find(pair.metrics, "time_method_s"), nullptr);
  EXPECT_EQ(find(pair.metrics, "fallback_holes_fraction"), nullptr);

  // Without the holed mesh: the whole model's metrics, the same numbers; nothing of a hole.
  const auto alone = evaluate_mesh_pair(c.complete, repaired, nullptr);
  for (const char* name : {"hausdorff_rel_diag", "hausdorff_upper_rel_diag", "is_closed",
                           "is_manifold", "self_intersections_count"}) {
    SCOPED_TRACE(name);
    const MetricValue* ours = find(alone.metrics, name);
    ASSERT_NE(ours, nullptr);
    EXPECT_EQ(ours->value, run.find(name)->value);
  }
  for (const auto& metric : alone.metrics) {
    EXPECT_NE(metric.name.rfind("hole_", 0), 0u) << metric.name;
    EXPECT_NE(metric.name.rfind("patch_", 0), 0u) << metric.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, MeshPairEvaluation,
                         ::testing::Values("box/corner", "brep/k2/inner/convex/small",
                                           "cad/fandisk/edge_convex/small"));

TEST(MeshPairEvaluationInput, ARepairThatChangedTheHoledMeshIsMeasuredAlone) {
  const Case c = generators::make_case("box/edge");
  TriangleSoup changed = to_soup(c.input);
  changed.points[0][0] += 1e-3;
  const auto pair = evaluate_mesh_pair(c.complete, changed, &c.input);
  EXPECT_NE(pair.note.find("changed or dropped"), std::string::npos) << pair.note;
  EXPECT_NE(find(pair.metrics, "hausdorff_rel_diag"), nullptr);
  EXPECT_EQ(find(pair.metrics, "hole_hausdorff_rel_diag"), nullptr);
}

// A noisy holed mesh shares no face with the clean complete one: it is not used (every face
// would count as removed), and the note says why.
TEST(MeshPairEvaluationInput, ANoisyHoledMeshIsNotTakenForAHoleEverywhere) {
  const Case c = generators::make_case("box/corner", 0, 5.0);
  const auto pair = evaluate_mesh_pair(c.complete, to_soup(c.input), &c.input);
  EXPECT_NE(pair.note.find("a noisy input?"), std::string::npos) << pair.note;
  EXPECT_EQ(pair.holes, 0u);
  EXPECT_NE(find(pair.metrics, "hausdorff_rel_diag"), nullptr);
  EXPECT_EQ(find(pair.metrics, "hole_mean_distance_rel_diag"), nullptr);
}

}  // namespace
}  // namespace holebench::harness
