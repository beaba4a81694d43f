// holebench compare: two results files job by job, judged by a suite's tolerances.
#include "harness/results/compare.h"
#include "harness/cli/subcommands.h"
#include "harness/results/results_reader.h"
#include "harness/run/suite.h"

#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

namespace holebench::harness::cli {

namespace {

struct CompareFlags {
  std::filesystem::path base, now, junit;
  std::string suite;
};

int compare(const CompareFlags& flags) {
  const auto base_results = read_results_json(flags.base);
  const auto new_results = read_results_json(flags.now);
  bool used_defaults = false;
  const auto tolerances =
      comparison_tolerances(flags.suite, new_results.context.suite, &used_defaults);
  if (used_defaults) {
    fmt::print(stderr,
               "holebench compare: the results name no known suite ('{}'): judging by the "
               "built-in tolerances (give --suite NAME for a suite's)\n",
               new_results.context.suite);
  }
  const auto comparison = compare_results(base_results, new_results, tolerances);
  print_comparison(comparison, stdout);
  if (!flags.junit.empty())
    write_junit_xml(comparison, flags.junit);
  return comparison.has_regression() ? 1 : 0;
}

}  // namespace

Subcommand add_compare_command(CLI::App& app) {
  auto flags = std::make_shared<CompareFlags>();
  auto* command = app.add_subcommand(
      "compare", "Compare two results files job by job; exit code 1 on a regression");
  command->add_option("base", flags->base, "Baseline results.json")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("new", flags->now, "New results.json")->required()->check(CLI::ExistingFile);
  command->add_option("--suite", flags->suite,
                      "Suite whose tolerances judge regressions (default: the suite named in the "
                      "new results' context; without one, the built-in defaults)");
  command->add_option("--junit", flags->junit, "Also write a JUnit XML file for CI dashboards");
  return {command, [flags] { return compare(*flags); }};
}

}  // namespace holebench::harness::cli
