#include "harness/outputs/report/report.h"

#include "core/atomic_file.h"

#include "harness/outputs/report/leaderboard.h"
#include "harness/results/markup_escape.h"
#include "metrics/metric_names.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <stdexcept>
#include <string_view>
#include <tuple>

#ifndef HOLEBENCH_SUITES_DIR
#define HOLEBENCH_SUITES_DIR "suites"
#endif

namespace holebench::harness::report {
namespace {

/// The plots the script draws, in the order the HTML shows them, with their captions.
const std::vector<std::pair<std::string, std::string>>& plot_files() {
  static const std::vector<std::pair<std::string, std::string>> files{
      {"error_vs_noise.png",
       "Median Hausdorff distance and median hole mean distance (relative to the diagonal) "
       "against the noise level, per method"},
      {"success_rate.png", "Fraction of jobs with status ok, per case kind and method"},
      {"time_per_method.png", "Method wall time per job (time_method_s), per method"},
  };
  return files;
}

// Atomically: a report killed while writing leaves the previous file, never half of one.
void write_file(const std::filesystem::path& path, const std::string& text) {
  write_file_atomically(path, text);
}

std::string case_kind_of(const JobRecord& record) {
  return record.case_family + "/" + record.case_kind;
}

std::string html_escape(const std::string& text) {
  return xml_escape(text, true);
}

/// A path for an href/src attribute: spaces and the like percent-encoded, then escaped.
std::string url_path(const std::string& path) {
  std::string out;
  for (unsigned char c : path) {
    if (std::isalnum(c) ||
        std::string_view("/._-~").find(static_cast<char>(c)) != std::string_view::npos) {
      out += static_cast<char>(c);
    } else {
      out += fmt::format("%{:02X}", c);
    }
  }
  return html_escape(out);
}

std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text)
    out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// --- plot data ------------------------------------------------------------------------------

nlohmann::ordered_json median_or_null(std::vector<double> values) {
  const auto stats = compute_stats(std::move(values));
  return stats ? nlohmann::ordered_json(stats->median) : nlohmann::ordered_json();
}

/// The numbers every plot shows, computed here so that the script only draws them.
nlohmann::ordered_json plot_data(const ResultsData& data) {
  std::set<std::string> methods, kinds;
  std::set<double> noise_levels;
  for (const auto& r : data.records) {
    methods.insert(r.job.method_id);
    kinds.insert(case_kind_of(r));
    noise_levels.insert(r.job.noise_percent);
  }
  nlohmann::ordered_json j;
  j["methods"] = methods;
  j["case_kinds"] = kinds;
  j["noise_percent"] = noise_levels;

  auto& error = j["error_vs_noise"] = nlohmann::ordered_json::object();
  for (const char* metric :
       {metric_names::kHausdorffRelDiag, metric_names::kHoleMeanDistanceRelDiag}) {
    auto& per_method = error[metric] = nlohmann::ordered_json::object();
    for (const auto& method : methods) {
      auto& medians = per_method[method] = nlohmann::ordered_json::array();
      for (double noise : noise_levels) {
        std::vector<double> values;
        for (const auto& r : data.records) {
          const double* v = r.metric(metric);
          if (v && r.job.method_id == method && r.job.noise_percent == noise)
            values.push_back(*v);
        }
        medians.push_back(median_or_null(std::move(values)));
      }
    }
  }

  auto& success = j["success_rate"] = nlohmann::ordered_json::object();
  for (const auto& method : methods) {
    auto& rates = success[method] = nlohmann::ordered_json::array();
    for (const auto& kind : kinds) {
      std::size_t jobs = 0, ok = 0;
      for (const auto& r : data.records) {
        if (r.job.method_id != method || case_kind_of(r) != kind)
          continue;
        ++jobs;
        ok += r.status == JobStatus::Ok ? 1 : 0;
      }
      rates.push_back(
          jobs == 0 ? nlohmann::ordered_json()
                    : nlohmann::ordered_json(static_cast<double>(ok) / static_cast<double>(jobs)));
    }
  }

  auto& times = j[metric_names::kTimeMethodS] = nlohmann::ordered_json::object();
  for (const auto& method : methods) {
    std::vector<double> values;
    for (const auto& r : data.records) {
      if (r.job.method_id != method)
        continue;
      if (const double* v = r.metric(metric_names::kTimeMethodS))
        values.push_back(*v);
    }
    std::sort(values.begin(), values.end());
    times[method] = values;
  }
  return j;
}

/// Runs the plot script; returns "" on success, otherwise why there are no plots.
std::string make_plots(const ResultsData& data, const std::filesystem::path& plots_dir,
                       const ReportOptions& options) {
  if (data.records.empty())
    return "the results file has no records";
  if (options.python.empty())
    return "plots were switched off (no Python interpreter given)";
  if (!std::filesystem::exists(options.python)) {
    return fmt::format(
        "no Python interpreter at {} (Debian: apt-get install python3 "
        "python3-matplotlib)",
        options.python);
  }
  const auto script = options.plot_script.empty() ? default_plot_script() : options.plot_script;
  if (!std::filesystem::exists(script))
    return "the plot script " + script.string() + " is missing";
  const auto data_path = plots_dir / "plot_data.json";
  const std::string command = fmt::format(
      "MPLBACKEND=Agg {} {} {} {} 1>&2", shell_quote(options.python), shell_quote(script.string()),
      shell_quote(data_path.string()), shell_quote(plots_dir.string()));
  std::fflush(stdout);
  std::fflush(stderr);
  const int status = std::system(command.c_str());
  const int code = status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (code == 3) {
    return fmt::format("matplotlib is missing for {} (Debian: apt-get install python3-matplotlib)",
                       options.python);
  }
  if (code != 0)
    return fmt::format("the plot script failed (exit status {})", code);
  for (const auto& [file, caption] : plot_files()) {
    if (!std::filesystem::exists(plots_dir / file))
      return "the plot script did not write " + file;
  }
  return "";
}

// --- HTML -----------------------------------------------------------------------------------

/// One section per family: the family's rows, and the target kinds' rows in a <tbody> that a
/// checkbox before the table shows or hides (CSS only, no script).
std::string html_family_section(const Leaderboard& board, std::size_t first, const char* id_prefix,
                                const std::string& head,
                                const std::function<std::string(const LeaderboardGroup&)>& rows) {
  const auto& family = board.groups[first];
  std::size_t kinds = 0;
  for (std::size_t i = first + 1; i < board.groups.size() && !board.groups[i].is_family(); ++i)
    ++kinds;
  const std::string id = fmt::format("{}-{}", id_prefix, url_path(family.family));
  std::string out = fmt::format(
      "<section class=\"family\">\n<h3>{0}</h3>\n<input type=\"checkbox\" class=\"kinds\" "
      "id=\"{1}\"><label for=\"{1}\">show the {2} target kinds</label>\n<table "
      "class=\"leaderboard\">\n<thead><tr>{3}</tr></thead>\n<tbody>\n{4}</tbody>\n",
      html_escape(family.family), id, kinds, head, rows(family));
  for (std::size_t i = first + 1; i < board.groups.size() && !board.groups[i].is_family(); ++i)
    out += "<tbody class=\"kind\">\n" + rows(board.groups[i]) + "</tbody>\n";
  return out + "</table>\n</section>\n";
}

std::string leaderboard_html(const Leaderboard& board) {
  const auto& columns = leaderboard_columns();
  std::string head = "<th>target kind</th><th>method</th><th>jobs</th>";
  for (const auto& column : columns)
    head += "<th>" + html_escape(column.header) + "</th>";
  const auto entry_rows = [&](const LeaderboardGroup& group) {
    std::string out;
    for (std::size_t e = 0; e < group.entries.size(); ++e) {
      const auto& entry = group.entries[e];
      out +=
          fmt::format("<tr{}><td>{}</td><td>{}</td><td>{}</td>", e == 0 ? " class=\"first\"" : "",
                      e == 0 ? html_escape(group.is_family() ? "all" : group.kind) : "",
                      html_escape(entry.method), entry.jobs);
      for (std::size_t c = 0; c < columns.size(); ++c) {
        out += fmt::format("<td{}>{}</td>", entry.best[c] ? " class=\"best\"" : "",
                           html_escape(leaderboard_entry_cell(entry, c)));
      }
      out += "</tr>\n";
    }
    return out;
  };
  const auto pair_rows = [&](const LeaderboardGroup& group) {
    std::string out;
    for (std::size_t p = 0; p < group.pairs.size(); ++p) {
      const auto& pair = group.pairs[p];
      const auto& c = pair.comparison;
      out += fmt::format(
          "<tr{}><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td{}>{}</td><td>{}</td>"
          "<td{}>{}</td><td>{}</td><td>{}</td></tr>\n",
          p == 0 ? " class=\"first\"" : "",
          p == 0 ? html_escape(group.is_family() ? "all" : group.kind) : "",
          html_escape(pair.first), html_escape(pair.second), pair.shared_jobs, pair.pairs,
          pair.better == pair.first ? " class=\"best\"" : "", c.wins, c.ties,
          pair.better == pair.second ? " class=\"best\"" : "", c.losses, leaderboard_p_value(pair),
          html_escape(pair.better.empty() ? "-" : pair.better));
    }
    return out;
  };

  std::string out =
      "<h2 id=\"leaderboard\">Leaderboard</h2>\n<p>Per case family, each method's share of "
      "<em>valid</em> repairs first (every hole closed, the output closed, manifold and "
      "consistently oriented, no self-intersection involving a new face, the input away from "
      "the holes unchanged; a failed job is not valid). For a method that guides holes by "
      "design the first cell is instead its <em>decision measure</em>, marked "
      "<q>(decision)</q>: the share of holes handled as the truth's decision says (closed "
      "where it says close, guided where it says guide), not ranked against valid shares. "
      "Then the share of jobs <em>closed but invalid</em> (every hole closed, yet not valid), "
      "of successful jobs (status ok, every hole closed), of holes a stand-in handled "
      "(<em>fallback</em>) and of holes whose method found a defect in its own patch, the "
      "median hole Hausdorff distance, the literature's metrics over the hole (median "
      "Chamfer-L1, mean F-score at 1 % of the diagonal, mean normal consistency), median "
      "new-vertex error (lengths relative to the diagonal), mean coverage of the missing sharp "
      "edges, and median method time; the best of each column is highlighted. Medians and "
      "means are over the jobs that have the metric: read them beside the valid share. Tick "
      "a box to see the target kinds. Also as <a "
      "href=\"leaderboard.md\">leaderboard.md</a> and <a "
      "href=\"leaderboard.tex\">leaderboard.tex</a>.</p>\n";
  for (std::size_t i = 0; i < board.groups.size(); ++i) {
    if (board.groups[i].is_family())
      out += html_family_section(board, i, "kinds", head, entry_rows);
  }
  out += fmt::format(
      "<h2 id=\"paired\">Paired comparisons: <code>{}</code></h2>\n<p>Each pair of methods on "
      "the jobs both ran (same case, noise, seed and user): <em>A better</em> when A's interval "
      "[value, upper bound] lies wholly below B's, <em>tie</em> when the intervals overlap (the "
      "error bounds cannot order them); p is the two-sided Wilcoxon signed-rank test on the "
      "differences A - B, ties counted as 0 (exact up to {} non-zero differences, else the "
      "normal approximation); <em>better</em> names the method the differences favour when p "
      "&lt; {:g}.</p>\n",
      html_escape(board.options.paired_metric), board.options.test.max_exact_n,
      board.options.significance);
  const std::string pair_head =
      "<th>target kind</th><th>A</th><th>B</th><th>jobs</th><th>pairs</th><th>A better</th>"
      "<th>tie</th><th>B better</th><th>p</th><th>better</th>";
  for (std::size_t i = 0; i < board.groups.size(); ++i) {
    if (board.groups[i].is_family())
      out += html_family_section(board, i, "pairs", pair_head, pair_rows);
  }
  return out;
}

std::string html_table(const SummaryTable& table) {
  std::string out =
      "<table class=\"summary\">\n<thead><tr><th>method</th><th>case kind</th>"
      "<th>noise %</th><th>jobs</th><th>ok</th><th>fallback</th>";
  for (const auto& metric : table.metrics) {
    out += fmt::format("<th>{}<br>median</th><th>IQR</th>", html_escape(metric));
  }
  out += "<th>note</th></tr></thead>\n<tbody>\n";
  for (const auto& row : table.rows) {
    const auto share = row.fallback_share();
    out += fmt::format("<tr{}><td>{}</td><td>{}</td><td>{:g}</td><td>{}</td><td>{}</td><td>{}</td>",
                       row.flagged() ? " class=\"flagged\"" : "", html_escape(row.method),
                       html_escape(row.case_kind), row.noise_percent, row.jobs, row.ok,
                       share ? fmt::format("{:.3g}", *share) : std::string("-"));
    for (const auto& stats : row.stats) {
      out += stats ? fmt::format("<td>{:.3g}</td><td>{:.3g}</td>", stats->median, stats->iqr())
                   : std::string("<td>-</td><td>-</td>");
    }
    out += fmt::format("<td>{}</td></tr>\n", html_escape(row.note()));
  }
  return out + "</tbody>\n</table>\n";
}

std::string snapshot_grid(const ResultsData& data) {
  std::set<std::string> methods;
  // case id -> (user, noise, seed) -> method -> record
  using Variant = std::tuple<std::string, double, std::uint64_t>;
  std::map<std::string, std::map<Variant, std::map<std::string, const JobRecord*>>> cases;
  for (const auto& r : data.records) {
    methods.insert(r.job.method_id);
    cases[r.job.case_id][{r.job.user, r.job.noise_percent, r.job.seed}][r.job.method_id] = &r;
  }
  std::string out;
  for (const auto& [case_id, variants] : cases) {
    out += fmt::format(
        "<h3 id=\"case-{}\">{}</h3>\n<div class=\"strip\"><table class=\"strip\">\n<tr><th></th>",
        url_path(case_id), html_escape(case_id));
    for (const auto& method : methods)
      out += "<th>" + html_escape(method) + "</th>";
    out += "</tr>\n";
    for (const auto& [variant, by_method] : variants) {
      const auto& [user, noise, seed] = variant;
      out +=
          fmt::format("<tr><th>{}<br>noise {} %<br>seed {}</th>", html_escape(user), noise, seed);
      for (const auto& method : methods) {
        const auto it = by_method.find(method);
        if (it == by_method.end()) {
          out += "<td class=\"none\">no job</td>";
          continue;
        }
        const JobRecord& r = *it->second;
        std::string caption = to_string(r.status);
        if (const double* h = r.metric(metric_names::kHausdorffRelDiag)) {
          caption += fmt::format(", Hausdorff {:.3g}", *h);
        }
        if (r.snapshot.empty()) {
          out += fmt::format("<td class=\"none\">no snapshot<br>{}</td>", html_escape(caption));
        } else {
          out += fmt::format(
              "<td><a href=\"../{0}\"><img src=\"../{0}\" alt=\"{1}\" width=\"340\" "
              "loading=\"lazy\"></a><br>{2}</td>",
              url_path(r.snapshot), html_escape(r.job.id()), html_escape(caption));
        }
      }
      out += "</tr>\n";
    }
    out += "</table></div>\n";
  }
  return out;
}

std::string report_html(const ResultsData& data, const Leaderboard& board,
                        const SummaryTable& table, const std::filesystem::path& results_dir,
                        const std::string& plots_note, const std::string& viewer_html) {
  const auto& c = data.context;
  std::string out =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<title>holebench report</title>\n<style>\n"
      "body { font-family: sans-serif; margin: 1.5em; }\n"
      "table { border-collapse: collapse; margin-bottom: 1em; }\n"
      "th, td { border: 1px solid #ccc; padding: 0.2em 0.5em; text-align: right; "
      "vertical-align: top; }\n"
      "td:nth-child(-n+2), table.strip td, table.strip th { text-align: left; }\n"
      "tr.flagged { background: #fff3cd; }\n"
      "td.none { color: #888; }\n"
      "figure { display: inline-block; margin: 0 1em 1em 0; }\n"
      "td.best { font-weight: bold; background: #d4edda; }\n"
      "table.leaderboard tr.first td { border-top: 2px solid #888; }\n"
      "table.leaderboard td:nth-child(-n+3) { text-align: left; }\n"
      "section.family input.kinds:not(:checked) ~ table tbody.kind { display: none; }\n"
      "div.strip { overflow-x: auto; }\n"
      "div.viewer-box { position: relative; width: 960px; max-width: 100%; }\n"
      "#viewer-canvas { width: 880px; height: 560px; display: block; background: #1d2433; }\n"
      "#viewer-bar { position: absolute; left: 890px; top: 0; height: 560px; width: 70px; }\n"
      ".viewer-strip { position: absolute; left: 0; top: 8px; bottom: 8px; width: 16px; }\n"
      ".viewer-label { position: absolute; left: 22px; font-size: 12px; }\n"
      ".viewer-label-0 { top: 0; } .viewer-label-1 { top: 272px; } "
      ".viewer-label-2 { bottom: 0; }\n"
      "</style>\n</head>\n<body>\n<h1>holebench report</h1>\n";
  out += fmt::format(
      "<p>Suite <code>{}</code>, code <code>{}</code>, {} build on {}, run {}; {} jobs.</p>\n",
      html_escape(c.suite), html_escape(c.code_version), html_escape(c.build_type),
      html_escape(c.host), html_escape(c.created_utc), data.records.size());
  out +=
      "<p>On this page: <a href=\"#leaderboard\">leaderboard</a>, <a href=\"#paired\">paired "
      "comparisons</a>, <a href=\"#summary\">summary</a>, <a href=\"#plots\">plots</a>, <a "
      "href=\"#snapshots\">pictures per case</a>, <a href=\"#viewer\">3D viewer</a>.</p>\n";
  out += leaderboard_html(board);
  out +=
      "<h2>Files</h2>\n<p>Also here: <a href=\"leaderboard.md\">leaderboard.md</a>, <a "
      "href=\"leaderboard.tex\">leaderboard.tex</a>, <a href=\"summary.md\">summary.md</a>, <a "
      "href=\"summary.csv\">summary.csv</a>, "
      "<a href=\"tables.tex\">tables.tex</a>, <a href=\"../results.json\">results.json</a>.";
  if (std::filesystem::exists(results_dir / "gallery.html")) {
    out += " The cases: <a href=\"../gallery.html\">case gallery</a>.";
  }
  if (std::filesystem::exists(results_dir / "report" / "history.html")) {
    out += " Earlier runs: <a href=\"history.html\">history</a>.";
  }
  out += "</p>\n";

  out += "<h2 id=\"summary\">Summary: method &times; case kind &times; noise level</h2>\n" +
         html_table(table);
  out += fmt::format(
      "<p>Medians over every job of the row that has the metric (all seeds and users); IQR = "
      "q3 - q1. Highlighted rows, with the reason in the note: <em>few</em> = fewer than {} "
      "values in a column because jobs of the row did not end ok (read their messages); "
      "<em>spread</em> = the third quartile above {:g} times the first, time excepted (the "
      "row's jobs fall into groups an order of magnitude apart; read results.csv).</p>\n",
      table.options.min_samples, table.options.max_quartile_ratio);

  out += "<h2 id=\"plots\">Plots</h2>\n";
  if (plots_note.empty()) {
    for (const auto& [file, caption] : plot_files()) {
      out += fmt::format(
          "<figure><img src=\"plots/{0}\" alt=\"{1}\"><figcaption>{1}</figcaption></figure>\n",
          file, html_escape(caption));
    }
    out +=
        "<p>The numbers plotted: <a href=\"plots/plot_data.json\">plots/plot_data.json</a>.</p>\n";
  } else {
    out += "<p class=\"none\">No plots: " + html_escape(plots_note) + ".</p>\n";
  }

  out +=
      "<h2 id=\"snapshots\">Pictures per case</h2>\n<p>Per case, the methods side by side; one "
      "row per user, noise level and seed. Each picture shows a close-up of the hole (of the "
      "first two holes where there are more), the camera outside the model looking into it, "
      "beside the whole model seen from the same side. Kept faces are grey; the patch is "
      "coloured by its distance to the complete model, relative to the bounding-box diagonal, "
      "from blue (on the model) to red (at the top of the bar or beyond). The bar's scale is the "
      "case's, from its ground truth only (half the largest hole's radius, rounded up to 1, 2 "
      "or 5 times a power of ten), so every method of a case is coloured on the same scale. "
      "Holes left open are outlined in magenta; guidance arrows are blue. Click a picture for "
      "its full size.</p>\n";
  out += snapshot_grid(data);
  out += viewer_html;
  out += "</body>\n</html>\n";
  return out;
}

}  // namespace

