// holebench: the command line of the benchmark.
#include "generators/case_catalog.h"
#include "harness/cluster/shard.h"
#include "harness/cluster/shard_merge.h"
#include "harness/cluster/shard_status.h"
#include "harness/cluster/slurm_submit.h"
#include "harness/outputs/case_export.h"
#include "harness/outputs/case_gallery.h"
#include "harness/outputs/history.h"
#include "harness/outputs/paper_figures.h"
#include "harness/outputs/report/report.h"
#include "harness/results/compare.h"
#include "harness/results/results_reader.h"
#include "harness/results/validate_results.h"
#include "harness/run/case_selection.h"
#include "harness/run/output_folder_lock.h"
#include "harness/run/run_command.h"
#include "harness/run/suite.h"
#include "methods/external/external_method_spec.h"
#include "methods/external/predefined_external_methods.h"
#include "methods/registry.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <OpenMesh/Core/System/omstream.hh>

#include <cstdio>
#include <exception>
#include <limits>

namespace {

using holebench::generators::CaseCatalog;
using holebench::generators::CatalogOptions;

int cases_list(const CaseCatalog& catalog, const std::vector<std::string>& patterns, bool labels) {
  const auto selected = holebench::harness::select_cases(
      catalog, patterns.empty() ? std::vector<std::string>{"*"} : patterns);
  for (const auto& c : selected) {
    std::string extra;
    if (labels)
      extra = "  " + holebench::harness::labels_summary(catalog.make(c.id));
    fmt::print("{:<48} {}{}\n", c.id, c.description, extra);
  }
  holebench::harness::print_skipped_models(catalog);
  std::fprintf(stderr, "%zu cases\n", selected.size());
  return 0;
}

int cases_export(const CaseCatalog& catalog, const std::vector<std::string>& patterns,
                 const std::filesystem::path& dir, double noise, std::uint64_t seed) {
  const auto selected = holebench::harness::select_cases(
      catalog, patterns.empty() ? std::vector<std::string>{"*"} : patterns);
  for (std::size_t i = 0; i < selected.size(); ++i) {
    const auto c = catalog.make(selected[i].id, seed, noise);
    holebench::harness::export_case(c, dir / holebench::harness::case_folder_name(c.id));
    std::fprintf(stderr, "[%zu/%zu] %s\n", i + 1, selected.size(), c.id.c_str());
  }
  holebench::harness::print_skipped_models(catalog);
  return 0;
}

void print_summary_table(const holebench::harness::RunSummary& summary) {
  fmt::print(
      "\n| case | method | noise % | status | hausdorff (rel. diag) | new faces | time (ms) |\n");
  fmt::print("|---|---|---:|---|---:|---:|---:|\n");
  for (const auto& r : summary.records) {
    auto metric = [&](const char* name) {
      for (const auto& m : r.metrics) {
        if (m.name == name)
          return fmt::format("{:.3g}", m.value);
      }
      return std::string("-");
    };
    fmt::print("| {} | {} | {} | {} | {} | {} | {:.1f} |\n", r.job.case_id, r.job.method_id,
               r.job.noise_percent, holebench::harness::to_string(r.status),
               metric("hausdorff_rel_diag"), metric("new_faces_count"), 1000.0 * r.method_seconds);
  }
  fmt::print("\n{} jobs, {} not ok, {:.1f} s. Results: {} and {}\n", summary.records.size(),
             summary.failures, summary.seconds, summary.results_json.string(),
             summary.results_csv.string());
}

// holebench validate: each violation on its own line, then "N records, M violations"; exit
// code 0 if none, 1 on a violation, 2 when a file cannot be read as a results file.
int validate_command(const std::vector<std::filesystem::path>& files) {
  holebench::harness::ValidationReport report;
  try {
    report = holebench::harness::validate_results_files(files);
  } catch (const std::exception& e) {
    fmt::print(stderr, "holebench validate: {}\n", e.what());
    return 2;
  }
  for (const auto& violation : report.violations)
    fmt::print("{}\n", holebench::harness::format_violation(violation));
  fmt::print("{}\n", holebench::harness::format_validation_summary(report));
  return report.ok() ? 0 : 1;
}

void add_catalog_options(CLI::App* command, CatalogOptions& catalog, bool& no_cad) {
  command
      ->add_option("--mesh", catalog.user_meshes,
                   "Your own mesh or B-Rep file or folder (OFF/OBJ/STL/PLY, STEP/IGES/BREP), "
                   "punched like the CAD models; repeatable. Its cases are file/<stem>/...")
      ->check(CLI::ExistingPath);
  command
      ->add_option("--brep-deflection", catalog.prepare.tessellation.linear_deflection_rel_diag,
                   "Tessellation of B-Rep files: the largest distance between a triangle and "
                   "its face, relative to the bounding-box diagonal")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command->add_flag("--no-cad", no_cad,
                    "Leave out the CGAL data set's CAD models (faster listing)");
  command->add_option("--cad-dir", catalog.cad_data_dir,
                      "Folder with the CGAL data set's meshes (default: extracted by the build; "
                      "or $HOLEBENCH_CAD_DIR)");
}

// A CLI11 validator from a parser that throws std::invalid_argument with the message.
template <typename Parse>
CLI::Validator parsed_by(Parse parse, const std::string& name) {
  return CLI::Validator(
      [parse](std::string& text) {
        try {
          parse(text);
          return std::string();
        } catch (const std::exception& e) {
          return std::string(e.what());
        }
      },
      "", name);
}

std::vector<std::size_t> shard_indices(const std::string& list) {
  if (list.empty())
    return {};
  return holebench::harness::parse_shard_list(list, std::numeric_limits<std::size_t>::max());
}

void print_submission(const holebench::harness::SlurmSubmitResult& result,
                      const std::filesystem::path& dir) {
  std::string command;
  for (const auto& arg : result.sbatch_command)
    command += (command.empty() ? "" : " ") + holebench::harness::shell_quote(arg);
  if (result.submitted) {
    fmt::print("Submitted Slurm job {}: array {}\n", result.slurm_job_id, result.array);
  } else {
    fmt::print("Dry run: not submitted. To submit:\n  {}\n", command);
  }
  const auto absolute = std::filesystem::absolute(dir).lexically_normal().string();
  fmt::print(
      "  script:   {}\n  manifest: {}\n  logs:     {}/slurm/shard-<I>.log\n"
      "  status:   holebench slurm status --out {}\n"
      "  merge:    holebench merge --shards {}\n",
      result.script.string(), result.manifest.string(), absolute, absolute, absolute);
}

}  // namespace

