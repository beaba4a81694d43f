// holebench history: trend lines of the headline numbers across successive runs.
#include "harness/outputs/history.h"
#include "harness/cli/subcommands.h"
#include "harness/results/results_reader.h"
#include "harness/run/suite.h"

#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <utility>
#include <vector>

namespace holebench::harness::cli {

namespace {

struct HistoryFlags {
  std::vector<std::filesystem::path> files;
  std::filesystem::path out;
  std::string suite;  ///< --suite: the suite whose tolerances judge every pair (else each run's)
  HistoryOptions options;
};

int history(const HistoryFlags& flags) {
  HistoryOptions options = flags.options;
  options.tolerances_of_suite = [suite = flags.suite](const std::string& named_suite,
                                                      bool* used_defaults) {
    return comparison_tolerances(suite, named_suite, used_defaults);
  };
  std::vector<HistoryRun> runs;
  for (const auto& file : flags.files)
    runs.push_back({file.string(), read_results_json(file)});
  const auto result = compute_history(std::move(runs), options);
  for (const auto& note : result.notes)
    fmt::print(stderr, "holebench history: {}\n", note);
  std::size_t flagged = 0;
  for (const auto& per_method : result.regressions) {
    for (const auto& jobs : per_method)
      flagged += jobs.empty() ? 0 : 1;
  }
  const auto path = write_history(result, flags.out);
  fmt::print("{} runs, {} methods, {} regression marks\nHistory: {}\n", result.runs.size(),
             result.methods.size(), flagged, path.string());
  return 0;
}

}  // namespace

Subcommand add_history_command(CLI::App& app) {
  auto flags = std::make_shared<HistoryFlags>();
  auto* command = app.add_subcommand(
      "history",
      "Write DIR/history.html: per method, trend lines of the headline numbers (median hole "
      "Hausdorff distance, success share, fallback share, median method time) across "
      "successive results files (ordered by their context's date, then code version), with "
      "the regressions `holebench compare` flags between consecutive runs circled");
  command
      ->add_option("results", flags->files,
                   "results.json files of successive runs (any order; at least one)")
      ->required();
  command->add_option("--out", flags->out, "Output folder (created)")->required();
  command->add_option("--suite", flags->suite,
                      "Suite whose tolerances judge regressions (default: the suite each newer "
                      "run names; without one, the built-in tolerances)");
  return {command, [flags] { return history(*flags); }};
}

}  // namespace holebench::harness::cli
