// Classification accuracy of methods that classify holes: each hole report with a
// classification, matched to a ground-truth hole with labels (metrics/hole_matching.h),
// is compared field by field:
//  - k: equal cardinality;
//  - orientation: equal (inner / outer), where both the truth and the classification
//    define it (HoleLabels::orientation_known; for k > 3 the paper's method cannot);
//  - convexity: the transitions' convexities equal as cyclic sequences (up to rotation:
//    the method's loop may start elsewhere; region ids are the method's own, so only the
//    convexity sequence is compared). Both empty (k = 1) counts as equal;
//  - boundary kinds (outer holes of the truth only): equal as cyclic sequences, with the
//    same rotation test;
//  - decision: the method's decision (its `expected_decision` field) equals the truth's;
//  - decision handled: the hole was handled as the truth's decision says: closed where it
//    says close automatically, guided (an arrow, the hole left open) where it says guide.
//    This is the success measure of a method that guides by design (docs/results.md).
// Reports without classification, and truths without labels, are not counted.
#pragma once

#include "core/case.h"
#include "core/method_result.h"
#include "metrics/hole_matching.h"

#include <cstddef>

namespace holebench {

struct ClassificationAccuracy {
  std::size_t compared = 0;  ///< reports compared
  std::size_t k_correct = 0;
  std::size_t orientation_compared = 0;  ///< of the compared, those where both define it
  std::size_t orientation_correct = 0;
  std::size_t convexity_correct = 0;
  std::size_t boundary_kind_compared = 0;  ///< of the compared, those with an outer truth
  std::size_t boundary_kind_correct = 0;
  std::size_t decision_correct = 0;
  std::size_t decision_handled = 0;  ///< handled as the truth's decision says
  std::size_t all_correct = 0;       ///< every applicable field correct
};

ClassificationAccuracy classification_accuracy(const Case& c, const MethodResult& result);

/// The same, with the reports' matches given (match_holes(c, result.holes)).
ClassificationAccuracy classification_accuracy(const Case& c, const MethodResult& result,
                                               const std::vector<HoleMatch>& matches);

/// Whether `a` equals some rotation of `b` (two empty sequences are equal).
template <typename T>
bool equal_up_to_rotation(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size())
    return false;
  if (a.empty())
    return true;
  for (std::size_t shift = 0; shift < b.size(); ++shift) {
    bool same = true;
    for (std::size_t i = 0; i < a.size() && same; ++i)
      same = a[i] == b[(i + shift) % b.size()];
    if (same)
      return true;
  }
  return false;
}

}  // namespace holebench
