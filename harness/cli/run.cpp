// holebench run: a suite, or cases x methods x users x noise x seeds, into a folder.
#include "harness/cli/common_flags.h"
#include "harness/cli/subcommands.h"
#include "harness/run/memory_limit.h"
#include "harness/run/resolve_run_options.h"
#include "harness/run/run_jobs.h"
#include "harness/run/run_summary_table.h"
#include "harness/run/shard.h"
#include "methods/external/external_method_spec.h"

#include <fmt/format.h>

#include <memory>
#include <string>
#include <vector>

namespace holebench::harness::cli {

namespace {

// What CLI11 fills in; run_flags() turns it into RunFlags once parsed.
struct RunCliValues {
  RunFlags flags;  ///< the flags CLI11 can fill in directly
  std::vector<std::string> external_texts;
  std::vector<double> noise_levels;
  std::vector<std::uint64_t> seeds;
  std::vector<std::string> users;
  double hausdorff_error_bound_rel_diag = EvaluationOptions{}.hausdorff_error_bound_rel_diag;
  generators::CatalogOptions catalog;  ///< --mesh, --brep-deflection, --cad-dir
  double timeout = -1.0;
  std::string memory_limit_text;
  std::string shard_text;
  int method_repetitions = 0;
};

// The flags given to `run` (CLI11 counts which ones were).
RunFlags run_flags(const CLI::App& run, const RunCliValues& values) {
  RunFlags flags = values.flags;
  for (const auto& text : values.external_texts)
    flags.external_methods.push_back(parse_external_method_spec(text));
  if (run.count("--noise"))
    flags.noise_levels = values.noise_levels;
  if (run.count("--seed"))
    flags.seeds = values.seeds;
  if (run.count("--user"))
    flags.users = values.users;
  if (run.count("--hausdorff-error-bound"))
    flags.hausdorff_error_bound_rel_diag = values.hausdorff_error_bound_rel_diag;
  flags.user_meshes = values.catalog.user_meshes;
  flags.brep_tessellation = values.catalog.prepare.tessellation;
  if (run.count("--cad-dir"))
    flags.cad_data_dir = values.catalog.cad_data_dir;
  if (values.timeout >= 0.0)
    flags.timeout_seconds = values.timeout;
  if (!values.memory_limit_text.empty())
    flags.memory_limit_bytes = parse_memory_size(values.memory_limit_text);
  if (values.method_repetitions > 0)
    flags.method_repetitions = values.method_repetitions;
  if (!values.shard_text.empty())
    flags.shard = parse_shard(values.shard_text);
  return flags;
}

int run(const CLI::App& run, const RunCliValues& values) {
  const RunFlags flags = run_flags(run, values);
  const auto summary = run_jobs(resolve_run_options(suite_of_run_flags(flags), flags));
  fmt::print("{}", format_run_summary(summary));
  return 0;
}

}  // namespace

Subcommand add_run_command(CLI::App& app) {
  auto values = std::make_shared<RunCliValues>();
  auto& flags = values->flags;
  auto* run = app.add_subcommand(
      "run",
      "Run a suite (or cases x methods x users x noise x seeds) into a folder; each job in "
      "its own process, in parallel");
  run->add_option("--out", flags.out_dir,
                  "Output folder (created if missing). One holebench process at a time: while a "
                  "run or merge holds it (DIR/.holebench.lock), another exits with code 2")
      ->required();
  run->add_option("--suite", flags.suite,
                  "Suite name (suites/<name>.json: smoke, default, nightly, paper) or path; the "
                  "options below, where given, override it");
  run->add_option("--case", flags.case_patterns,
                  "Case id or pattern, repeatable (default: the default suite's)");
  run->add_option("--method", flags.method_ids,
                  "Method id, repeatable (default: every built-in method): a built-in, a "
                  "predefined external method (meshlab_close_holes) or an --external name");
  run->add_option("--external", values->external_texts,
                  "A program as a method, repeatable: 'name=NAME;command=COMMAND', COMMAND "
                  "reading {input} (the holed mesh, binary PLY) and writing {output} (the "
                  "repaired mesh, PLY; the input's faces unchanged, new faces are the patch), "
                  "e.g. 'name=my_fill;command=python3 my_fill.py {input} {output}'. It runs "
                  "beside the --method ids (default: every built-in); add --method NAME to run "
                  "it alone. Optional before command=: vertex_tolerance_rel_diag=X, to match "
                  "single-precision output (docs/methods.md)")
      ->type_name("'name=NAME;command=COMMAND'")
      ->check(parsed_by(parse_external_method_spec, "'name=NAME;command=COMMAND'"));
  run->add_option("--noise", values->noise_levels,
                  "Noise level in % of 1 % of the diagonal, repeatable (default: 0)")
      ->check(CLI::NonNegativeNumber);
  run->add_option("--seed", values->seeds, "Seed, repeatable (default: 0)");
  run->add_option("--user", values->users,
                  "Who answers the methods' questions: no_user (default) or oracle (from the "
                  "ground truth); repeatable");
  run->add_flag("--no-snapshots", flags.no_snapshots, "Do not render a PNG per job");
  run->add_flag("--no-viewer-meshes", flags.no_viewer_meshes,
                "Do not write the report's 3D viewer meshes (meshes/) with the snapshots");
  run->add_flag("--layers", flags.layers,
                "Ask each method for its steps as geometry (segments, missing edges, slices, "
                "crest lines, feature lines, sub-holes, faces, transitions, arrows) and draw "
                "them: layers/<job>.png, one panel per step, and layers/<job>.obj. Metrics "
                "ignore them. Meant for a single job or a few");
  run->add_flag("--repaired-meshes", flags.repaired_meshes,
                "Write each job's repaired mesh (repaired/<job>.ply, the whole model) and what "
                "its method reported (repaired/<job>.method.json), to score them again with "
                "`holebench evaluate --cases` (docs/evaluate.md)");
  run->add_option("--workers,-j", flags.workers, "Jobs at once (default: the number of cores)")
      ->check(CLI::NonNegativeNumber);
  run->add_option("--timeout", values->timeout,
                  "Seconds a job may take before it is stopped (default: the suite's, 300)")
      ->check(CLI::NonNegativeNumber);
  run->add_option("--memory-limit", values->memory_limit_text,
                  "Address space each job's process may take (RLIMIT_AS), e.g. 4G, 512M; 0: "
                  "none. A job past it gets the status out_of_memory and the run goes on "
                  "(default: the suite's, 4G)")
      ->type_name("SIZE")
      ->check(parsed_by(parse_memory_size, "SIZE"));
  run->add_flag("--resume", flags.resume,
                "Keep the records already in DIR/records.jsonl and run the rest");
  run->add_option("--shard", values->shard_text,
                  "Run only shard I of N (0 <= I < N): the suite's case instances g (case, noise, "
                  "seed; in plan order) with g mod N = I, all their jobs, in "
                  "plan order; the N shards together are the suite, each job once (e.g. 0/4)")
      ->type_name("I/N")
      ->check(parsed_by(parse_shard, "I/N"));
  run->add_option("--method-repetitions", values->method_repetitions,
                  "Run each job's method N times and record the median wall time (the first "
                  "run's result is evaluated; default: the suite's, 1)")
      ->check(CLI::Range(1, 1000));
  run->add_option("--hausdorff-error-bound", values->hausdorff_error_bound_rel_diag,
                  "Error bound of the Hausdorff distance, relative to the diagonal")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  add_catalog_flags(run, values->catalog, flags.no_cad);
  return {run, [run, values] { return cli::run(*run, *values); }};
}

}  // namespace holebench::harness::cli
