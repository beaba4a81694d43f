#include "harness/outputs/report/leaderboard.h"

#include "harness/outputs/report/summary_table.h"
#include "metrics/metric_names.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <set>
#include <tuple>
#include <utility>

namespace holebench::harness::report {

const std::vector<LeaderboardColumn>& leaderboard_columns() {
  static const std::vector<LeaderboardColumn> columns{
      {"valid_share", "valid", true},
      {"closed_invalid_share", "closed but invalid", false},
      {"success_share", "success", true},
      {"fallback_share", "fallback", false},
      {"defect_share", "self-checked defect", false},
      {"hole_hausdorff_rel_diag_median", "hole Hausdorff (median)", false},
      {"hole_chamfer_l1_rel_diag_median", "hole Chamfer-L1 (median)", false},
      {"hole_f_score_1pct_fraction_mean", "hole F-score 1% (mean)", true},
      {"hole_normal_consistency_fraction_mean", "hole normal consistency (mean)", true},
      {"new_vertex_mean_error_rel_diag_median", "new-vertex error (median)", false},
      {"missing_edge_covered_fraction_mean", "missing-edge coverage (mean)", true},
      {"method_seconds_median", "method time s (median)", false},
  };
  return columns;
}

namespace {

using Records = std::vector<const JobRecord*>;

bool method_returned(JobStatus status) {
  return status == JobStatus::Ok || status == JobStatus::Partial ||
         status == JobStatus::MethodFailed;
}

bool succeeded(const JobRecord& record) {
  return record.status == JobStatus::Ok &&
         std::all_of(record.holes.begin(), record.holes.end(),
                     [](const HoleRecord& hole) { return hole.closed; });
}

bool valid(const JobRecord& record) {
  const double* flag = record.metric(metric_names::kValidRepairOk);
  return flag && *flag == 1.0;
}

// The decision measure of a job: its decision_handled_fraction; a job whose method did not
// return a result handled no hole (0); a returned job without the metric (no truth to compare
// with) is left out.
std::optional<double> decision_handled(const JobRecord& record) {
  if (const double* v = record.metric(metric_names::kDecisionHandledFraction))
    return *v;
  if (record.status == JobStatus::Ok || record.status == JobStatus::Partial)
    return std::nullopt;
  return 0.0;
}

std::optional<double> mean_decision_handled(const Records& records) {
  double sum = 0.0;
  std::size_t count = 0;
  for (const JobRecord* r : records) {
    if (const auto v = decision_handled(*r)) {
      sum += *v;
      ++count;
    }
  }
  return count == 0 ? std::nullopt : std::optional<double>(sum / static_cast<double>(count));
}

std::optional<double> share(std::size_t part, std::size_t whole) {
  if (whole == 0)
    return std::nullopt;
  return static_cast<double>(part) / static_cast<double>(whole);
}

std::optional<double> median_of_metric(const Records& records, const std::string& metric) {
  std::vector<double> values;
  for (const JobRecord* r : records) {
    if (const double* v = r->metric(metric))
      values.push_back(*v);
  }
  return values.empty() ? std::nullopt : std::optional<double>(median_of(values));
}

std::optional<double> mean_of_metric(const Records& records, const std::string& metric) {
  std::vector<double> values;
  for (const JobRecord* r : records) {
    if (const double* v = r->metric(metric))
      values.push_back(*v);
  }
  if (values.empty())
    return std::nullopt;
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

// Whether the records carry valid_repair_ok: not those written before it existed (a returned
// job with metrics but without the flag), where the valid share would read as 0.
bool validity_known(const Records& records) {
  const auto flagged = [](const JobRecord* r) {
    return r->metric(metric_names::kValidRepairOk) != nullptr;
  };
  const auto unflagged_result = [&](const JobRecord* r) {
    return (r->status == JobStatus::Ok || r->status == JobStatus::Partial) && !r->metrics.empty() &&
           !flagged(r);
  };
  return std::any_of(records.begin(), records.end(), flagged) ||
         std::none_of(records.begin(), records.end(), unflagged_result);
}

LeaderboardEntry make_entry(const std::string& method, const Records& records,
                            bool guides_by_design) {
  LeaderboardEntry entry;
  entry.method = method;
  entry.jobs = records.size();
  entry.judged_by_decision = guides_by_design;
  std::vector<double> times;
  for (const JobRecord* r : records) {
    entry.successes += succeeded(*r) ? 1 : 0;
    entry.valid_jobs += valid(*r) ? 1 : 0;
    entry.closed_invalid_jobs += succeeded(*r) && !valid(*r) ? 1 : 0;
    entry.holes += r->holes.size();
    for (const auto& hole : r->holes)
      entry.fallback_holes += hole.fallback.empty() ? 0 : 1;
    for (const auto& hole : r->holes)
      entry.defect_holes += hole.defect.empty() ? 0 : 1;
    if (method_returned(r->status))
      times.push_back(r->method_seconds);
  }
  const bool known = validity_known(records);
  entry.values = {
      guides_by_design ? mean_decision_handled(records)
      : known          ? share(entry.valid_jobs, entry.jobs)
                       : std::nullopt,
      known ? share(entry.closed_invalid_jobs, entry.jobs) : std::nullopt,
      share(entry.successes, entry.jobs),
      share(entry.fallback_holes, entry.holes),
      share(entry.defect_holes, entry.holes),
      median_of_metric(records, metric_names::kHoleHausdorffRelDiag),
      median_of_metric(records, metric_names::kHoleChamferL1RelDiag),
      mean_of_metric(records, metric_names::kHoleFScore1PctFraction),
      mean_of_metric(records, metric_names::kHoleNormalConsistencyFraction),
      median_of_metric(records, metric_names::kNewVertexMeanErrorRelDiag),
      mean_of_metric(records, metric_names::kMissingEdgeCoveredFraction),
      times.empty() ? std::nullopt : std::optional<double>(median_of(times)),
  };
  return entry;
}

/// Marks, per column, the entries whose value is the best of the group as the tables show it
/// (when at least two entries have a value).
void mark_best(std::vector<LeaderboardEntry>& entries) {
  const auto& columns = leaderboard_columns();
  for (auto& entry : entries)
    entry.best.assign(columns.size(), false);
  for (std::size_t c = 0; c < columns.size(); ++c) {
    std::optional<double> best;
    std::size_t with_value = 0;
    // The decision measure is not a valid share: it is not ranked against one.
    const auto comparable = [&](const LeaderboardEntry& entry) {
      return entry.values[c] && !(c == 0 && entry.judged_by_decision);
    };
    for (const auto& entry : entries) {
      const auto& v = entry.values[c];
      if (!comparable(entry))
        continue;
      ++with_value;
      if (!best || (columns[c].higher_is_better ? *v > *best : *v < *best))
        best = v;
    }
    if (with_value < 2)
      continue;
    // Equal as shown (3 significant digits) is equal: the reader sees no difference.
    for (auto& entry : entries)
      entry.best[c] = comparable(entry) && short_number(*entry.values[c]) == short_number(*best);
  }
}

/// "<stem>_lower_rel_diag" / "<stem>_upper_rel_diag" for "<stem>_rel_diag"; otherwise
/// "<metric>_lower" / "<metric>_upper".
std::string bound_name(const std::string& metric, const std::string& side) {
  const std::string unit = "_rel_diag";
  if (metric.size() > unit.size() &&
      metric.compare(metric.size() - unit.size(), unit.size(), unit) == 0) {
    return metric.substr(0, metric.size() - unit.size()) + "_" + side + unit;
  }
  return metric + "_" + side;
}

std::optional<BoundedValue> bounded_metric(const JobRecord& record, const std::string& metric) {
  const double* value = record.metric(metric);
  if (!value)
    return std::nullopt;
  const double* lower = record.metric(bound_name(metric, "lower"));
  const double* upper = record.metric(bound_name(metric, "upper"));
  return BoundedValue{lower ? *lower : *value, *value, upper ? *upper : *value};
}

using Variant = std::tuple<std::string, std::string, double, std::uint64_t>;

std::vector<LeaderboardPair> make_pairs(const std::map<std::string, Records>& by_method,
                                        const LeaderboardOptions& options) {
  std::map<std::string, std::map<Variant, const JobRecord*>> jobs;
  for (const auto& [method, records] : by_method) {
    for (const JobRecord* r : records)
      jobs[method][{r->job.case_id, r->job.user, r->job.noise_percent, r->job.seed}] = r;
  }
  std::vector<LeaderboardPair> pairs;
  for (auto first = jobs.begin(); first != jobs.end(); ++first) {
    for (auto second = std::next(first); second != jobs.end(); ++second) {
      LeaderboardPair pair;
      pair.first = first->first;
      pair.second = second->first;
      std::vector<BoundedValue> a, b;
      for (const auto& [variant, record] : first->second) {
        const auto other = second->second.find(variant);
        if (other == second->second.end())
          continue;
        ++pair.shared_jobs;
        const auto va = bounded_metric(*record, options.paired_metric);
        const auto vb = bounded_metric(*other->second, options.paired_metric);
        if (va && vb) {
          a.push_back(*va);
          b.push_back(*vb);
        }
      }
      pair.pairs = a.size();
      pair.comparison = compare_paired(a, b, options.test);
      const auto& c = pair.comparison;
      if (c.test.n > 0 && c.test.p_value < options.significance) {
        // The sign of the rank sums says which side the differences lean to.
        pair.better = c.test.w_minus > c.test.w_plus ? pair.first : pair.second;
      }
      pairs.push_back(std::move(pair));
    }
  }
  return pairs;
}

std::map<std::string, Records> by_method_of(const Records& records) {
  std::map<std::string, Records> by_method;
  for (const JobRecord* r : records)
    by_method[r->job.method_id].push_back(r);
  return by_method;
}

/// One entry per method, best values marked.
std::vector<LeaderboardEntry> entries_of(const std::map<std::string, Records>& by_method,
                                         const std::set<std::string>& guiding) {
  std::vector<LeaderboardEntry> entries;
  for (const auto& [method, records] : by_method)
    entries.push_back(make_entry(method, records, guiding.count(method) > 0));
  mark_best(entries);
  return entries;
}

LeaderboardGroup make_group(const std::string& family, const std::string& kind,
                            const Records& records, const std::set<std::string>& guiding,
                            const LeaderboardOptions& options) {
  LeaderboardGroup group;
  group.family = family;
  group.kind = kind;
  const auto by_method = by_method_of(records);
  group.entries = entries_of(by_method, guiding);
  group.pairs = make_pairs(by_method, options);
  return group;
}

std::string bold_if(bool best, const std::string& text, const char* open, const char* close) {
  return best && text != "-" ? open + text + close : text;
}

std::string kind_label(const LeaderboardGroup& group) {
  return group.is_family() ? "all" : group.kind;
}

}  // namespace

std::set<std::string> methods_that_guide(const ResultsData& data) {
  std::set<std::string> guiding;
  for (const auto& record : data.records) {
    if (std::any_of(record.holes.begin(), record.holes.end(),
                    [](const HoleRecord& hole) { return hole.arrow && !hole.closed; }))
      guiding.insert(record.job.method_id);
  }
  return guiding;
}

std::string leaderboard_entry_cell(const LeaderboardEntry& entry, std::size_t column) {
  const std::string text = leaderboard_cell(entry.values[column]);
  return column == 0 && entry.judged_by_decision && text != "-" ? text + " (decision)" : text;
}

Leaderboard compute_leaderboard(const ResultsData& data, const LeaderboardOptions& options) {
  Leaderboard board;
  board.options = options;
  const std::set<std::string> guiding = methods_that_guide(data);
  std::map<std::string, std::map<std::string, Records>> families;
  for (const auto& record : data.records)
    families[record.case_family][record.case_kind].push_back(&record);
  for (const auto& [family, kinds] : families) {
    Records all;
    for (const auto& [kind, records] : kinds)
      all.insert(all.end(), records.begin(), records.end());
    board.groups.push_back(make_group(family, "", all, guiding, options));
    for (const auto& [kind, records] : kinds)
      board.groups.push_back(make_group(family, kind, records, guiding, options));
  }
  return board;
}

std::vector<LeaderboardEntry> method_totals(const ResultsData& data) {
  Records all;
  for (const auto& record : data.records)
    all.push_back(&record);
  return entries_of(by_method_of(all), methods_that_guide(data));
}

std::string leaderboard_cell(const std::optional<double>& value) {
  return value ? short_number(*value) : std::string("-");
}

std::string leaderboard_p_value(const LeaderboardPair& pair) {
  if (pair.comparison.test.n == 0)
    return pair.pairs == 0 ? "-" : "1";
  return fmt::format("{:.2g}", pair.comparison.test.p_value);
}

std::string leaderboard_markdown(const Leaderboard& board) {
  const auto& columns = leaderboard_columns();
  std::string out = "# holebench leaderboard\n";
  for (const auto& group : board.groups) {
    if (group.is_family()) {
      out += fmt::format("\n## {}\n\n| target kind | method | jobs |", markdown_cell(group.family));
      std::string rule = "| --- | --- | ---: |";
      for (const auto& column : columns) {
        out += " " + column.header + " |";
        rule += " ---: |";
      }
      out += "\n" + rule + "\n";
    }
    for (const auto& entry : group.entries) {
      out += fmt::format("| {} | {} | {} |", markdown_cell(kind_label(group)),
                         markdown_cell(entry.method), entry.jobs);
      for (std::size_t c = 0; c < columns.size(); ++c)
        out += " " + bold_if(entry.best[c], leaderboard_entry_cell(entry, c), "**", "**") + " |";
      out += "\n";
    }
  }
  out += fmt::format(
      "\n## Paired comparisons: `{}`\n\n| family | target kind | A | B | jobs | pairs | A better "
      "| tie | B better | p (Wilcoxon) | better |\n| --- | --- | --- | --- | ---: | ---: | ---: "
      "| ---: | ---: | ---: | --- |\n",
      board.options.paired_metric);
  for (const auto& group : board.groups) {
    for (const auto& pair : group.pairs) {
      const auto& c = pair.comparison;
      out += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
                         markdown_cell(group.family), markdown_cell(kind_label(group)),
                         markdown_cell(pair.first), markdown_cell(pair.second), pair.shared_jobs,
                         pair.pairs, c.wins, c.ties, c.losses, leaderboard_p_value(pair),
                         pair.better.empty() ? "-" : markdown_cell(pair.better));
    }
  }
  out += fmt::format(
      "\n`valid`: share of jobs whose output is a valid repair (`valid_repair_ok`: every hole "
      "closed, the output closed, manifold and consistently oriented, no self-intersection "
      "with a new face, the input away from the holes unchanged); a failed job is not valid. "
      "For a method that guides holes by design (an open hole with a guidance arrow in its "
      "jobs) the cell is instead the decision measure, marked `(decision)`: the mean share of "
      "holes handled as the truth's decision says (closed where it says close, guided where it "
      "says guide; `decision_handled_fraction`, a failed job 0), not ranked against valid "
      "shares. `closed but invalid`: share of jobs with status ok and every hole closed that "
      "are not valid. `hole Chamfer-L1`, `hole F-score 1%`, `hole normal consistency`: the "
      "literature's metrics over the hole region (docs/metrics.md). "
      "`success`: share of jobs with status ok and every hole closed. `fallback`: share of the "
      "hole records (jobs of every status) a stand-in handled instead of the method's own path. "
      "`self-checked defect`: share of the hole records whose method's check of its own patch "
      "found a defect (a patch that intersects itself or the mesh around the hole); methods "
      "that do not check have 0. Rows named `<method>_plus` are the papers' methods with the "
      "project's departures; the row named after the paper runs its steps as written. "
      "Medians and the mean are over the jobs that have the metric (a failed job has none; read "
      "them beside `success`); lengths are relative to the bounding-box diagonal; the method "
      "time is over the jobs whose method returned. Bold: the best of the rows of the same "
      "target kind.\n\n"
      "Paired comparisons: on the jobs both methods ran (same case, noise, seed and user; "
      "`jobs`), of which `pairs` have `{0}` on both sides. `A better`: A's error interval "
      "(for a Hausdorff distance [value, upper bound]) lies wholly below B's; `tie`: the intervals "
      "overlap, so the error bounds "
      "cannot order them. p: two-sided Wilcoxon signed-rank test on the differences A - B, "
      "ties counted as 0 and dropped (exact up to {1} non-zero differences, else the normal "
      "approximation with the tie correction). `better`: the method the differences favour "
      "when p < {2:g}.\n",
      board.options.paired_metric, board.options.test.max_exact_n, board.options.significance);
  return out;
}

std::string leaderboard_latex(const Leaderboard& board) {
  const auto& columns = leaderboard_columns();
  std::string out =
      "% holebench leaderboard tables (booktabs). Generated by `holebench report`; do not "
      "edit.\n% Needs \\usepackage{booktabs}.\n";
  const auto latex_cell = [](const std::optional<double>& v) {
    return v ? latex_number(*v) : std::string("--");
  };

  std::string header = "Target kind & Method & Jobs";
  std::string spec = "llr";
  for (const auto& column : columns) {
    header += " & " + latex_escape(column.header);
    spec += "r";
  }
  for (std::size_t i = 0; i < board.groups.size(); ++i) {
    const auto& group = board.groups[i];
    if (group.is_family()) {
      out += latex_table_begin(
          fmt::format("Leaderboard of the {} cases; bold: the best of a target kind; $^{{d}}$: "
                      "the decision measure of a method that guides by design, in place of "
                      "its valid share",
                      latex_escape(group.family)),
          "leaderboard-" + latex_label(group.family), spec, header);
    } else {
      out += "    \\midrule\n";
    }
    for (std::size_t e = 0; e < group.entries.size(); ++e) {
      const auto& entry = group.entries[e];
      out += fmt::format("    {} & {} & {}", e == 0 ? latex_escape(kind_label(group)) : "",
                         latex_escape(entry.method), entry.jobs);
      for (std::size_t c = 0; c < columns.size(); ++c)
        out += " & " + bold_if(entry.best[c], latex_cell(entry.values[c]), "\\textbf{", "}") +
               (c == 0 && entry.judged_by_decision && entry.values[c] ? "$^{d}$" : "");
      out += " \\\\\n";
    }
    if (i + 1 == board.groups.size() || board.groups[i + 1].is_family())
      out += latex_table_end();
  }

  for (std::size_t i = 0; i < board.groups.size(); ++i) {
    const auto& group = board.groups[i];
    if (group.is_family()) {
      out += latex_table_begin(
          fmt::format("Paired comparisons of \\texttt{{{}}} on the {} cases: jobs both "
                      "methods ran; ties within the error bounds; two-sided Wilcoxon "
                      "signed-rank p-value",
                      latex_escape(board.options.paired_metric), latex_escape(group.family)),
          "paired-" + latex_label(group.family), "lllrrrrrl",
          "Target kind & A & B & Pairs & A better & Tie & B better & $p$ & Better");
    }
    for (const auto& pair : group.pairs) {
      const auto& c = pair.comparison;
      out += fmt::format("    {} & {} & {} & {} & {} & {} & {} & {} & {} \\\\\n",
                         latex_escape(kind_label(group)), latex_escape(pair.first),
                         latex_escape(pair.second), pair.pairs, c.wins, c.ties, c.losses,
                         pair.pairs == 0 ? std::string("--") : latex_number(c.test.p_value),
                         pair.better.empty() ? "--" : latex_escape(pair.better));
    }
    if (i + 1 == board.groups.size() || board.groups[i + 1].is_family())
      out += latex_table_end();
  }
  return out;
}

}  // namespace holebench::harness::report
