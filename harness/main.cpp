// holebench: the command line of the benchmark. Each subcommand is a file in harness/cli/;
// main() adds them and dispatches.
#include "harness/cli/subcommands.h"
#include "harness/results/output_folder_lock.h"
#include "harness/run/heap_reuse.h"
#include "harness/run/huge_page_heap.h"

#include <CLI/CLI.hpp>
#include <OpenMesh/Core/System/omstream.hh>

#include <cstdio>
#include <cstring>
#include <exception>
#include <vector>

int main(int argc, char** argv) {
  // A run's job processes allocate all their memory anew: in huge pages where the system
  // gives them (harness/run/huge_page_heap.h). Only `run` forks jobs.
  if (argc > 1 && std::strcmp(argv[1], "run") == 0)
    holebench::harness::restart_with_huge_page_heap(argv);
  // OpenMesh writes "complex edge" and similar to stderr when a method tries a face that
  // would be non-manifold; methods report such failures in their records instead.
  omerr().disable();
  omlog().disable();
  // Large blocks from the heap, freed memory kept (harness/run/heap_reuse.h).
  holebench::harness::keep_freed_heap_memory();
  CLI::App app{
      "holebench: a benchmark and evaluation harness for hole filling on CAD meshes.\n"
      "Generates holed cases with ground truth, runs hole-filling methods on them,\n"
      "measures the results and writes records, tables and pictures.\n"
      "Case ids and patterns: '*' matches anything, e.g. 'brep/k3/*' or 'cad/fandisk/*'."};
  app.require_subcommand(1);

  namespace cli = holebench::harness::cli;
  // In the order `holebench --help` lists them.
  const std::vector<cli::Subcommand> subcommands{
      cli::add_list_command(app),     cli::add_cases_command(app),   cli::add_run_command(app),
      cli::add_evaluate_command(app), cli::add_merge_command(app),   cli::add_slurm_command(app),
      cli::add_suites_command(app),   cli::add_compare_command(app), cli::add_validate_command(app),
      cli::add_figures_command(app),  cli::add_history_command(app), cli::add_report_command(app),
      cli::add_timing_command(app)};

  CLI11_PARSE(app, argc, argv);
  try {
    for (const auto& subcommand : subcommands) {
      if (subcommand.app->parsed())
        return subcommand.execute();
    }
  } catch (const holebench::harness::OutputFolderInUse& e) {
    // holebench run / merge: another process writes the folder.
    std::fprintf(stderr, "holebench %s: %s\n", app.get_subcommands().front()->get_name().c_str(),
                 e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "holebench: %s\n", e.what());
    return 2;
  }
  return 0;
}
