// The summary of a results file as data: one row per method x case kind x noise level with
// job and ok counts and the median and spread of a few key metrics, then the same rows as Markdown
// (the console summary), CSV and LaTeX. In the manner of nanobench: medians with a spread column,
// unstable rows flagged with what to do about them, every format from the same data.
#pragma once

#include "harness/results/markup_escape.h"  // markdown_cell, latex_escape: the tables' cells
#include "harness/results/results_reader.h"

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace holebench::harness::report {

/// The metrics the summary shows, in column order; a column appears only when some record
/// has the metric.
const std::vector<std::string>& summary_metrics();

/// When a row is flagged: only where its reader should act (docs/reports.md).
struct SummaryOptions {
  /// A column with fewer values than this is flagged "few" where values are missing because
  /// jobs of the row did not end ok (its median then stands for the survivors only). A metric
  /// that a method's ok jobs lack by nature (no new vertex, no classification) is no reason.
  std::size_t min_samples = 3;
  /// A column with at least min_samples values whose third quartile exceeds this multiple of
  /// its first is flagged "spread": the row's jobs fall into groups an order of magnitude
  /// apart (an exact closing beside an approximate one, a fold beside a clean fill), which
  /// its median hides. The method's time is not judged: its spread is the cases' sizes.
  double max_quartile_ratio = 10.0;
};

/// Order statistics of a set of values; quantiles by linear interpolation between the sorted
/// values (q(p) at position p * (n - 1), numpy's default).
struct Stats {
  std::size_t n = 0;
  double median = 0.0;
  double q1 = 0.0;
  double q3 = 0.0;
  double min = 0.0;
  double max = 0.0;
  double iqr() const { return q3 - q1; }
};

/// Stats of `values` (any order); nullopt when empty.
std::optional<Stats> compute_stats(std::vector<double> values);

struct SummaryRow {
  std::string method;
  std::string case_kind;       ///< "<case_family>/<case_kind>", e.g. "box/corner", "brep/k3/inner"
  double noise_percent = 0.0;  ///< the noise level of every job of the row
  std::size_t jobs = 0;
  std::size_t ok = 0;              ///< jobs with status ok
  std::size_t holes = 0;           ///< hole reports of the row's jobs (whatever their status)
  std::size_t fallback_holes = 0;  ///< of those, holes a stand-in handled (HoleRecord::fallback)
  std::vector<std::optional<Stats>> stats;  ///< one per SummaryTable::metrics; nullopt: no value
  /// Columns with 0 < n < min_samples where a job that is not ok lacks the value.
  std::vector<std::string> few;
  /// Columns with n >= min_samples and q3 > max_quartile_ratio * q1 (time excepted).
  std::vector<std::string> spread;
  std::vector<std::pair<double, double>> spread_quartiles;  ///< (q1, q3) of each `spread` column
  bool flagged() const { return !few.empty() || !spread.empty(); }
  /// fallback_holes / holes: the share of the row's holes that the method's own path did not
  /// handle (docs/results.md); nullopt when the row reports no hole.
  std::optional<double> fallback_share() const;
  /// "" or the reasons, e.g. "few: n=1 of 2 jobs, some not ok; spread:
  /// hausdorff_rel_diag (q1 1e-16, q3 0.0003)" (few in every column with values: the smallest
  /// count; otherwise the short columns by name).
  std::string note() const;
};

struct SummaryTable {
  std::vector<std::string> metrics;  ///< the columns present, in summary_metrics() order
  std::vector<SummaryRow> rows;      ///< sorted by method, then case kind
  SummaryOptions options;
};

/// Groups the records by method x case kind x noise level. A metric's values are those of
/// every record of the group that has it (whatever its status, seed or user).
SummaryTable summarize(const ResultsData& data, const SummaryOptions& options = {});

/// Markdown: a heading with the results' context, the table (jobs, ok, fallback share, then
/// median and IQR per metric, 3 significant digits), and a legend for the flags.
std::string summary_markdown(const ResultsData& data, const SummaryTable& table);

/// CSV, one row per method x case kind x noise level x metric:
/// method,case_kind,noise_percent,jobs,ok,holes,fallback_holes,metric,n,median,q1,q3,iqr,min,max,
/// note
/// (numbers in full precision; empty when the group has no value).
std::string summary_csv(const SummaryTable& table);

/// LaTeX (booktabs): a table of jobs, ok counts and fallback shares and one table per metric
/// (n, median, IQR, min, max); text escaped.
std::string summary_latex(const SummaryTable& table);

/// 3 significant digits, as every human-facing table shows numbers.
std::string short_number(double value);

/// short_number for LaTeX: "1.23e-05" becomes "$1.23\times10^{-5}$".
std::string latex_number(double value);

/// The opening of a booktabs table: caption, label `tab:holebench-<label>`, the tabular's
/// column spec, the header row and \midrule.
std::string latex_table_begin(const std::string& caption, const std::string& label,
                              const std::string& columns, const std::string& header);

/// The closing of latex_table_begin's table.
std::string latex_table_end();

/// A label part from a name: '_' becomes '-'.
std::string latex_label(std::string name);

}  // namespace holebench::harness::report
