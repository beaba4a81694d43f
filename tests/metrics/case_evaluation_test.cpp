// What the evaluations of a case share (CaseEvaluation) changes no number: the metrics of a
// repair evaluated with it equal, bit for bit, those evaluated without it.
#include "metrics/case_evaluation.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"
#include "generators/case_catalog.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace holebench {
namespace {

// The input with every hole closed by a fan from its loop's first vertex (new faces).
Mesh fan_closing(const Mesh& input) {
  Mesh repaired = input;
  for (const auto& loop : find_boundary_loops(input)) {
    const auto v = loop_vertices(input, loop);
    for (std::size_t i = 1; i + 1 < v.size(); ++i)
      repaired.add_face(v[0], v[i], v[i + 1]);
  }
  return repaired;
}

// The complete model with the removed faces new: an exact closing.
Mesh exact_closing(const Case& c) {
  Mesh repaired = c.complete;
  for (const auto& hole : c.holes) {
    for (int f : hole.removed_faces)
      repaired.data(repaired.face_handle(f)).provenance = Provenance::New;
  }
  return repaired;
}

void expect_same_metrics(const Evaluation& alone, const Evaluation& shared,
                         const std::string& what) {
  ASSERT_EQ(alone.values.size(), shared.values.size()) << what;
  for (std::size_t i = 0; i < alone.values.size(); ++i) {
    EXPECT_EQ(alone.values[i].name, shared.values[i].name) << what;
    EXPECT_EQ(alone.values[i].value, shared.values[i].value) << what << " " << alone.values[i].name;
  }
}

TEST(CaseEvaluation, SharedPartsChangeNoMetric) {
  for (const char* id : {"box/corner", "brep/k3/inner/convex-convex-convex/small"}) {
    for (double noise : {0.0, 25.0}) {
      const Case c = generators::make_case(id, 0, noise);
      const EvaluationOptions options;
      const CaseEvaluation shared(c, options);
      ASSERT_NE(shared.complete_scene(), nullptr);
      ASSERT_NE(shared.input_self_intersections(), nullptr);
      ASSERT_NE(shared.input_cell_bounds(), nullptr);
      ASSERT_NE(shared.input_hausdorff_bounds(), nullptr);
      if (noise > 0.0) {  // no input face lies on the complete model: each has its bounds
        EXPECT_GT(shared.input_cell_bounds()->size(), c.input.n_faces() / 2);
        EXPECT_EQ(shared.input_hausdorff_bounds()->size(), c.input.n_faces());
      }
      const std::string what = std::string(id) + " noise " + std::to_string(noise);
      MethodResult fan;
      fan.repaired = fan_closing(c.input);
      expect_same_metrics(evaluate(c, fan, options), evaluate(c, fan, options, shared),
                          what + " fan");
      MethodResult exact;
      exact.repaired = exact_closing(c);
      expect_same_metrics(evaluate(c, exact, options), evaluate(c, exact, options, shared),
                          what + " exact");
      // A repair that also moved an input vertex away from the holes: the faces around it are
      // not the input's, and the bounds read near them are not taken.
      MethodResult moved = fan;
      const VertexHandle v = moved.repaired.vertex_handle(0);
      ASSERT_FALSE(moved.repaired.is_boundary(v));
      moved.repaired.point(v) += Point(1.0, 1.0, 1.0) * (0.01 * bounding_box_diagonal(c.complete));
      expect_same_metrics(evaluate(c, moved, options), evaluate(c, moved, options, shared),
                          what + " moved");
      MethodResult open;
      open.repaired = c.input;
      expect_same_metrics(evaluate(c, open, options), evaluate(c, open, options, shared),
                          what + " open");
      MethodResult nothing;  // an empty repair: no distance, the same validity
      expect_same_metrics(evaluate(c, nothing, options), evaluate(c, nothing, options, shared),
                          what + " empty");
    }
  }
}

}  // namespace
}  // namespace holebench
