// holebench: the command line of the benchmark.
#include "generators/case_catalog.h"
#include "harness/run_command.h"
#include "methods/registry.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

namespace {

int list_command() {
  fmt::print("cases:\n");
  for (const auto& c : holebench::generators::list_cases()) {
    fmt::print("  {:<24} {}\n", c.id, c.description);
  }
  fmt::print("methods:\n");
  for (const auto& m : holebench::make_all_methods()) {
    fmt::print("  {:<24} {}\n", m->id(), m->description());
  }
  return 0;
}

void print_summary_table(const holebench::harness::RunSummary& summary) {
  fmt::print("\n| case | method | status | hausdorff (rel. diag) | new faces | time (s) |\n");
  fmt::print("|---|---|---|---:|---:|---:|\n");
  for (const auto& r : summary.records) {
    auto metric = [&](const char* name) {
      for (const auto& m : r.metrics) {
        if (m.name == name)
          return fmt::format("{:.3g}", m.value);
      }
      return std::string("-");
    };
    fmt::print("| {} | {} | {} | {} | {} | {:.2f} |\n", r.job.case_id, r.job.method_id,
               holebench::harness::to_string(r.status), metric("hausdorff_rel_diag"),
               metric("new_faces_count"), r.method_seconds);
  }
  fmt::print("\n{} jobs, {} not ok, {:.1f} s. Results: {} and {}\n", summary.records.size(),
             summary.failures, summary.seconds, summary.results_json.string(),
             summary.results_csv.string());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "holebench: a benchmark and evaluation harness for hole filling on CAD meshes.\n"
      "Generates holed cases with ground truth, runs hole-filling methods on them,\n"
      "measures the results and writes records, tables and pictures."};
  app.require_subcommand(1);

  auto* list = app.add_subcommand("list", "List the cases and the methods");

  holebench::harness::RunOptions run_options;
  auto* run = app.add_subcommand("run", "Run cases x methods and write results to a folder");
  run->add_option("--out", run_options.out_dir, "Output folder (created if missing)")->required();
  run->add_option("--case", run_options.case_ids, "Case id to run (repeatable; default: all)");
  run->add_option("--method", run_options.method_ids,
                  "Method id to run (repeatable; default: all)");
  run->add_option("--seed", run_options.seeds, "Seed (repeatable; default: 0)");
  bool no_snapshots = false;
  run->add_flag("--no-snapshots", no_snapshots, "Do not render a PNG per job");
  run->add_option("--hausdorff-error-bound", run_options.evaluation.hausdorff_error_bound_rel_diag,
                  "Error bound of the Hausdorff distance, relative to the diagonal")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);

  CLI11_PARSE(app, argc, argv);
  try {
    if (list->parsed())
      return list_command();
    if (run->parsed()) {
      run_options.snapshots = !no_snapshots;
      const auto summary = holebench::harness::run_jobs(run_options);
      print_summary_table(summary);
      return 0;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "holebench: %s\n", e.what());
    return 2;
  }
  return 0;
}
