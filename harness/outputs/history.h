// `holebench history RESULTS.json... --out DIR`: how the headline numbers of successive runs
// (nightlies) moved, per method, with the regressions `holebench compare` flags between
// consecutive runs marked on the lines, in the manner of airspeed velocity's benchmark
// histories. Computed as data (`compute_history`), drawn separately (`history_html`: inline
// SVG, no script). The definitions are in docs/reports.md.
#pragma once

#include "harness/results/results_reader.h"
#include "harness/results/tolerances.h"

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace holebench::harness {

struct HistoryOptions {
  /// The tolerances that judge each consecutive pair of runs, given the suite the newer run's
  /// context names; sets `*used_defaults` where they are the built-in ones. The command line
  /// answers from the suites as `holebench compare` does (comparison_tolerances,
  /// harness/run/suite.h). Unset: the built-in tolerances for every pair.
  std::function<Tolerances(const std::string& named_suite, bool* used_defaults)>
      tolerances_of_suite;
  /// Job ids listed per marked regression (the rest are counted).
  std::size_t listed_jobs = 5;
};

/// One results file of the history.
struct HistoryRun {
  std::string name;  ///< as given (the file's path)
  ResultsData data;
  /// "2026-12-01 80e643f": the date of its context's created_utc and its code version.
  std::string label() const;
};

/// A headline metric: a column of the leaderboard's method totals (method_totals()).
struct HistoryMetric {
  std::string key;    ///< leaderboard_columns() key, e.g. "success_share"
  std::string title;  ///< e.g. "Success share (ok, every hole closed)"
};

/// The headline metrics in the page's order: median hole Hausdorff distance, success share,
/// fallback share, median method time.
const std::vector<HistoryMetric>& history_metrics();

struct History {
  std::vector<HistoryRun> runs;      ///< oldest first: by created_utc, then code version
  std::vector<std::string> methods;  ///< every method of any run, sorted
  /// values[m][k][r]: history_metrics()[m] of methods[k] in runs[r] (over all its jobs);
  /// nullopt when the run has no such value (or not the method).
  std::vector<std::vector<std::vector<std::optional<double>>>> values;
  /// regressions[k][r]: the ids of the jobs of methods[k] that `compare` flags as regressed
  /// from runs[r - 1] to runs[r] (empty for r = 0).
  std::vector<std::vector<std::vector<std::string>>> regressions;
  std::vector<std::string> notes;  ///< e.g. which tolerances judged
  HistoryOptions options;
};

/// Orders the runs (stably: equal date and version keep the given order), computes each
/// method's headline numbers per run and compares each run with the one before it
/// (compare_results). Deterministic.
History compute_history(std::vector<HistoryRun> runs, const HistoryOptions& options = {});

/// The page: per headline metric a chart (a line per method, runs along the x axis, each
/// flagged point circled in red with the regressed jobs in its tooltip), the runs, and a
/// table of the flagged regressions.
std::string history_html(const History& history);

/// Writes out_dir/history.html (creating out_dir) and returns its path. Throws
/// std::runtime_error when it cannot be written.
std::filesystem::path write_history(const History& history, const std::filesystem::path& out_dir);

}  // namespace holebench::harness
