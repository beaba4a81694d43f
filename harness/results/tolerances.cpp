#include "harness/results/tolerances.h"

#include <algorithm>

namespace holebench::harness {

namespace {

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

bool higher_is_better_metric(const std::string& metric) {
  return ends_with(metric, "_correct_fraction") || ends_with(metric, "_ok") ||
         metric.rfind("is_", 0) == 0 ||
         (metric.rfind("missing_edge_", 0) == 0 && ends_with(metric, "_fraction")) ||
         (metric.rfind("arrow_", 0) == 0 && ends_with(metric, "visible_fraction")) ||
         metric.find("f_score_") != std::string::npos ||
         ends_with(metric, "normal_consistency_fraction") ||
         metric == metric_names::kDecisionHandledFraction;
}

bool informational_metric(const std::string& metric) {
  return metric == metric_names::kInputFacesCount || metric == metric_names::kNewFacesCount ||
         metric == metric_names::kArrowsCount;
}

std::optional<MetricTolerance> Tolerances::find(const std::string& metric) const {
  if (std::find(ignored.begin(), ignored.end(), metric) != ignored.end())
    return std::nullopt;
  if (const auto it = metrics.find(metric); it != metrics.end())
    return it->second;
  if (informational_metric(metric))
    return std::nullopt;
  MetricTolerance tolerance = default_tolerance;
  tolerance.lower_is_better = !higher_is_better_metric(metric);
  return tolerance;
}

}  // namespace holebench::harness
