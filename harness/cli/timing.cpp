// holebench timing: where a run's worker time went, from its records' timings.
#include "harness/cli/subcommands.h"
#include "harness/outputs/time_breakdown.h"
#include "harness/results/results_reader.h"

#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <vector>

namespace holebench::harness::cli {

namespace {

int timing(const std::vector<std::filesystem::path>& files) {
  std::vector<JobRecord> records;
  for (const auto& file : files) {
    ResultsData data = read_results_json(file);
    records.insert(records.end(), std::make_move_iterator(data.records.begin()),
                   std::make_move_iterator(data.records.end()));
  }
  fmt::print("{}", format_time_breakdown(time_breakdown(records)));
  return 0;
}

}  // namespace

Subcommand add_timing_command(CLI::App& app) {
  auto files = std::make_shared<std::vector<std::filesystem::path>>();
  auto* command = app.add_subcommand(
      "timing",
      "Print where the workers' time went, as Markdown tables summed over the records: each "
      "stage (stages_s: making the case, the method, the evaluation, the snapshot, the heap "
      "warm-up), each step of the evaluation (evaluation_phases_s) and each method, with the "
      "ratio of the time outside the method calls to the methods' own (docs/results.md)");
  command->add_option("results", *files, "results.json files (their records taken together)")
      ->required();
  return {command, [files] { return timing(*files); }};
}

}  // namespace holebench::harness::cli
