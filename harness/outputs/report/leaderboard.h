// The leaderboard of a results file, as data: per case family, and per target kind within it,
// each method's valid share (or, for a method that guides by design, its decision measure),
// closed-but-invalid share, success share, fallback and defect shares, median hole Hausdorff
// distance and Chamfer-L1, mean hole F-score and normal consistency, median new-vertex error,
// mean missing-edge coverage and median method time, with the best value of each column
// marked; then, per family and kind, every pair of methods compared on the jobs
// both ran (win/tie/loss counts within the metric's error bound and a Wilcoxon signed-rank
// p-value, core/statistics.h). Formatted as Markdown and LaTeX here, as HTML by report.cpp.
// The definitions are in docs/reports.md.
#pragma once

#include "core/statistics.h"
#include "harness/results/results_reader.h"
#include "metrics/metric_names.h"

#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace holebench::harness::report {

struct LeaderboardOptions {
  /// The metric the paired comparisons judge (lower is better). Its interval is
  /// [<stem>_lower_rel_diag, <stem>_upper_rel_diag] where the record has those bounds,
  /// otherwise the value itself on that side (the hole Hausdorff distance is a lower bound:
  /// its interval is [hole_hausdorff_rel_diag, hole_hausdorff_upper_rel_diag]).
  std::string paired_metric = metric_names::kHoleHausdorffRelDiag;
  /// A pair's verdict names the better method when the p-value is below this.
  double significance = 0.05;
  SignedRankOptions test;  ///< exact p-values up to test.max_exact_n pairs
};

/// A leaderboard column: what it shows and which way is better.
struct LeaderboardColumn {
  std::string key;     ///< short name (CSV-like, e.g. "success_share")
  std::string header;  ///< human header, e.g. "hole Hausdorff (median)"
  bool higher_is_better = false;
};

/// The columns in order: valid share (the decision measure for a method that guides by design),
/// closed-but-invalid share, success share, fallback share, self-checked defect share, median
/// hole Hausdorff distance, median hole Chamfer-L1, mean hole F-score at 1 %, mean hole normal
/// consistency, median new-vertex error, mean missing-edge coverage, median method time.
const std::vector<LeaderboardColumn>& leaderboard_columns();

/// One method in one group (a family, or a target kind of a family).
struct LeaderboardEntry {
  std::string method;
  std::size_t jobs = 0;
  std::size_t successes = 0;            ///< status ok and every hole closed
  std::size_t valid_jobs = 0;           ///< valid_repair_ok = 1
  std::size_t closed_invalid_jobs = 0;  ///< successes that are not valid
  /// The method guides holes by design (methods_that_guide): the first column holds its
  /// decision measure (mean decision_handled_fraction) instead of the valid share, unranked.
  bool judged_by_decision = false;
  std::size_t holes = 0;           ///< hole records of the jobs (every status)
  std::size_t fallback_holes = 0;  ///< of those, with a non-empty `fallback`
  /// Of those, with a defect the method found in its own result (HoleReport::defect, e.g. a
  /// self-intersecting patch).
  std::size_t defect_holes = 0;
  /// One per leaderboard_columns(); nullopt: no job of the group has the value.
  std::vector<std::optional<double>> values;
  /// One per column: the best value of the group's methods (ties at the tables' precision,
  /// 3 significant digits, all marked; only when at least two methods have a value).
  std::vector<bool> best;
};

/// Two methods on the jobs both ran in one group (same case id, noise, seed and user).
struct LeaderboardPair {
  std::string first;            ///< the method earlier in name order
  std::string second;           ///< the later one
  std::size_t shared_jobs = 0;  ///< jobs both ran
  std::size_t pairs = 0;        ///< of those, with the paired metric on both sides
  PairedComparison comparison;  ///< wins = first better, losses = second better
  /// The better method when comparison.test.p_value < significance, else empty.
  std::string better;
};

struct LeaderboardGroup {
  std::string family;  ///< case_family, e.g. "brep"
  std::string kind;    ///< case_kind, e.g. "k3/inner"; empty: every kind of the family
  std::vector<LeaderboardEntry> entries;  ///< sorted by method
  std::vector<LeaderboardPair> pairs;     ///< sorted by (first, second)
  bool is_family() const { return kind.empty(); }
};

struct Leaderboard {
  /// For each family (sorted) its whole-family group, then one per target kind (sorted).
  std::vector<LeaderboardGroup> groups;
  LeaderboardOptions options;
};

/// Computes the leaderboard of `data`. Shares count every job of the group whatever its
/// status; the medians and the mean are over the jobs that have the metric (a failed job
/// has none: read them beside the success share); the method time is `method_seconds` of the
/// jobs whose method returned (status ok, partial or method_failed). Deterministic.
Leaderboard compute_leaderboard(const ResultsData& data, const LeaderboardOptions& options = {});

/// Each method's entry over every record of `data` (all families and kinds), sorted by
/// method, best values marked: the headline numbers of a run (`holebench history`).
std::vector<LeaderboardEntry> method_totals(const ResultsData& data);

/// A column's value as the tables show it (3 significant digits; "-" when absent).
std::string leaderboard_cell(const std::optional<double>& value);

/// An entry's cell: leaderboard_cell, with " (decision)" after a decision measure.
std::string leaderboard_entry_cell(const LeaderboardEntry& entry, std::size_t column);

/// The methods that guide holes by design: some job of theirs has a hole left open with a
/// guidance arrow.
std::set<std::string> methods_that_guide(const ResultsData& data);

/// A pair's p-value as the tables show it ("-" without pairs).
std::string leaderboard_p_value(const LeaderboardPair& pair);

/// Markdown: per family one leaderboard table (the family's rows, then each target kind's,
/// best values in bold), then per family the paired comparisons, and a legend.
std::string leaderboard_markdown(const Leaderboard& board);

/// LaTeX (booktabs): per family one leaderboard table (best values in \textbf) and one table
/// of paired comparisons.
std::string leaderboard_latex(const Leaderboard& board);

}  // namespace holebench::harness::report
