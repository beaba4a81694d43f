// How much a metric may move between two runs before `holebench compare` calls it a
// regression, and in which direction each metric is better. Suites set them (run/suite.h);
// the comparison of results reads them (compare.h).
#pragma once

#include "metrics/metric_names.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace holebench::harness {

/// How much a metric may move before a change counts as a regression.
struct MetricTolerance {
  bool lower_is_better = true;  ///< false: higher is better (fractions of correct answers, ...)
  double relative = 0.05;       ///< allowed change relative to |old|
  double absolute = 1e-9;       ///< allowed change in the metric's own unit (guards old = 0)
};

struct Tolerances {
  MetricTolerance default_tolerance;
  std::map<std::string, MetricTolerance> metrics;  ///< by metric name; others use the default
  /// Metrics never judged (timings vary from machine to machine).
  std::vector<std::string> ignored{metric_names::kTimeMethodS};

  /// How `metric` is judged: its own entry if listed; nothing (not judged) if ignored or
  /// if it only describes the case or the answer's size (`informational_metric`);
  /// otherwise the default, in the direction its name says (`higher_is_better_metric`).
  std::optional<MetricTolerance> find(const std::string& metric) const;
};

/// Metrics that are better higher, by name: fractions of correct answers
/// (`*_correct_fraction`), pass/fail checks (`*_ok`, `is_*`), and the coverage and visibility
/// fractions (`missing_edge_*_fraction`, `arrow_*visible_fraction`). Every other metric
/// (distances, errors, angles, counts of defects, times, the share of holes a fallback
/// handled: `fallback_holes_fraction`) is better lower.
bool higher_is_better_metric(const std::string& metric);

/// Metrics that describe the case or the size of the answer, not its quality
/// (`input_faces_count`, `new_faces_count`, `arrows_count`): not judged unless a suite lists
/// them.
bool informational_metric(const std::string& metric);

}  // namespace holebench::harness
