#include "metrics/classification_accuracy.h"

#include "metrics/hole_matching.h"

namespace holebench {

ClassificationAccuracy classification_accuracy(const Case& c, const MethodResult& result) {
  return classification_accuracy(c, result, match_holes(c, result.holes));
}

ClassificationAccuracy classification_accuracy(const Case& c, const MethodResult& result,
                                               const std::vector<HoleMatch>& matches) {
  ClassificationAccuracy accuracy;
  for (std::size_t i = 0; i < result.holes.size(); ++i) {
    const auto& report = result.holes[i];
    if (!report.classification || matches[i].truth < 0)
      continue;
    const auto& truth_labels = c.holes[matches[i].truth].labels;
    if (!truth_labels)
      continue;
    const HoleLabels& got = *report.classification;
    const HoleLabels& truth = *truth_labels;
    ++accuracy.compared;
    const bool k = got.k == truth.k;
    // Orientation is compared where both define it (HoleLabels::orientation_known).
    const bool orientation_compared = got.orientation_known && truth.orientation_known;
    const bool orientation = !orientation_compared || got.orientation == truth.orientation;
    accuracy.orientation_compared += orientation_compared;
    const bool convexity = equal_up_to_rotation(got.transitions, truth.transitions);
    const bool decision = got.expected_decision == truth.expected_decision;
    bool all = k && orientation && convexity && decision;
    accuracy.k_correct += k;
    accuracy.orientation_correct += orientation_compared && orientation;
    accuracy.convexity_correct += convexity;
    accuracy.decision_correct += decision;
    const bool guided = report.arrow.has_value() && !report.closed;
    accuracy.decision_handled +=
        truth.expected_decision == Decision::Guide ? guided : report.closed;
    // Boundary kinds are defined for outer holes; they are compared where the method, too,
    // found the hole outer and computed them.
    if (truth.orientation == Orientation::Outer && got.orientation == Orientation::Outer &&
        got.orientation_known && !got.boundary_kinds.empty()) {
      const bool kinds = equal_up_to_rotation(got.boundary_kinds, truth.boundary_kinds);
      ++accuracy.boundary_kind_compared;
      accuracy.boundary_kind_correct += kinds;
      all = all && kinds;
    }
    accuracy.all_correct += all;
  }
  return accuracy;
}

}  // namespace holebench