int main(int argc, char** argv) {
  // OpenMesh writes "complex edge" and similar to stderr when a method tries a face that
  // would be non-manifold; methods report such failures in their records instead.
  omerr().disable();
  omlog().disable();
  CLI::App app{
      "holebench: a benchmark and evaluation harness for hole filling on CAD meshes.\n"
      "Generates holed cases with ground truth, runs hole-filling methods on them,\n"
      "measures the results and writes records, tables and pictures.\n"
      "Case ids and patterns: '*' matches anything, e.g. 'brep/k3/*' or 'cad/fandisk/*'."};
  app.require_subcommand(1);

  auto* list = app.add_subcommand("list", "List the methods and the case families");

  CatalogOptions catalog_options;
  bool no_cad = false;
  auto* cases = app.add_subcommand("cases", "List or export cases");
  cases->require_subcommand(1);
  std::vector<std::string> case_patterns;
  bool with_labels = false;
  auto* cases_list_cmd = cases->add_subcommand("list", "List cases (optionally matching patterns)");
  cases_list_cmd->add_option("patterns", case_patterns, "Case ids or patterns (default: all)");
  cases_list_cmd->add_flag("--labels", with_labels, "Generate each case and print its labels");
  add_catalog_options(cases_list_cmd, catalog_options, no_cad);
  std::filesystem::path export_dir;
  double export_noise = 0.0;
  std::uint64_t export_seed = 0;
  auto* cases_export_cmd =
      cases->add_subcommand("export", "Write cases as PLY/OFF meshes and JSON ground truth");
  cases_export_cmd->add_option("dir", export_dir, "Output folder")->required();
  cases_export_cmd->add_option("patterns", case_patterns, "Case ids or patterns (default: all)");
  cases_export_cmd->add_option("--noise", export_noise, "Noise level in % of 1 % of the diagonal")
      ->check(CLI::NonNegativeNumber);
  cases_export_cmd->add_option("--seed", export_seed, "Noise seed");
  add_catalog_options(cases_export_cmd, catalog_options, no_cad);

  std::filesystem::path gallery_dir;
  auto* cases_gallery_cmd = cases->add_subcommand(
      "gallery", "Render one picture per case (figure-5 style) and a gallery.html page");
  cases_gallery_cmd->add_option("dir", gallery_dir, "Output folder")->required();
  cases_gallery_cmd->add_option("patterns", case_patterns,
                                "Case ids or patterns (default: brep/*)");
  add_catalog_options(cases_gallery_cmd, catalog_options, no_cad);

  holebench::harness::RunOptions run_options;
  std::string suite_name;
  auto* run = app.add_subcommand(
      "run",
      "Run a suite (or cases x methods x users x noise x seeds) into a folder; each job in "
      "its own process, in parallel");
  run->add_option("--out", run_options.out_dir,
                  "Output folder (created if missing). One holebench process at a time: while a "
                  "run or merge holds it (DIR/.holebench.lock), another exits with code 2")
      ->required();
  run->add_option("--suite", suite_name,
                  "Suite name (suites/<name>.json: smoke, default, nightly, paper) or path; the "
                  "options below, where given, override it");
  run->add_option("--case", run_options.case_patterns,
                  "Case id or pattern, repeatable (default: the default suite's)");
  run->add_option("--method", run_options.method_ids,
                  "Method id, repeatable (default: every built-in method): a built-in, a "
                  "predefined external method (meshlab_close_holes) or an --external name");
  std::vector<std::string> external_texts;
  run->add_option("--external", external_texts,
                  "A program as a method, repeatable: 'name=NAME;command=COMMAND', COMMAND "
                  "reading {input} (the holed mesh, binary PLY) and writing {output} (the "
                  "repaired mesh, PLY; the input's faces unchanged, new faces are the patch), "
                  "e.g. 'name=my_fill;command=python3 my_fill.py {input} {output}'. It runs "
                  "beside the --method ids (default: every built-in); add --method NAME to run "
                  "it alone. Optional before command=: vertex_tolerance_rel_diag=X, to match "
                  "single-precision output (docs/methods.md)")
      ->type_name("'name=NAME;command=COMMAND'")
      ->check(parsed_by(holebench::parse_external_method_spec, "'name=NAME;command=COMMAND'"));
  run->add_option("--noise", run_options.noise_levels,
                  "Noise level in % of 1 % of the diagonal, repeatable (default: 0)")
      ->check(CLI::NonNegativeNumber);
  run->add_option("--seed", run_options.seeds, "Seed, repeatable (default: 0)");
  run->add_option("--user", run_options.users,
                  "Who answers the methods' questions: no_user (default) or oracle (from the "
                  "ground truth); repeatable");
  bool no_snapshots = false;
  run->add_flag("--no-snapshots", no_snapshots, "Do not render a PNG per job");
  bool no_viewer_meshes = false;
  run->add_flag("--no-viewer-meshes", no_viewer_meshes,
                "Do not write the report's 3D viewer meshes (meshes/) with the snapshots");
  int workers = 0;
  run->add_option("--workers,-j", workers, "Jobs at once (default: the number of cores)")
      ->check(CLI::NonNegativeNumber);
  double timeout = -1.0;
  run->add_option("--timeout", timeout,
                  "Seconds a job may take before it is stopped (default: the suite's, 300)")
      ->check(CLI::NonNegativeNumber);
  std::string memory_limit_text;
  run->add_option("--memory-limit", memory_limit_text,
                  "Address space each job's process may take (RLIMIT_AS), e.g. 4G, 512M; 0: "
                  "none. A job past it gets the status out_of_memory and the run goes on "
                  "(default: the suite's, 4G)")
      ->type_name("SIZE")
      ->check(parsed_by(holebench::harness::parse_memory_size, "SIZE"));
  bool resume = false;
  run->add_flag("--resume", resume,
                "Keep the records already in DIR/records.jsonl and run the rest");
  std::string shard_text;
  run->add_option("--shard", shard_text,
                  "Run only shard I of N (0 <= I < N): the suite's jobs i with i mod N = I, in "
                  "plan order; the N shards together are the suite, each job once (e.g. 0/4)")
      ->type_name("I/N")
      ->check(parsed_by(holebench::harness::parse_shard, "I/N"));
  int method_repetitions = 0;
  run->add_option("--method-repetitions", method_repetitions,
                  "Run each job's method N times and record the median wall time (the first "
                  "run's result is evaluated; default: the suite's, 1)")
      ->check(CLI::Range(1, 1000));
  run->add_option("--hausdorff-error-bound", run_options.evaluation.hausdorff_error_bound_rel_diag,
                  "Error bound of the Hausdorff distance, relative to the diagonal")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  add_catalog_options(run, run_options.catalog, no_cad);

  std::vector<std::filesystem::path> merge_inputs;
  std::filesystem::path merge_out, merge_shards_dir;
  bool merge_allow_incomplete = false;
  auto* merge = app.add_subcommand(
      "merge",
      "Join results files (matched by job id; later files win), or with --shards the shards of "
      "a sharded run into one results file equal to a single-machine run's, up to timings");
  auto* merge_inputs_option =
      merge->add_option("inputs", merge_inputs, "results.json files")->check(CLI::ExistingFile);
  auto* merge_shards_option =
      merge
          ->add_option("--shards", merge_shards_dir,
                       "A sharded run's folder (holebench slurm submit --out DIR): merges its "
                       "shard-I/ results in the suite's order; exit code 1, naming the shards, "
                       "if some are missing or incomplete")
          ->check(CLI::ExistingDirectory)
          ->excludes(merge_inputs_option);
  merge_inputs_option->excludes(merge_shards_option);
  merge->add_option("--out", merge_out,
                    "Output folder for the merged results.json and results.csv (with --shards, "
                    "default: the sharded run's folder); locked while merging, like run's --out");
  merge->add_flag("--allow-incomplete", merge_allow_incomplete,
                  "With --shards: merge the records there are even if shards are not complete");

  // holebench slurm submit | status | resubmit
  auto* slurm = app.add_subcommand(
      "slurm",
      "Run a suite on a Slurm cluster: a job array with one task per shard (holebench run "
      "--shard I/N); see docs/cluster.md");
  slurm->require_subcommand(1);
  holebench::harness::SlurmSubmitOptions submit_options;
  std::string submit_only;
  bool submit_no_snapshots = false;
  int submit_workers = 0;
  double submit_timeout = -1.0;
  auto* slurm_submit = slurm->add_subcommand(
      "submit",
      "Write DIR/shards.json and the sbatch script DIR/slurm/shards.sbatch (--array=0-(N-1), "
      "task I runs `holebench run --suite NAME --shard I/N --out DIR/shard-I --resume`) and "
      "submit it. sbatch options go after --, e.g. -- --partition=short --time=02:00:00");
  slurm_submit->add_option("--suite", submit_options.suite, "Suite name or path")->required();
  slurm_submit
      ->add_option("--shards", submit_options.shard_count,
                   "Number of shards N (array tasks 0 to N-1)")
      ->required()
      ->check(CLI::Range(std::size_t{1}, std::size_t{100000}));
  slurm_submit->add_option("--out", submit_options.out_dir, "The sharded run's folder")->required();
  slurm_submit->add_option("--workers,-j", submit_workers,
                           "Jobs at once in each task (default: the CPUs Slurm gives the task, "
                           "$SLURM_CPUS_PER_TASK)");
  slurm_submit
      ->add_option("--timeout", submit_timeout,
                   "Seconds a job may take before it is stopped (default: the suite's)")
      ->check(CLI::NonNegativeNumber);
  slurm_submit->add_flag("--no-snapshots", submit_no_snapshots, "Do not render a PNG per job");
  slurm_submit->add_option("--holebench", submit_options.holebench,
                           "The holebench binary the tasks run, on a file system the nodes "
                           "share (default: this one)");
  slurm_submit
      ->add_option("--only", submit_only,
                   "Submit only these shards (array indices), e.g. 1,3 or 0-2,7")
      ->check(parsed_by(shard_indices, "LIST"));
  slurm_submit->add_flag("--dry-run", submit_options.dry_run,
                         "Write the manifest and the script and print the sbatch command, "
                         "without submitting");
  slurm_submit->add_option("sbatch_options", submit_options.sbatch_options,
                           "Options for sbatch, after --");

  std::filesystem::path slurm_status_dir;
  auto* slurm_status = slurm->add_subcommand(
      "status",
      "Each shard of a sharded run: complete, incomplete (running, or its task failed) or "
      "missing, by name; exit code 1 unless all are complete");
  slurm_status->add_option("--out", slurm_status_dir, "The sharded run's folder")
      ->required()
      ->check(CLI::ExistingDirectory);

  holebench::harness::SlurmResubmitOptions resubmit_options;
  std::string resubmit_only;
  auto* slurm_resubmit = slurm->add_subcommand(
      "resubmit",
      "Submit again the shards that are not complete (or --only those), as array indices of the "
      "same script; each keeps the jobs it had finished. sbatch options go after -- (default: "
      "those of the submission)");
  slurm_resubmit->add_option("--out", resubmit_options.dir, "The sharded run's folder")
      ->required()
      ->check(CLI::ExistingDirectory);
  slurm_resubmit->add_option("--only", resubmit_only, "Resubmit only these shards, e.g. 1,3")
      ->check(parsed_by(shard_indices, "LIST"));
  slurm_resubmit->add_flag("--even-if-queued", resubmit_options.even_if_queued,
                           "Also resubmit shards whose task squeue still lists (pending or "
                           "running); by default they are left alone");
  slurm_resubmit->add_flag("--dry-run", resubmit_options.dry_run,
                           "Print the sbatch command without submitting");
  slurm_resubmit->add_option("sbatch_options", resubmit_options.sbatch_options,
                             "Options for sbatch, after --");

  auto* suites = app.add_subcommand("suites", "List the suites (suites/*.json)");

  std::filesystem::path compare_base, compare_new, junit_path;
  std::string compare_suite;
  auto* compare = app.add_subcommand(
      "compare", "Compare two results files job by job; exit code 1 on a regression");
  compare->add_option("base", compare_base, "Baseline results.json")
      ->required()
      ->check(CLI::ExistingFile);
  compare->add_option("new", compare_new, "New results.json")->required()->check(CLI::ExistingFile);
  compare->add_option("--suite", compare_suite,
                      "Suite whose tolerances judge regressions (default: the suite named in the "
                      "new results' context; without one, the built-in defaults)");
  compare->add_option("--junit", junit_path, "Also write a JUnit XML file for CI dashboards");

  std::vector<std::filesystem::path> validate_files;
  auto* validate = app.add_subcommand(
      "validate",
      "Check results files record by record: required fields, unique job ids, every metric a "
      "finite number in its range (_fraction, _ok/is_ flags, _count), lower <= value <= upper, "
      "mean <= RMS <= Hausdorff upper, no open hole in an ok job (docs/results.md). Prints each "
      "violation with its job id and a summary; exit code 0 if none, 1 on a violation, 2 on an "
      "unreadable file");
  validate->add_option("results", validate_files, "results.json files (job ids unique across them)")
      ->required();

  holebench::harness::FiguresOptions figures_options;
  std::filesystem::path figures_results;
  auto* figures = app.add_subcommand(
      "figures",
      "Regenerate the papers' figures and tables: B-Rep figure 5 (rendered), and with "
      "--results the slice paper's Table 2 and the crest-line paper's figures 10/13 setting");
  figures->add_option("--out", figures_options.out_dir, "Output folder")->required();
  figures
      ->add_option("--results", figures_results,
                   "results.json of the paper suite (holebench run --suite paper)")
      ->check(CLI::ExistingFile);

  std::vector<std::filesystem::path> history_files;
  std::filesystem::path history_out;
  holebench::harness::HistoryOptions history_options;
  auto* history = app.add_subcommand(
      "history",
      "Write DIR/history.html: per method, trend lines of the headline numbers (median hole "
      "Hausdorff distance, success share, fallback share, median method time) across "
      "successive results files (ordered by their context's date, then code version), with "
      "the regressions `holebench compare` flags between consecutive runs circled");
  history
      ->add_option("results", history_files,
                   "results.json files of successive runs (any order; at least one)")
      ->required();
  history->add_option("--out", history_out, "Output folder (created)")->required();
  history->add_option("--suite", history_options.suite,
                      "Suite whose tolerances judge regressions (default: the suite each newer "
                      "run names; without one, the built-in tolerances)");

  std::filesystem::path report_dir;
  auto* report = app.add_subcommand(
      "report", "Write DIR/report/: summary tables (Markdown, CSV, LaTeX), plots and an HTML page");
  report->add_option("dir", report_dir, "A run's output folder (with results.json)")
      ->required()
      ->check(CLI::ExistingDirectory);

  CLI11_PARSE(app, argc, argv);
  try {
    if (list->parsed()) {
      fmt::print("methods:\n");
      for (const auto& m : holebench::make_all_methods())
        fmt::print("  {:<16} {}\n", m->id(), m->description());
      fmt::print("variants run by name only (--method ID):\n");
      for (const auto& m : holebench::make_methods_run_by_name())
        fmt::print("  {:<16} {}\n", m->id(), m->description());
      fmt::print("external methods holebench predefines (run by name: --method NAME):\n");
      for (const auto& spec : holebench::predefined_external_methods())
        fmt::print("  {:<16} {}\n", spec.name, spec.command);
      fmt::print(
          "case families (see `holebench cases list`):\n"
          "  box/<target>                  the walking skeleton's box holes\n"
          "  brep/...                      synthetic planar B-Rep cases, k <= 3 and variants\n"
          "  solid/<name>/<target>/<size>  holes in procedural solids\n"
          "  cad/<model>/<target>/<size>   holes in CGAL's CAD meshes\n"
          "  file/<stem>/<target>/<size>   holes in your own meshes (--mesh)\n");
      return 0;
    }
    catalog_options.include_cad = !no_cad;
    catalog_options.families = holebench::harness::families_of_patterns(case_patterns);
    if (cases_list_cmd->parsed())
      return cases_list(CaseCatalog(catalog_options), case_patterns, with_labels);
    if (cases_export_cmd->parsed()) {
      return cases_export(CaseCatalog(catalog_options), case_patterns, export_dir, export_noise,
                          export_seed);
    }
    if (cases_gallery_cmd->parsed()) {
      const CaseCatalog catalog(catalog_options);
      const auto selected = holebench::harness::select_cases(
          catalog, case_patterns.empty() ? std::vector<std::string>{"brep/*"} : case_patterns);
      const auto page = holebench::harness::write_case_gallery(catalog, selected, gallery_dir);
      fmt::print("{}\n", page.string());
      return 0;
    }
    if (run->parsed()) {
      holebench::harness::RunOptions options = run_options;
      // A suite gives the defaults; options given on the command line override them.
      if (!suite_name.empty() || run_options.case_patterns.empty()) {
        options = holebench::harness::run_options_from_suite(
            holebench::harness::load_suite(suite_name.empty() ? "default" : suite_name));
        if (!run_options.case_patterns.empty())
          options.case_patterns = run_options.case_patterns;
        if (!run_options.method_ids.empty())
          options.method_ids = run_options.method_ids;
        if (run->count("--noise"))
          options.noise_levels = run_options.noise_levels;
        if (run->count("--seed"))
          options.seeds = run_options.seeds;
        if (run->count("--user"))
          options.users = run_options.users;
        if (run->count("--hausdorff-error-bound")) {
          options.evaluation.hausdorff_error_bound_rel_diag =
              run_options.evaluation.hausdorff_error_bound_rel_diag;
        }
        options.out_dir = run_options.out_dir;
      }
      options.catalog.user_meshes = run_options.catalog.user_meshes;
      options.catalog.prepare.tessellation = run_options.catalog.prepare.tessellation;
      if (run->count("--cad-dir"))
        options.catalog.cad_data_dir = run_options.catalog.cad_data_dir;
      if (no_cad)
        options.catalog.include_cad = false;
      options.snapshots = !no_snapshots;
      options.viewer_meshes = !no_viewer_meshes;
      options.runner.workers = workers;
      if (timeout >= 0.0)
        options.runner.timeout_seconds = timeout;
      options.runner.resume = resume;
      if (!memory_limit_text.empty())
        options.runner.memory_limit_bytes =
            holebench::harness::parse_memory_size(memory_limit_text);
      if (method_repetitions > 0)
        options.method_repetitions = method_repetitions;
      if (!shard_text.empty())
        options.shard = holebench::harness::parse_shard(shard_text);
      for (const auto& text : external_texts)
        options.external_methods.push_back(holebench::parse_external_method_spec(text));
      const auto summary = holebench::harness::run_jobs(options);
      print_summary_table(summary);
      return 0;
    }
    if (merge->parsed() && !merge_shards_dir.empty()) {
      holebench::harness::ShardMergeOptions options;
      options.dir = merge_shards_dir;
      options.out_dir = merge_out;
      options.allow_incomplete = merge_allow_incomplete;
      const auto result = holebench::harness::merge_shards(options);
      if (!result.written) {
        std::fprintf(stderr, "holebench: not merged: some shards are not complete\n%s",
                     holebench::harness::format_shard_status(result.status).c_str());
        return 1;
      }
      if (!result.missing_jobs.empty()) {
        std::fprintf(stderr, "holebench: %zu of %zu jobs missing (incomplete shards):\n%s",
                     result.missing_jobs.size(), result.status.manifest.job_ids.size(),
                     holebench::harness::format_shard_status(result.status).c_str());
      }
      std::fprintf(stderr, "%zu records from %zu shards into %s\n", result.merged.records.size(),
                   result.status.shards.size(), result.results_json.c_str());
      return 0;
    }
    if (merge->parsed()) {
      if (merge_inputs.empty() || merge_out.empty()) {
        std::fprintf(stderr,
                     "holebench merge: give results.json files and --out, or --shards DIR\n");
        return 2;
      }
      const holebench::harness::OutputFolderLock lock(merge_out);
      std::vector<holebench::harness::ResultsData> sets;
      for (const auto& path : merge_inputs) {
        sets.push_back(holebench::harness::read_results_json(path));
        // Snapshot paths follow the merged file (the report finds the pictures).
        for (auto& record : sets.back().records) {
          record.snapshot = holebench::harness::snapshot_relative_to(record.snapshot,
                                                                     path.parent_path(), merge_out);
        }
      }
      const auto merged = holebench::harness::merge_results(sets);
      std::filesystem::create_directories(merge_out);
      auto context = merged.context;
      holebench::harness::write_results_json(merge_out / "results.json", context, merged.records);
      holebench::harness::write_results_csv(merge_out / "results.csv", merged.records);
      std::fprintf(stderr, "%zu records from %zu files into %s\n", merged.records.size(),
                   sets.size(), (merge_out / "results.json").c_str());
      return 0;
    }
    if (slurm_submit->parsed()) {
      if (submit_no_snapshots)
        submit_options.run_arguments.push_back("--no-snapshots");
      if (submit_workers > 0) {
        submit_options.run_arguments.insert(submit_options.run_arguments.end(),
                                            {"--workers", std::to_string(submit_workers)});
      }
      if (submit_timeout >= 0.0) {
        submit_options.run_arguments.insert(submit_options.run_arguments.end(),
                                            {"--timeout", fmt::format("{}", submit_timeout)});
      }
      submit_options.only = shard_indices(submit_only);
      const auto result = holebench::harness::submit_shards(submit_options);
      print_submission(result, submit_options.out_dir);
      return 0;
    }
    if (slurm_status->parsed()) {
      const auto report = holebench::harness::shard_status(slurm_status_dir);
      fmt::print("{}", holebench::harness::format_shard_status(report));
      return report.all_complete() ? 0 : 1;
    }
    if (slurm_resubmit->parsed()) {
      resubmit_options.only = shard_indices(resubmit_only);
      const auto result = holebench::harness::resubmit_shards(resubmit_options);
      if (!result.warning.empty())
        fmt::print(stderr, "holebench slurm resubmit: {}\n", result.warning);
      if (!result.still_queued.empty()) {
        std::string queued;
        for (auto index : result.still_queued)
          queued += (queued.empty() ? "" : ", ") + holebench::harness::shard_folder_name(index);
        fmt::print(
            "Still in Slurm's queue, left alone: {} (--even-if-queued to resubmit them "
            "anyway)\n",
            queued);
      }
      if (result.shards.empty() && !result.still_queued.empty())
        return 0;
      if (result.shards.empty()) {
        fmt::print(
            "Every shard is complete: nothing to resubmit. Merge with: holebench merge "
            "--shards {}\n",
            resubmit_options.dir.string());
        return 0;
      }
      std::string names;
      for (auto index : result.shards)
        names += (names.empty() ? "" : ", ") + holebench::harness::shard_folder_name(index);
      fmt::print("Resubmitting {}\n", names);
      print_submission(result, resubmit_options.dir);
      return 0;
    }
    if (compare->parsed()) {
      const auto base_results = holebench::harness::read_results_json(compare_base);
      const auto new_results = holebench::harness::read_results_json(compare_new);
      bool used_defaults = false;
      const auto tolerances = holebench::harness::comparison_tolerances(
          compare_suite, new_results.context.suite, &used_defaults);
      if (used_defaults) {
        fmt::print(stderr,
                   "holebench compare: the results name no known suite ('{}'): judging by the "
                   "built-in tolerances (give --suite NAME for a suite's)\n",
                   new_results.context.suite);
      }
      const auto comparison =
          holebench::harness::compare_results(base_results, new_results, tolerances);
      holebench::harness::print_comparison(comparison, stdout);
      if (!junit_path.empty())
        holebench::harness::write_junit_xml(comparison, junit_path);
      return comparison.has_regression() ? 1 : 0;
    }
    if (validate->parsed())
      return validate_command(validate_files);
    if (figures->parsed()) {
      if (!figures_results.empty())
        figures_options.results = figures_results;
      for (const auto& path : holebench::harness::write_paper_figures(figures_options)) {
        fmt::print("{}\n", path.string());
      }
      if (!figures_options.results) {
        fmt::print(stderr,
                   "holebench figures: only figure 5 (it needs no results); Table 2 and the "
                   "crease table need --results of the paper suite (holebench run --suite paper "
                   "--out DIR)\n");
      } else {
        const auto data = holebench::harness::read_results_json(*figures_options.results);
        for (const auto& gap : holebench::harness::paper_figure_gaps(data))
          fmt::print(stderr, "holebench figures: {} (run the paper suite)\n", gap);
      }
      return 0;
    }
    if (history->parsed()) {
      std::vector<holebench::harness::HistoryRun> runs;
      for (const auto& file : history_files)
        runs.push_back({file.string(), holebench::harness::read_results_json(file)});
      const auto result = holebench::harness::compute_history(std::move(runs), history_options);
      for (const auto& note : result.notes)
        fmt::print(stderr, "holebench history: {}\n", note);
      std::size_t flagged = 0;
      for (const auto& per_method : result.regressions) {
        for (const auto& jobs : per_method)
          flagged += jobs.empty() ? 0 : 1;
      }
      const auto path = holebench::harness::write_history(result, history_out);
      fmt::print("{} runs, {} methods, {} regression marks\nHistory: {}\n", result.runs.size(),
                 result.methods.size(), flagged, path.string());
      return 0;
    }
    if (report->parsed()) {
      const auto data = holebench::harness::read_results_json(report_dir / "results.json");
      const holebench::harness::report::ReportOptions report_options;
      const auto summary =
          holebench::harness::report::write_report(data, report_dir, report_options);
      fmt::print("{}", holebench::harness::report::console_summary(data, report_options));
      fmt::print("\nReport: {}\n", (summary.dir / "report.html").string());
      return 0;
    }
    if (suites->parsed()) {
      for (const auto& name : holebench::harness::list_suites()) {
        const auto suite = holebench::harness::load_suite(name);
        fmt::print("{:<10} {}\n", name, suite.description);
      }
      return 0;
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
