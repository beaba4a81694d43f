// Reading a metric off an evaluation, for the methods' tests.
#pragma once

#include "metrics/evaluation.h"

#include <string>

namespace holebench::test {

/// The value of the metric `name` in `e`; -1 where `e` has none.
inline double metric(const Evaluation& e, const std::string& name) {
  const MetricValue* v = e.find(name);
  return v ? v->value : -1.0;
}

}  // namespace holebench::test
