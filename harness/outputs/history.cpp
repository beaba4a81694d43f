#include "harness/outputs/history.h"

#include "core/atomic_file.h"

#include "harness/outputs/report/leaderboard.h"
#include "harness/outputs/report/summary_table.h"
#include "harness/results/compare.h"
#include "harness/results/markup_escape.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <tuple>

namespace holebench::harness {

std::string HistoryRun::label() const {
  const auto& c = data.context;
  const std::string date = c.created_utc.substr(0, std::min<std::size_t>(10, c.created_utc.size()));
  return fmt::format("{} {}", date.empty() ? "?" : date,
                     c.code_version.empty() ? "?" : c.code_version);
}

const std::vector<HistoryMetric>& history_metrics() {
  static const std::vector<HistoryMetric> metrics{
      {"hole_hausdorff_rel_diag_median",
       "Median hole Hausdorff distance (hole_hausdorff_rel_diag, relative to the diagonal)"},
      {"valid_share", "Valid share (valid_repair_ok; a guiding method's decision measure)"},
      {"success_share", "Success share (status ok, every hole closed)"},
      {"fallback_share", "Fallback share (holes a stand-in handled / all holes)"},
      {"method_seconds_median", "Median method time (s)"},
  };
  return metrics;
}

namespace {

std::size_t column_index(const std::string& key) {
  const auto& columns = report::leaderboard_columns();
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (columns[c].key == key)
      return c;
  }
  throw std::logic_error("no leaderboard column " + key);
}

std::string escape(const std::string& text) {
  return xml_escape(text, true);
}

/// Shares are drawn on [0, 1]; everything else on [0, 1.1 * max].
bool is_share(const std::string& key) {
  return key.size() > 6 && key.compare(key.size() - 6, 6, "_share") == 0;
}

const char* color(std::size_t i) {
  static const char* palette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd",
                                  "#8c564b", "#e377c2", "#7f7f7f", "#17becf"};
  return palette[i % (sizeof(palette) / sizeof(palette[0]))];
}

std::string regression_tooltip(const History& history, std::size_t k, std::size_t r) {
  const auto& jobs = history.regressions[k][r];
  std::string text = fmt::format("{}: {} job(s) regressed from run {} to run {}",
                                 history.methods[k], jobs.size(), r, r + 1);
  for (std::size_t j = 0; j < jobs.size() && j < history.options.listed_jobs; ++j)
    text += "\n" + jobs[j];
  if (jobs.size() > history.options.listed_jobs)
    text += fmt::format("\n... and {} more", jobs.size() - history.options.listed_jobs);
  return text;
}

