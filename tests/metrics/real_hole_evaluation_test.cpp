// The evaluation of real-hole cases (generators/real_holes.h): without ground truth only the
// metrics that need none; with the rings as truth, the ring_* metrics of the truth-to-repair
// direction, exact for an exact repair.
#include "core/mesh_builder.h"
#include "core/method_result.h"
#include "generators/box_solid.h"
#include "generators/hole_punch.h"
#include "generators/real_holes.h"
#include "metrics/evaluation.h"
#include "metrics/metric_names.h"

#include <gtest/gtest.h>

namespace holebench {
namespace {
using namespace metric_names;

Mesh box_with_one_hole() {
  const Mesh box = generators::make_box();
  return generators::punch_faces(box, generators::faces_in_ball(box, Point(1.0, 0.75, 0.0), 0.2))
      .holed;
}

// The input with the complete model's faces it lacks added back as new faces: the exact repair
// of a ring-removal case (the complete model keeps its real hole open).
MethodResult exact_ring_repair(const Case& c) {
  MethodResult result;
  result.repaired = c.input;
  std::vector<VertexHandle> added(c.complete.n_vertices());
  for (int f : c.holes[0].removed_faces) {
    std::vector<VertexHandle> corners;
    for (auto v : c.complete.fv_range(c.complete.face_handle(f))) {
      // A vertex the input kept is found by position (punch_faces keeps positions exactly).
      VertexHandle found;
      for (auto w : result.repaired.vertices()) {
        if (result.repaired.point(w) == c.complete.point(v)) {
          found = w;
          break;
        }
      }
      if (!found.is_valid()) {
        found = result.repaired.add_vertex(c.complete.point(v));
        result.repaired.data(found).provenance = Provenance::New;
      }
      corners.push_back(found);
    }
    const FaceHandle added_face = result.repaired.add_face(corners);
    EXPECT_TRUE(added_face.is_valid());
    result.repaired.data(added_face).provenance = Provenance::New;
  }
  HoleReport hole;
  hole.closed = true;
  result.holes.push_back(hole);
  return result;
}

const double* metric(const Evaluation& e, const char* name) {
  const MetricValue* m = e.find(name);
  return m ? &m->value : nullptr;
}

TEST(RealHoleEvaluation, WithoutTruthOnlyTheMetricsThatNeedNone) {
  const Case c = generators::make_real_hole_case(box_with_one_hole(), 0, "file/box/hole/0");
  MethodResult unchanged;
  unchanged.repaired = c.input;
  const Evaluation e = evaluate(c, unchanged);
  EXPECT_EQ(metric(e, kHausdorffRelDiag), nullptr);
  EXPECT_EQ(metric(e, kHoleHausdorffRelDiag), nullptr);
  ASSERT_NE(metric(e, kOpenBoundaryLoopsCount), nullptr);
  EXPECT_EQ(*metric(e, kOpenBoundaryLoopsCount), 1.0);
  EXPECT_EQ(metric(e, kPatchTriangleQualityMinFraction), nullptr);  // no patch
}

TEST(RealHoleEvaluation, AnExactRepairOfTheRingsScoresZeroOnTheRings) {
  const Case c =
      generators::make_ring_removal_case(box_with_one_hole(), 0, 2, "file/box/hole/0/rings-2");
  const Evaluation e = evaluate(c, exact_ring_repair(c));
  ASSERT_NE(metric(e, kRingHausdorffRelDiag), nullptr);
  EXPECT_LE(*metric(e, kRingHausdorffRelDiag), 1e-12);
  EXPECT_LE(*metric(e, kRingMeanDistanceUpperRelDiag), 1e-5);
  EXPECT_LE(*metric(e, kHoleHausdorffRelDiag), 1e-12);  // the patch lies on the complete model

  // An inexact repair: the rings' direction is at most the hole region's (the larger of both).
  MethodResult moved = exact_ring_repair(c);
  for (auto v : moved.repaired.vertices()) {
    if (is_new(moved.repaired, v))
      moved.repaired.point(v)[2] -= 0.05;
  }
  const Evaluation m = evaluate(c, moved);
  ASSERT_NE(metric(m, kRingHausdorffRelDiag), nullptr);
  EXPECT_GT(*metric(m, kRingHausdorffRelDiag), 0.0);
  EXPECT_LE(*metric(m, kRingHausdorffRelDiag), *metric(m, kHoleHausdorffUpperRelDiag));
  EXPECT_GT(*metric(m, kRingMeanDistanceRelDiag), 0.0);
}

}  // namespace
}  // namespace holebench