std::filesystem::path default_plot_script() {
  if (const char* path = std::getenv("HOLEBENCH_PLOT_SCRIPT"); path && *path)
    return path;
  return std::filesystem::path(HOLEBENCH_SUITES_DIR).parent_path() / "scripts" / "plot_results.py";
}

std::string console_summary(const ResultsData& data, const ReportOptions& options) {
  return summary_markdown(data, summarize(data, options.summary));
}

ReportSummary write_report(const ResultsData& data, const std::filesystem::path& results_dir,
                           const ReportOptions& options) {
  ReportSummary summary;
  summary.dir = results_dir / "report";
  const auto plots_dir = summary.dir / "plots";
  std::filesystem::create_directories(plots_dir);

  const SummaryTable table = summarize(data, options.summary);
  summary.rows = table.rows.size();
  summary.flagged_rows = static_cast<std::size_t>(std::count_if(
      table.rows.begin(), table.rows.end(), [](const SummaryRow& r) { return r.flagged(); }));

  write_file(summary.dir / "summary.md", summary_markdown(data, table));
  write_file(summary.dir / "summary.csv", summary_csv(table));
  write_file(summary.dir / "tables.tex", summary_latex(table));
  const Leaderboard board = compute_leaderboard(data, options.leaderboard);
  write_file(summary.dir / "leaderboard.md", leaderboard_markdown(board));
  write_file(summary.dir / "leaderboard.tex", leaderboard_latex(board));
  summary.files = {"leaderboard.md", "leaderboard.tex", "summary.md", "summary.csv", "tables.tex"};

  // Plots: stale pictures go first, so that a failed run cannot show an older one (with what a
  // killed run of the script left beside them).
  for (const auto& [file, caption] : plot_files()) {
    std::filesystem::remove(plots_dir / file);
    std::filesystem::remove(plots_dir / (file + ".partial"));
  }
  write_file(plots_dir / "plot_data.json", plot_data(data).dump(2) + "\n");
  summary.files.push_back("plots/plot_data.json");
  summary.plots_note = make_plots(data, plots_dir, options);
  summary.plots_written = summary.plots_note.empty();
  if (summary.plots_written) {
    for (const auto& [file, caption] : plot_files())
      summary.files.push_back("plots/" + file);
  } else if (options.warnings_to_stderr) {
    std::fprintf(stderr, "holebench report: no plots: %s\n", summary.plots_note.c_str());
  }

  const viewer::ViewerSection viewer =
      viewer::write_viewer(data, results_dir, summary.dir, options.viewer);
  summary.viewer_cases = viewer.cases;
  summary.viewer_note = viewer.note;
  summary.files.insert(summary.files.end(), viewer.files.begin(), viewer.files.end());
  if (!viewer.note.empty() && options.warnings_to_stderr)
    std::fprintf(stderr, "holebench report: no 3D viewer: %s\n", viewer.note.c_str());

  write_file(summary.dir / "report.html",
             report_html(data, board, table, results_dir, summary.plots_note, viewer.html));
  summary.files.push_back("report.html");
  std::sort(summary.files.begin(), summary.files.end());
  return summary;
}

}  // namespace holebench::harness::report
