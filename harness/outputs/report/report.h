// `holebench report DIR`: tables, plots and pictures from a results file, written into
// DIR/report/. The same results file gives the same bytes in every output. What each file
// holds is in docs/reports.md.
#pragma once

#include "harness/outputs/report/leaderboard.h"
#include "harness/outputs/report/summary_table.h"
#include "harness/outputs/viewer/viewer_page.h"
#include "harness/results/results_reader.h"

#include <filesystem>
#include <string>
#include <vector>

namespace holebench::harness::report {

struct ReportOptions {
  LeaderboardOptions leaderboard;  ///< the paired comparisons' metric and significance level
  SummaryOptions summary;          ///< flags of the summary rows (few samples, large spread)
  /// The Python interpreter that runs the plot script; it needs matplotlib. Debian's, not
  /// the pyenv one that may come first on PATH. Empty: no plots.
  std::string python = "/usr/bin/python3";
  /// The plot script; empty: default_plot_script().
  std::filesystem::path plot_script;
  bool warnings_to_stderr = true;  ///< say on stderr why plots (or the viewer) were not made
  viewer::ViewerOptions viewer;    ///< where three.js is, how many cases the viewer shows
};

struct ReportSummary {
  std::filesystem::path dir;                 ///< results_dir/report
  std::vector<std::filesystem::path> files;  ///< written, relative to dir, sorted
  bool plots_written = false;
  std::string plots_note;        ///< why there are no plots (empty when there are)
  std::size_t rows = 0;          ///< summary rows (method x case kind)
  std::size_t flagged_rows = 0;  ///< of those, flagged few / spread
  std::size_t viewer_cases = 0;  ///< cases in the 3D viewer
  std::string viewer_note;       ///< why there is no 3D viewer (empty when there is)
};

/// $HOLEBENCH_PLOT_SCRIPT if set, else scripts/plot_results.py of the source tree.
std::filesystem::path default_plot_script();

/// The console summary (the text of summary.md).
std::string console_summary(const ResultsData& data, const ReportOptions& options = {});

/// Writes results_dir/report/: leaderboard.md and leaderboard.tex (leaderboard.h, first on
/// the HTML page), summary.md, summary.csv, tables.tex, report.html,
/// plots/*.png (with plots/plot_data.json, the numbers the plots show) and viewer/ (the 3D
/// viewer, outputs/viewer/viewer_page.h, where the run wrote meshes/). The records'
/// snapshot paths are taken relative to results_dir; the HTML links results_dir/gallery.html
/// when it exists. A missing Python or matplotlib costs the plots only (said in the HTML and
/// on stderr). Throws std::runtime_error when a file cannot be written.
ReportSummary write_report(const ResultsData& data, const std::filesystem::path& results_dir,
                           const ReportOptions& options = {});

}  // namespace holebench::harness::report
