// What the evaluations of a case share (CaseEvaluation) changes no number: the metrics of a
// repair evaluated with it equal, bit for bit, those evaluated without it, whether the repair
// keeps every input face (its scene then made from the input's), drops one, moves a vertex or
// leaves holes open (its topology then counted at its changes).
#include "metrics/case_evaluation.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"
#include "generators/case_catalog.h"
#include "metrics/face_subset.h"
#include "metrics/literature_metrics.h"

#include "tests/metrics/test_repairs.h"

#include <gtest/gtest.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace holebench {
namespace {

// The input with one face at a hole's boundary removed (OpenMesh's garbage collection moves
// the last face into its place, so the kept faces are not in the input's order), then every
// hole closed by a fan: a repair that drops an input face.
Mesh drop_and_fan(const Mesh& input) {
  Mesh dropped = input;
  dropped.request_face_status();
  dropped.request_edge_status();
  dropped.request_vertex_status();
  const auto loop = find_boundary_loops(dropped).front();
  const HalfedgeHandle inside = dropped.opposite_halfedge_handle(loop.halfedges.front());
  dropped.delete_face(dropped.face_handle(inside), false);
  dropped.garbage_collection();
  return test::fan_closing(dropped);
}

// The input with only its first hole closed by a fan.
Mesh first_hole_closed(const Mesh& input) {
  Mesh repaired = input;
  const auto loops = find_boundary_loops(input);
  const auto v = loop_vertices(input, loops.front());
  for (std::size_t i = 1; i + 1 < v.size(); ++i)
    repaired.add_face(v[0], v[i], v[i + 1]);
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
  // A corner (missing corners), a B-Rep pocket, several loops, a crease (missing edges).
  for (const char* id :
       {"box/corner", "brep/k3/inner/convex-convex-convex/small",
        "brep/weak/multiple-inner-boundaries/small", "solid/l_block/edge_convex/small"}) {
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
        ASSERT_NE(shared.complete_hausdorff_bounds(), nullptr);
        // The truth's cones are at the samples a job's hole region draws, so that it takes them.
        ASSERT_NE(shared.truth_cone_answers(), nullptr);
        const Mesh truth = face_subset(c.complete, removed_faces(c));
        const AreaSamples truth_samples = tally_samples(truth, options.hole_literature_samples,
                                                        sampled_faces(face_areas(truth), nullptr));
        EXPECT_EQ(shared.truth_cone_answers()->points(), truth_samples.points);
        EXPECT_EQ(shared.truth_cone_answers()->normals(), truth_samples.normals);
        EXPECT_EQ(shared.complete_hausdorff_bounds()->size(), c.complete.n_faces());
      }
      const std::string what = std::string(id) + " noise " + std::to_string(noise);
      MethodResult fan;
      fan.repaired = test::fan_closing(c.input);
      expect_same_metrics(evaluate(c, fan, options), evaluate(c, fan, options, shared),
                          what + " fan");
      MethodResult exact;
      exact.repaired = exact_closing(c);
      expect_same_metrics(evaluate(c, exact, options), evaluate(c, exact, options, shared),
                          what + " exact");
      MethodResult appended;  // an exact closing after the input's faces (new faces shared)
      appended.repaired = test::exact_appended_closing(c);
      expect_same_metrics(evaluate(c, appended, options), evaluate(c, appended, options, shared),
                          what + " exact appended");
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
      MethodResult dropped;  // an input face dropped: counted at the changes all the same
      dropped.repaired = drop_and_fan(c.input);
      expect_same_metrics(evaluate(c, dropped, options), evaluate(c, dropped, options, shared),
                          what + " dropped");
      // An input face dropped, the others kept in order one index lower after it: the case's
      // bounds are taken through the face maps (SurfaceChange), not at the same indices.
      MethodResult dropped_in_order;
      dropped_in_order.repaired = test::drop_in_order_and_fan(c.input);
      expect_same_metrics(evaluate(c, dropped_in_order, options),
                          evaluate(c, dropped_in_order, options, shared),
                          what + " dropped in order");
      MethodResult partial;  // holes left open beside a closed one
      partial.repaired = first_hole_closed(c.input);
      expect_same_metrics(evaluate(c, partial, options), evaluate(c, partial, options, shared),
                          what + " partial");
      MethodResult nothing;  // an empty repair: no distance, the same validity
      expect_same_metrics(evaluate(c, nothing, options), evaluate(c, nothing, options, shared),
                          what + " empty");
    }
  }
}

}  // namespace
}  // namespace holebench
