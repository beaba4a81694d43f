// The subcommands of `holebench`, one file each in harness/cli/ (named after the
// subcommand): each adds itself and its flags to the command line and says how to execute
// it once parsed. main() adds them in the order `holebench --help` lists them and
// dispatches.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace holebench::harness::cli {

/// A subcommand added to the command line: CLI11's App (`parsed()` once chosen) and the
/// function that executes it, returning the exit code. Its flags live in the function.
/// Exceptions leave `execute`: main() prints them ("holebench: ...") and exits with code 2.
struct Subcommand {
  CLI::App* app = nullptr;
  std::function<int()> execute;
};

Subcommand add_list_command(CLI::App& app);      ///< list: methods and case families
Subcommand add_cases_command(CLI::App& app);     ///< cases list | export | gallery
Subcommand add_run_command(CLI::App& app);       ///< run: a suite or an ad hoc selection
Subcommand add_evaluate_command(CLI::App& app);  ///< evaluate: repairs made elsewhere, scored
Subcommand add_merge_command(CLI::App& app);     ///< merge: results files, or --shards
Subcommand add_slurm_command(CLI::App& app);     ///< slurm submit | status | resubmit
Subcommand add_suites_command(CLI::App& app);    ///< suites: the suites and descriptions
Subcommand add_compare_command(CLI::App& app);   ///< compare: base vs new, exit 1 on regression
Subcommand add_validate_command(CLI::App& app);  ///< validate: results files' invariants
Subcommand add_figures_command(CLI::App& app);   ///< figures: the papers' figures and tables
Subcommand add_history_command(CLI::App& app);   ///< history: trends across runs
Subcommand add_report_command(CLI::App& app);    ///< report: tables, plots, report.html
Subcommand add_timing_command(CLI::App& app);    ///< timing: worker time by stage and step

}  // namespace holebench::harness::cli