std::string chart_svg(const History& history, std::size_t m) {
  const double width = 760, height = 260, left = 70, right = 190, top = 15, bottom = 40;
  const double plot_w = width - left - right, plot_h = height - top - bottom;
  const auto& values = history.values[m];
  const std::size_t runs = history.runs.size();
  // Shares on [0, 1]; other numbers on [0, 1.1 max], or on a log scale when they are all
  // positive and span more than a factor of 20 (distances and times do).
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const auto& per_method : values) {
    for (const auto& v : per_method) {
      if (v) {
        lo = std::min(lo, *v);
        hi = std::max(hi, *v);
      }
    }
  }
  const bool log_scale = !is_share(history_metrics()[m].key) && lo > 0.0 && hi > 20.0 * lo;
  if (log_scale) {
    lo /= 1.5;
    hi *= 1.5;
  } else {
    lo = 0.0;
    hi = is_share(history_metrics()[m].key) ? 1.0 : (hi > 0.0 ? 1.1 * hi : 1.0);
  }
  const auto x = [&](std::size_t r) {
    return runs < 2 ? left + plot_w / 2
                    : left + plot_w * static_cast<double>(r) / static_cast<double>(runs - 1);
  };
  const auto y = [&](double v) {
    const double t = log_scale ? std::log(v / lo) / std::log(hi / lo) : v / hi;
    return top + plot_h * (1.0 - t);
  };
  const auto tick = [&](double t) { return log_scale ? lo * std::pow(hi / lo, t) : t * hi; };

  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} "
      "{1}\" font-family=\"sans-serif\" font-size=\"11\">\n",
      width, height);
  out += fmt::format(
      "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#999\"/>\n", left,
      top, plot_w, plot_h);
  for (double t : {0.0, 0.5, 1.0}) {
    out += fmt::format(
        "<line x1=\"{0}\" x2=\"{1}\" y1=\"{2:.1f}\" y2=\"{2:.1f}\" stroke=\"#eee\"/>"
        "<text x=\"{3}\" y=\"{4:.1f}\" text-anchor=\"end\">{5}</text>\n",
        left, left + plot_w, y(tick(t)), left - 4, y(tick(t)) + 4,
        escape(report::short_number(tick(t))));
  }
  if (log_scale) {
    out +=
        fmt::format("<text x=\"{}\" y=\"{}\" fill=\"#666\">log scale</text>\n", left + 4, top + 12);
  }
  for (std::size_t r = 0; r < runs; ++r) {
    out += fmt::format("<text x=\"{:.1f}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", x(r),
                       top + plot_h + 15, r + 1);
  }
  out += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">run</text>\n",
                     left + plot_w / 2, height - 5);

  for (std::size_t k = 0; k < history.methods.size(); ++k) {
    // The line, broken where a run has no value.
    std::string points;
    const auto flush = [&] {
      if (!points.empty()) {
        out += fmt::format(
            "<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"2\" points=\"{}\"/>\n", color(k),
            points);
      }
      points.clear();
    };
    for (std::size_t r = 0; r < runs; ++r) {
      if (const auto& v = values[k][r])
        points += fmt::format("{}{:.1f},{:.1f}", points.empty() ? "" : " ", x(r), y(*v));
      else
        flush();
    }
    flush();
    for (std::size_t r = 0; r < runs; ++r) {
      const auto& v = values[k][r];
      if (!v)
        continue;
      out += fmt::format(
          "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3\" fill=\"{}\"><title>{}, run {} ({}): "
          "{}</title></circle>\n",
          x(r), y(*v), color(k), escape(history.methods[k]), r + 1, escape(history.runs[r].label()),
          escape(report::short_number(*v)));
      if (!history.regressions[k][r].empty()) {
        out += fmt::format(
            "<circle class=\"regression\" data-method=\"{}\" data-run=\"{}\" cx=\"{:.1f}\" "
            "cy=\"{:.1f}\" r=\"7\" fill=\"none\" stroke=\"#d00\" stroke-width=\"2\"><title>{}"
            "</title></circle>\n",
            escape(history.methods[k]), r + 1, x(r), y(*v),
            escape(regression_tooltip(history, k, r)));
      }
    }
    const double ly = top + 12 + 16 * static_cast<double>(k);
    out += fmt::format(
        "<line x1=\"{0}\" x2=\"{1}\" y1=\"{2:.1f}\" y2=\"{2:.1f}\" stroke=\"{3}\" "
        "stroke-width=\"2\"/><text x=\"{4}\" y=\"{5:.1f}\">{6}</text>\n",
        left + plot_w + 10, left + plot_w + 30, ly, color(k), left + plot_w + 35, ly + 4,
        escape(history.methods[k]));
  }
  return out + "</svg>\n";
}

}  // namespace

