// holebench report: a run's tables, plots and report.html.
#include "harness/outputs/report/report.h"
#include "harness/cli/subcommands.h"
#include "harness/results/results_reader.h"

#include <fmt/format.h>

#include <filesystem>
#include <memory>

namespace holebench::harness::cli {

namespace {

int write_run_report(const std::filesystem::path& dir) {
  const auto data = read_results_json(dir / "results.json");
  const report::ReportOptions options;
  const auto summary = report::write_report(data, dir, options);
  fmt::print("{}", report::console_summary(data, options));
  fmt::print("\nReport: {}\n", (summary.dir / "report.html").string());
  return 0;
}

}  // namespace

Subcommand add_report_command(CLI::App& app) {
  auto dir = std::make_shared<std::filesystem::path>();
  auto* command = app.add_subcommand(
      "report", "Write DIR/report/: summary tables (Markdown, CSV, LaTeX), plots and an HTML page");
  command->add_option("dir", *dir, "A run's output folder (with results.json)")
      ->required()
      ->check(CLI::ExistingDirectory);
  return {command, [dir] { return write_run_report(*dir); }};
}

}  // namespace holebench::harness::cli
