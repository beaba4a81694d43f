// Invariants: a report carrying the ground truth's own labels is correct in every field,
// whatever the starting point of its loop; a wrong field is counted wrong; reports without
// a classification are not compared.
#include "metrics/classification_accuracy.h"

#include "core/boundary_loops.h"
#include "generators/case_catalog.h"
#include "metrics/hole_matching.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace holebench {
namespace {

HoleReport report_at_hole(const Case& c, int hole) {
  HoleReport report;
  report.hole_index = hole;
  const auto loops = find_boundary_loops(c.input);
  report.centroid = loop_centroid(c.input, loops.at(hole));
  return report;
}

TEST(HoleMatching, ReportAtTheLoopMatchesItsHole) {
  const Case c = generators::make_case("box/corner");
  const auto matches = match_holes(c, {report_at_hole(c, 0)});
  ASSERT_EQ(matches.size(), 1u);
  EXPECT_EQ(matches[0].truth, 0);
}

TEST(ClassificationAccuracy, TruthLabelsRotatedAreCorrect) {
  for (const char* id : {"brep/k3/inner/convex-convex-reflex/small",
                         "brep/k3/outer/convex-convex-reflex/inner-outer-outer/large"}) {
    const Case c = generators::make_case(id);
    ASSERT_TRUE(c.holes[0].labels.has_value()) << id;
    MethodResult result;
    HoleReport report = report_at_hole(c, 0);
    HoleLabels labels = *c.holes[0].labels;
    std::rotate(labels.transitions.begin(), labels.transitions.begin() + 1,
                labels.transitions.end());
    if (!labels.boundary_kinds.empty())
      std::rotate(labels.boundary_kinds.begin(), labels.boundary_kinds.begin() + 1,
                  labels.boundary_kinds.end());
    report.classification = labels;
    result.holes.push_back(report);
    result.holes.push_back(report_at_hole(c, 0));  // no classification: not compared
    const auto a = classification_accuracy(c, result);
    EXPECT_EQ(a.compared, 1u) << id;
    EXPECT_EQ(a.all_correct, 1u) << id;
    EXPECT_EQ(a.boundary_kind_compared,
              c.holes[0].labels->orientation == Orientation::Outer ? 1u : 0u);
  }
}

TEST(ClassificationAccuracy, WrongFieldsAreCountedWrong) {
  const Case c = generators::make_case("brep/k3/inner/convex-convex-reflex/small");
  MethodResult result;
  HoleReport report = report_at_hole(c, 0);
  HoleLabels labels = *c.holes[0].labels;
  labels.k = 2;
  labels.transitions = {Convexity::Convex, Convexity::Convex, Convexity::Convex};
  report.classification = labels;
  result.holes.push_back(report);
  const auto a = classification_accuracy(c, result);
  EXPECT_EQ(a.compared, 1u);
  EXPECT_EQ(a.k_correct, 0u);
  EXPECT_EQ(a.convexity_correct, 0u);  // c c r is no rotation of c c c
  EXPECT_EQ(a.orientation_correct, 1u);
  EXPECT_EQ(a.decision_correct, 1u);
  EXPECT_EQ(a.all_correct, 0u);
}

// The decision measure: a hole the truth says to close counts when closed; one it says to
// guide counts when guided by an arrow and left open (closing it instead does not count).
TEST(ClassificationAccuracy, DecisionHandledFollowsTheTruthsDecision) {
  const Case close = generators::make_case("brep/k3/inner/convex-convex-reflex/small");
  const Case guide =
      generators::make_case("brep/k3/outer/convex-convex-reflex/inner-outer-outer/large");
  ASSERT_EQ(close.holes[0].labels->expected_decision, Decision::CloseAutomatically);
  ASSERT_EQ(guide.holes[0].labels->expected_decision, Decision::Guide);
  const auto handled = [](const Case& c, bool closed, bool arrow) {
    MethodResult result;
    HoleReport report = report_at_hole(c, 0);
    report.classification = *c.holes[0].labels;
    report.closed = closed;
    if (arrow)
      report.arrow = GuidanceArrow{Point(0, 0, 0), Point(0, 0, 1)};
    result.holes.push_back(report);
    const auto a = classification_accuracy(c, result);
    EXPECT_EQ(a.compared, 1u);
    return a.decision_handled;
  };
  EXPECT_EQ(handled(close, true, false), 1u);
  EXPECT_EQ(handled(close, false, true), 0u);
  EXPECT_EQ(handled(guide, false, true), 1u);
  EXPECT_EQ(handled(guide, true, false), 0u);
  EXPECT_EQ(handled(guide, false, false), 0u);  // neither closed nor guided
}

}  // namespace
}  // namespace holebench
