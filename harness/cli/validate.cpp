// holebench validate: results files checked record by record.
#include "harness/cli/subcommands.h"
#include "harness/results/validate_results.h"

#include <fmt/format.h>

#include <exception>
#include <filesystem>
#include <memory>
#include <vector>

namespace holebench::harness::cli {

namespace {

// Each violation on its own line, then "N records, M violations"; exit code 0 if none, 1 on
// a violation, 2 when a file cannot be read as a results file.
int validate(const std::vector<std::filesystem::path>& files) {
  ValidationReport report;
  try {
    report = validate_results_files(files);
  } catch (const std::exception& e) {
    fmt::print(stderr, "holebench validate: {}\n", e.what());
    return 2;
  }
  for (const auto& violation : report.violations)
    fmt::print("{}\n", format_violation(violation));
  fmt::print("{}\n", format_validation_summary(report));
  return report.ok() ? 0 : 1;
}

}  // namespace

Subcommand add_validate_command(CLI::App& app) {
  auto files = std::make_shared<std::vector<std::filesystem::path>>();
  auto* command = app.add_subcommand(
      "validate",
      "Check results files record by record: required fields, unique job ids, every metric a "
      "finite number in its range (_fraction, _ok/is_ flags, _count), lower <= value <= upper, "
      "mean <= RMS <= Hausdorff upper, no open hole in an ok job (docs/results.md). Prints each "
      "violation with its job id and a summary; exit code 0 if none, 1 on a violation, 2 on an "
      "unreadable file");
  command->add_option("results", *files, "results.json files (job ids unique across them)")
      ->required();
  return {command, [files] { return validate(*files); }};
}

}  // namespace holebench::harness::cli
