#include "harness/outputs/report/summary_table.h"

#include "core/statistics.h"
#include "metrics/metric_names.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <tuple>
#include <utility>

namespace holebench::harness::report {

const std::vector<std::string>& summary_metrics() {
  static const std::vector<std::string> metrics{
      metric_names::kHausdorffRelDiag, metric_names::kHoleMeanDistanceRelDiag,
      metric_names::kNewVertexMeanErrorRelDiag, metric_names::kClassificationAllCorrectFraction,
      metric_names::kTimeMethodS};
  return metrics;
}

namespace {

std::string join(const std::vector<std::string>& items, const char* separator) {
  std::string out;
  for (const auto& item : items)
    out += (out.empty() ? "" : separator) + item;
  return out;
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos)
    return text;
  std::string out = "\"";
  for (char c : text)
    out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

std::string short_number(double value) {
  return fmt::format("{:.3g}", value);
}

std::string latex_number(double value) {
  const std::string text = short_number(value);
  const auto e = text.find('e');
  if (e == std::string::npos)
    return text;
  const int exponent = std::stoi(text.substr(e + 1));
  return fmt::format("${}\\times10^{{{}}}$", text.substr(0, e), exponent);
}

std::optional<Stats> compute_stats(std::vector<double> values) {
  if (values.empty())
    return std::nullopt;
  std::sort(values.begin(), values.end());
  Stats stats;
  stats.n = values.size();
  stats.median = quantile(values, 0.5);
  stats.q1 = quantile(values, 0.25);
  stats.q3 = quantile(values, 0.75);
  stats.min = values.front();
  stats.max = values.back();
  return stats;
}

std::string SummaryRow::note() const {
  std::string note;
  if (!few.empty()) {
    // Every column with values short (the row has few jobs): the smallest count says it all;
    // otherwise the short columns are named.
    std::size_t with_values = 0, fewest = 0;
    for (const auto& s : stats) {
      if (!s)
        continue;
      fewest = with_values == 0 ? s->n : std::min(fewest, s->n);
      ++with_values;
    }
    note += few.size() == with_values
                ? fmt::format("few: n={} of {} jobs, some not ok", fewest, jobs)
                : "few: " + join(few, ", ") + " (missing where jobs were not ok)";
  }
  if (!spread.empty()) {
    std::vector<std::string> quartiles;
    for (std::size_t i = 0; i < spread.size(); ++i) {
      const auto [q1, q3] = spread_quartiles[i];
      quartiles.push_back(
          fmt::format("{} (q1 {}, q3 {})", spread[i], short_number(q1), short_number(q3)));
    }
    note += (note.empty() ? "" : "; ") + ("spread: " + join(quartiles, ", "));
  }
  return note;
}

std::optional<double> SummaryRow::fallback_share() const {
  if (holes == 0)
    return std::nullopt;
  return static_cast<double>(fallback_holes) / static_cast<double>(holes);
}

SummaryTable summarize(const ResultsData& data, const SummaryOptions& options) {
  SummaryTable table;
  table.options = options;
  for (const auto& metric : summary_metrics()) {
    const bool present = std::any_of(data.records.begin(), data.records.end(),
                                     [&](const JobRecord& r) { return r.metric(metric); });
    if (present)
      table.metrics.push_back(metric);
  }

  std::map<std::tuple<std::string, std::string, double>, std::vector<const JobRecord*>> groups;
  for (const auto& record : data.records) {
    groups[{record.job.method_id, record.case_family + "/" + record.case_kind,
            record.job.noise_percent}]
        .push_back(&record);
  }
  for (const auto& [key, records] : groups) {
    SummaryRow row;
    std::tie(row.method, row.case_kind, row.noise_percent) = key;
    row.jobs = records.size();
    row.ok = static_cast<std::size_t>(
        std::count_if(records.begin(), records.end(),
                      [](const JobRecord* r) { return r->status == JobStatus::Ok; }));
    for (const JobRecord* record : records) {
      row.holes += record->holes.size();
      for (const auto& hole : record->holes)
        row.fallback_holes += hole.fallback.empty() ? 0 : 1;
    }
    for (const auto& metric : table.metrics) {
      std::vector<double> values;
      bool missing_where_not_ok = false;
      for (const JobRecord* record : records) {
        if (const double* value = record->metric(metric))
          values.push_back(*value);
        else if (record->status != JobStatus::Ok)
          missing_where_not_ok = true;
      }
      const auto stats = compute_stats(values);
      if (stats && stats->n < options.min_samples && missing_where_not_ok)
        row.few.push_back(metric);
      if (stats && stats->n >= options.min_samples && metric != metric_names::kTimeMethodS &&
          stats->q3 > 0.0 && stats->q3 > options.max_quartile_ratio * stats->q1) {
        row.spread.push_back(metric);
        row.spread_quartiles.emplace_back(stats->q1, stats->q3);
      }
      row.stats.push_back(stats);
    }
    table.rows.push_back(std::move(row));
  }
  return table;
}

std::string summary_markdown(const ResultsData& data, const SummaryTable& table) {
  const auto& c = data.context;
  std::size_t ok = 0;
  for (const auto& record : data.records)
    ok += record.status == JobStatus::Ok ? 1 : 0;
  std::string out = "# holebench summary\n\n";
  out += fmt::format("Suite `{}`, code `{}`, {} build, run {}; {} jobs, {} ok.\n\n",
                     c.suite.empty() ? "?" : c.suite, c.code_version.empty() ? "?" : c.code_version,
                     c.build_type.empty() ? "?" : c.build_type,
                     c.created_utc.empty() ? "?" : c.created_utc, data.records.size(), ok);

  out += "| method | case kind | noise % | jobs | ok | fallback |";
  std::string rule = "| --- | --- | ---: | ---: | ---: | ---: |";
  for (const auto& metric : table.metrics) {
    out += fmt::format(" {} | IQR |", metric);
    rule += " ---: | ---: |";
  }
  out += " note |\n" + rule + " --- |\n";
  for (const auto& row : table.rows) {
    const auto share = row.fallback_share();
    out += fmt::format("| {} | {} | {:g} | {} | {} | {} |", markdown_cell(row.method),
                       markdown_cell(row.case_kind), row.noise_percent, row.jobs, row.ok,
                       share ? short_number(*share) : std::string("-"));
    for (const auto& stats : row.stats) {
      out +=
          stats ? fmt::format(" {} | {} |", short_number(stats->median), short_number(stats->iqr()))
                : std::string(" - | - |");
    }
    out += fmt::format(" {} |\n", row.note());
  }
  const auto flagged = std::count_if(table.rows.begin(), table.rows.end(),
                                     [](const SummaryRow& r) { return r.flagged(); });
  out += fmt::format(
      "\n`fallback`: the share of the row's hole reports (jobs of every status) that a "
      "stand-in handled instead of the method's own path (the hole records' `fallback`; `-`: "
      "no hole reported). A row is one method, one case kind and one noise level; its medians are "
      "over every job of the row that has the metric (all seeds and users); IQR = q3 - q1 "
      "(linear interpolation); `-`: no job of the row has it. Lengths are relative to the "
      "bounding-box diagonal (`_rel_diag`), times in seconds.\n\n"
      "{} of {} rows flagged, each with its reason. `few`: fewer than {} values in that column "
      "because jobs of the row did not end ok, so the median stands for the survivors only: "
      "read the failed jobs' messages. `spread`: the third quartile above {:g} times the first "
      "(time excepted): the row's jobs fall into groups an order of magnitude apart, which the "
      "median hides; read the per-job values (results.csv).\n",
      flagged, table.rows.size(), table.options.min_samples, table.options.max_quartile_ratio);
  return out;
}

std::string summary_csv(const SummaryTable& table) {
  std::string out =
      "method,case_kind,noise_percent,jobs,ok,holes,fallback_holes,metric,n,median,q1,q3,iqr,min,"
      "max,note\n";
  for (const auto& row : table.rows) {
    for (std::size_t i = 0; i < table.metrics.size(); ++i) {
      out += fmt::format("{},{},{},{},{},{},{},{},", csv_field(row.method),
                         csv_field(row.case_kind), row.noise_percent, row.jobs, row.ok, row.holes,
                         row.fallback_holes, table.metrics[i]);
      if (const auto& s = row.stats[i]) {
        out += fmt::format("{},{},{},{},{},{},{},", s->n, s->median, s->q1, s->q3, s->iqr(), s->min,
                           s->max);
      } else {
        out += "0,,,,,,,";
      }
      out += csv_field(row.note()) + "\n";
    }
  }
  return out;
}

std::string latex_table_begin(const std::string& caption, const std::string& label,
                              const std::string& columns, const std::string& header) {
  return fmt::format(
      "\n\\begin{{table}}[ht]\n  \\centering\n  \\caption{{{}}}\n  \\label{{tab:holebench-{}}}\n"
      "  \\begin{{tabular}}{{{}}}\n    \\toprule\n    {} \\\\\n    \\midrule\n",
      caption, label, columns, header);
}

std::string latex_table_end() {
  return "    \\bottomrule\n  \\end{tabular}\n\\end{table}\n";
}

std::string latex_label(std::string name) {
  std::replace(name.begin(), name.end(), '_', '-');
  return name;
}

std::string summary_latex(const SummaryTable& table) {
  std::string out =
      "% holebench summary tables (booktabs). Generated by `holebench report`; do not edit.\n"
      "% Needs \\usepackage{booktabs}.\n";
  const auto begin_table = [&](const std::string& caption, const std::string& label,
                               const std::string& columns, const std::string& header) {
    out += latex_table_begin(caption, label, columns, header);
  };
  const auto end_table = [&] { out += latex_table_end(); };
  // The method is written on the first row of its block only.
  const auto method_cell = [&](std::size_t i) {
    const auto& rows = table.rows;
    return i > 0 && rows[i - 1].method == rows[i].method ? std::string()
                                                         : latex_escape(rows[i].method);
  };

  begin_table(
      "Jobs per method, case kind and noise level; fallback share: holes a stand-in handled",
      "jobs", "llrrrr", "Method & Case kind & Noise \\% & Jobs & OK & Fallback share");
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const auto& row = table.rows[i];
    const auto share = row.fallback_share();
    out += fmt::format("    {} & {} & {:g} & {} & {} & {} \\\\\n", method_cell(i),
                       latex_escape(row.case_kind), row.noise_percent, row.jobs, row.ok,
                       share ? latex_number(*share) : std::string("--"));
  }
  end_table();

  for (std::size_t m = 0; m < table.metrics.size(); ++m) {
    const auto& metric = table.metrics[m];
    begin_table(fmt::format("\\texttt{{{}}}: median, interquartile range, minimum and maximum",
                            latex_escape(metric)),
                latex_label(metric), "llrrrrrr",
                "Method & Case kind & Noise \\% & $n$ & Median & IQR & Min & Max");
    for (std::size_t i = 0; i < table.rows.size(); ++i) {
      const auto& row = table.rows[i];
      out += fmt::format("    {} & {} & {:g} & ", method_cell(i), latex_escape(row.case_kind),
                         row.noise_percent);
      if (const auto& s = row.stats[m]) {
        out += fmt::format("{} & {} & {} & {} & {} \\\\\n", s->n, latex_number(s->median),
                           latex_number(s->iqr()), latex_number(s->min), latex_number(s->max));
      } else {
        out += "0 & -- & -- & -- & -- \\\\\n";
      }
    }
    end_table();
  }
  return out;
}

}  // namespace holebench::harness::report
