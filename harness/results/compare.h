// Baseline comparison: what changed between two results files, job by job and metric by
// metric, judged by a suite's tolerances. The comparison is computed as data
// (`compare_results`) and printed or written separately (`print_comparison`,
// `write_junit_xml`), in the manner of Google Benchmark's tools/gbench/report.py.
// The rules (regression, zero handling) are in docs/reports.md.
#pragma once

#include "harness/results/record.h"
#include "harness/results/results_reader.h"
#include "harness/results/tolerances.h"

#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace holebench::harness {

/// How one metric of a matched job moved.
enum class MetricVerdict {
  Unchanged,        ///< new == old (bit for bit, or both NaN)
  WithinTolerance,  ///< moved, but by no more than the tolerance either way
  Improved,         ///< moved the good way by more than the tolerance
  Regressed,        ///< moved the bad way by more than the tolerance
  NotJudged,        ///< moved, but the metric is in the tolerances' `ignored` list
  Appeared,         ///< absent in the baseline, present now (not a regression)
  Disappeared,      ///< present in the baseline, absent now (not a regression by itself)
};
const char* to_string(MetricVerdict verdict);

struct MetricChange {
  std::string metric;
  std::optional<double> old_value;  ///< absent: the baseline had no such metric
  std::optional<double> new_value;  ///< absent: the new results have no such metric
  double change = 0.0;              ///< new - old (0 when either is absent)
  /// (new - old) / |old|; 0 when both are 0; +-infinity when old is 0 and new is not
  /// ("new from zero": judged by the absolute tolerance alone).
  double relative_change = 0.0;
  bool from_zero = false;  ///< old == 0 and new != 0
  double allowed = 0.0;    ///< max(absolute, relative * |old|); 0 when not judged
  MetricVerdict verdict = MetricVerdict::Unchanged;

  bool regression() const { return verdict == MetricVerdict::Regressed; }
};

/// Where a job is found.
enum class JobPresence {
  Both,     ///< in the baseline and in the new results: compared
  Missing,  ///< in the baseline only: a regression
  New,      ///< in the new results only: reported, not a regression
};
const char* to_string(JobPresence presence);

struct JobComparison {
  std::string job_id;
  std::string case_id;
  std::string method;
  JobPresence presence = JobPresence::Both;
  std::optional<JobStatus> old_status;  ///< absent for a new job
  std::optional<JobStatus> new_status;  ///< absent for a missing job
  /// Metrics present on either side, sorted by name (empty unless presence == Both).
  std::vector<MetricChange> metrics;
  /// The method's settings that differ, "name: old -> new" (a setting only one side has:
  /// "-" on the other), where both records name their settings (`method_options`; records
  /// written before them have none). Not judged: the same job run with other settings.
  std::vector<std::string> changed_settings;

  bool status_changed() const { return old_status && new_status && *old_status != *new_status; }
  /// The status went from ok to anything else.
  bool status_regressed() const;
  /// A regression: missing now, status regressed, or a metric regressed.
  bool regression() const;
  std::vector<const MetricChange*> regressed_metrics() const;
};

struct Comparison {
  std::string base_label;  ///< the baseline's code version (from its context), for the report
  std::string new_label;   ///< the new results' code version
  std::vector<JobComparison> jobs;  ///< sorted by job id

  bool has_regression() const;
  std::size_t regressed_jobs() const;
};

/// Compares `now` against `base`, matching records by job id (`Job::id()`). A metric is a
/// regression when it moves the bad way (`MetricTolerance::lower_is_better`) by more than
/// max(absolute, relative * |old|); a job whose status went from ok to anything else is a
/// regression; a job of `base` missing in `now` is a regression; a job only in `now` is
/// reported, not judged. Metrics in `tolerances.ignored` are reported as NotJudged.
/// Deterministic: the result depends on the records, not on their order in the files.
Comparison compare_results(const ResultsData& base, const ResultsData& now,
                           const Tolerances& tolerances);

/// Prints a Markdown table of the changed metrics and statuses (regressions first, then
/// missing jobs, improvements, status changes, new jobs and changes within the tolerance;
/// not-judged metrics are left out) and a one-line summary ending in "REGRESSION" or "OK".
void print_comparison(const Comparison& comparison, std::FILE* out);

/// The text `print_comparison` prints.
std::string format_comparison(const Comparison& comparison);

/// Writes a JUnit XML report: one <testsuite> per method, one <testcase> per job
/// (classname = method, name = job id), a <failure> for each regressed job listing its
/// regressed metrics (or the status change, or "missing"). Throws std::runtime_error when
/// the file cannot be written.
void write_junit_xml(const Comparison& comparison, const std::filesystem::path& path);

}  // namespace holebench::harness
