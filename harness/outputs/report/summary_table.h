// The summary of a results file as data: one row per method x case kind with job and ok
// counts and the median and spread of a few key metrics, then the same rows as Markdown (the
// console summary), CSV and LaTeX. In the manner of nanobench: medians with a spread column,
// unstable rows flagged with what to do about them, every format from the same data.
#pragma once

#include "harness/results/markup_escape.h"  // markdown_cell, latex_escape: the tables' cells
#include "harness/results/results_reader.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace holebench::harness::report {

/// The metrics the summary shows, in column order; a column appears only when some record
/// has the metric.
const std::vector<std::string>& summary_metrics();

struct SummaryOptions {
  /// A row with fewer values than this in some column is flagged "few".
  std::size_t min_samples = 3;
  /// A column whose IQR exceeds this fraction of |median| is flagged "spread".
  double max_relative_spread = 0.5;
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
  std::string case_kind;  ///< "<case_family>/<case_kind>", e.g. "box/corner", "brep/k3/inner"
  std::size_t jobs = 0;
  std::size_t ok = 0;              ///< jobs with status ok
  std::size_t holes = 0;           ///< hole reports of the row's jobs (whatever their status)
  std::size_t fallback_holes = 0;  ///< of those, holes a stand-in handled (HoleRecord::fallback)
  std::vector<std::optional<Stats>> stats;  ///< one per SummaryTable::metrics; nullopt: no value
  std::vector<std::string> few;             ///< columns with 0 < n < min_samples
  std::vector<std::string> spread;          ///< columns with IQR > max_relative_spread * |median|
  bool flagged() const { return !few.empty() || !spread.empty(); }
  /// fallback_holes / holes: the share of the row's holes that the method's own path did not
  /// handle (docs/results.md); nullopt when the row reports no hole.
  std::optional<double> fallback_share() const;
  /// "" or e.g. "few: n=2; spread: hausdorff_rel_diag" (few in every column with values: the
  /// smallest count; otherwise the short columns by name).
  std::string note() const;
};

struct SummaryTable {
  std::vector<std::string> metrics;  ///< the columns present, in summary_metrics() order
  std::vector<SummaryRow> rows;      ///< sorted by method, then case kind
  SummaryOptions options;
};

/// Groups the records by method x case kind. A metric's values are those of every record of
/// the group that has it (whatever its status, noise, seed or user).
SummaryTable summarize(const ResultsData& data, const SummaryOptions& options = {});

/// Markdown: a heading with the results' context, the table (jobs, ok, fallback share, then
/// median and IQR per metric, 3 significant digits), and a legend for the flags.
std::string summary_markdown(const ResultsData& data, const SummaryTable& table);

/// CSV, one row per method x case kind x metric:
/// method,case_kind,jobs,ok,holes,fallback_holes,metric,n,median,q1,q3,iqr,min,max,note
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