History compute_history(std::vector<HistoryRun> runs, const HistoryOptions& options) {
  History history;
  history.options = options;
  std::stable_sort(runs.begin(), runs.end(), [](const HistoryRun& a, const HistoryRun& b) {
    const auto& ca = a.data.context;
    const auto& cb = b.data.context;
    return std::tie(ca.created_utc, ca.code_version) < std::tie(cb.created_utc, cb.code_version);
  });
  history.runs = std::move(runs);

  std::set<std::string> methods;
  for (const auto& run : history.runs) {
    for (const auto& record : run.data.records)
      methods.insert(record.job.method_id);
  }
  history.methods.assign(methods.begin(), methods.end());
  std::map<std::string, std::size_t> method_index;
  for (std::size_t k = 0; k < history.methods.size(); ++k)
    method_index[history.methods[k]] = k;

  const auto& metrics = history_metrics();
  const std::size_t runs_count = history.runs.size();
  history.values.assign(
      metrics.size(), std::vector<std::vector<std::optional<double>>>(
                          history.methods.size(), std::vector<std::optional<double>>(runs_count)));
  history.regressions.assign(history.methods.size(),
                             std::vector<std::vector<std::string>>(runs_count));
  for (std::size_t r = 0; r < runs_count; ++r) {
    for (const auto& entry : report::method_totals(history.runs[r].data)) {
      const std::size_t k = method_index.at(entry.method);
      for (std::size_t m = 0; m < metrics.size(); ++m)
        history.values[m][k][r] = entry.values[column_index(metrics[m].key)];
    }
    if (r == 0)
      continue;
    bool used_defaults = true;
    const auto tolerances =
        options.tolerances_of_suite
            ? options.tolerances_of_suite(history.runs[r].data.context.suite, &used_defaults)
            : Tolerances{};
    if (used_defaults && !options.tolerances_of_suite) {
      history.notes.push_back(
          fmt::format("run {}: no tolerances given: judged by the built-in tolerances", r + 1));
    } else if (used_defaults) {
      history.notes.push_back(
          fmt::format("run {} names no known suite ('{}'): judged by the built-in tolerances",
                      r + 1, history.runs[r].data.context.suite));
    }
    const auto comparison =
        compare_results(history.runs[r - 1].data, history.runs[r].data, tolerances);
    for (const auto& job : comparison.jobs) {
      if (job.regression())
        history.regressions[method_index.at(job.method)][r].push_back(job.job_id);
    }
  }
  return history;
}

std::string history_html(const History& history) {
  std::string out =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<title>holebench history</title>\n<style>\n"
      "body { font-family: sans-serif; margin: 1.5em; }\n"
      "table { border-collapse: collapse; margin-bottom: 1em; }\n"
      "th, td { border: 1px solid #ccc; padding: 0.2em 0.5em; text-align: left; "
      "vertical-align: top; }\n"
      "</style>\n</head>\n<body>\n<h1>holebench history</h1>\n";
  out += fmt::format(
      "<p>{} runs, oldest first (by the date and code version of their context). Each line is "
      "a method's number over all its jobs in a run; a red circle marks a run in which "
      "<code>holebench compare</code> flags a regression of that method against the run "
      "before it (hover for the jobs).</p>\n",
      history.runs.size());
  for (const auto& note : history.notes)
    out += "<p><em>" + escape(note) + "</em></p>\n";
  for (std::size_t m = 0; m < history_metrics().size(); ++m) {
    out += "<h2>" + escape(history_metrics()[m].title) + "</h2>\n";
    out += chart_svg(history, m);
  }

  out +=
      "<h2>Runs</h2>\n<table>\n<tr><th>run</th><th>date, code</th><th>suite</th>"
      "<th>jobs</th><th>file</th></tr>\n";
  for (std::size_t r = 0; r < history.runs.size(); ++r) {
    const auto& run = history.runs[r];
    out += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>\n", r + 1,
                       escape(run.label()), escape(run.data.context.suite), run.data.records.size(),
                       escape(run.name));
  }
  out += "</table>\n<h2>Regressions between consecutive runs</h2>\n";
  std::string rows;
  for (std::size_t r = 1; r < history.runs.size(); ++r) {
    for (std::size_t k = 0; k < history.methods.size(); ++k) {
      const auto& jobs = history.regressions[k][r];
      if (jobs.empty())
        continue;
      std::string listed;
      for (std::size_t j = 0; j < jobs.size() && j < history.options.listed_jobs; ++j)
        listed += (listed.empty() ? "" : "<br>") + escape(jobs[j]);
      if (jobs.size() > history.options.listed_jobs)
        listed += fmt::format("<br>... and {} more", jobs.size() - history.options.listed_jobs);
      rows += fmt::format("<tr><td>{} &rarr; {}</td><td>{}</td><td>{}</td><td>{}</td></tr>\n", r,
                          r + 1, escape(history.methods[k]), jobs.size(), listed);
    }
  }
  if (rows.empty()) {
    out += "<p>None.</p>\n";
  } else {
    out += "<table>\n<tr><th>runs</th><th>method</th><th>regressed jobs</th><th>jobs</th></tr>\n" +
           rows + "</table>\n";
  }
  return out + "</body>\n</html>\n";
}

std::filesystem::path write_history(const History& history, const std::filesystem::path& out_dir) {
  std::filesystem::create_directories(out_dir);
  const auto path = out_dir / "history.html";
  write_file_atomically(path, history_html(history));  // never half a page
  return path;
}

}  // namespace holebench::harness
