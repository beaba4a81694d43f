// holebench evaluate: repairs made elsewhere, scored. Against exported cases (--cases), into
// the records a run writes; or one pair of mesh files (--complete, --repaired), printed.
#include "core/mesh_io.h"
#include "harness/cli/common_flags.h"
#include "harness/cli/subcommands.h"
#include "harness/run/exported_cases.h"
#include "harness/run/mesh_pair_evaluation.h"
#include "harness/run/resolve_run_options.h"
#include "harness/run/run_jobs.h"
#include "harness/run/run_summary_table.h"
#include "harness/run/scored_repairs.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace holebench::harness::cli {

namespace {

namespace fs = std::filesystem;

struct EvaluateValues {
  // Against exported cases:
  std::vector<fs::path> cases;
  std::string method;
  std::string user = "no_user";
  RunFlags run;  ///< --out, --no-snapshots, --no-viewer-meshes, --workers
  generators::CatalogOptions catalog;
  double timeout = -1.0;
  // One pair:
  fs::path complete;
  fs::path holed;
  bool json = false;
  // Both:
  fs::path repaired;
  double hausdorff_error_bound_rel_diag = EvaluationOptions{}.hausdorff_error_bound_rel_diag;
};

int evaluate_cases(const EvaluateValues& values) {
  if (values.method.empty() || values.run.out_dir.empty())
    throw std::invalid_argument("--cases needs --method NAME and --out DIR");
  if (!fs::is_directory(values.repaired))
    throw std::invalid_argument("--repaired " + values.repaired.string() +
                                ": no such folder of repaired meshes");
  const std::vector<ExportedCase> exported = find_exported_cases(values.cases);
  RunFlags flags = values.run;
  std::set<std::string> ids;
  for (const auto& c : exported)
    ids.insert(c.id);
  flags.case_patterns.assign(ids.begin(), ids.end());
  flags.user_meshes = values.catalog.user_meshes;
  flags.brep_tessellation = values.catalog.prepare.tessellation;
  if (!values.catalog.cad_data_dir.empty())
    flags.cad_data_dir = values.catalog.cad_data_dir;
  flags.hausdorff_error_bound_rel_diag = values.hausdorff_error_bound_rel_diag;
  if (values.timeout >= 0.0)
    flags.timeout_seconds = values.timeout;
  Suite suite = ad_hoc_suite();
  suite.name = "evaluate";
  RunOptions options = resolve_run_options(suite, flags);
  ScoredRepairs scored;
  scored.repaired_dir = values.repaired;
  std::set<std::string> instances;
  for (const auto& c : exported) {
    Job job = scoring_job(c, values.method, values.user);
    if (!instances.insert(job.case_instance()).second) {
      throw std::invalid_argument(fmt::format(
          "case {} (noise {}, seed {}) is exported twice under --cases (the second in {})", c.id,
          c.noise_percent, c.seed, c.dir.string()));
    }
    scored.exported_inputs[job.case_instance()] = c.input;
    options.jobs.push_back(std::move(job));
  }
  options.scored_repairs = std::move(scored);
  const auto summary = run_jobs(options);
  fmt::print("{}", format_run_summary(summary));
  return 0;
}

std::string metric_text(double value) {
  return fmt::format("{:.6g}", value);
}

int evaluate_pair(const EvaluateValues& values) {
  if (!values.run.out_dir.empty() || !values.method.empty() || !values.cases.empty())
    throw std::invalid_argument("--complete takes --repaired, --holed and --json only");
  const Mesh complete = read_mesh(values.complete);
  const TriangleSoup repaired = read_soup(values.repaired);
  std::optional<Mesh> holed;
  if (!values.holed.empty())
    holed = read_mesh(values.holed);
  EvaluationOptions options;
  options.hausdorff_error_bound_rel_diag = values.hausdorff_error_bound_rel_diag;
  const MeshPairEvaluation pair =
      evaluate_mesh_pair(complete, repaired, holed ? &*holed : nullptr, options);
  if (values.json) {
    nlohmann::ordered_json j;
    j["complete"] = values.complete.string();
    j["repaired"] = values.repaired.string();
    if (holed)
      j["holed"] = values.holed.string();
    j.update(mesh_pair_to_json(pair, holed.has_value()));
    fmt::print("{}\n", j.dump(2));
    return 0;
  }
  fmt::print("complete  {} (bounding-box diagonal {})\nrepaired  {}\n", values.complete.string(),
             metric_text(pair.diagonal), values.repaired.string());
  if (holed) {
    fmt::print("holed     {} ({} holes, {} faces removed, {} new faces)\n", values.holed.string(),
               pair.holes, pair.removed_faces, pair.new_faces);
  }
  if (!pair.note.empty())
    fmt::print("note: {}\n", pair.note);
  fmt::print("\n| metric | value |\n| --- | --- |\n");
  for (const auto& metric : pair.metrics)
    fmt::print("| {} | {} |\n", metric.name, metric_text(metric.value));
  return 0;
}

}  // namespace

Subcommand add_evaluate_command(CLI::App& app) {
  auto values = std::make_shared<EvaluateValues>();
  auto* command = app.add_subcommand(
      "evaluate",
      "Score repairs made elsewhere: a folder of repaired meshes against exported cases "
      "(--cases, into a run's records), or one repaired mesh against a complete one "
      "(--complete; docs/evaluate.md)");
  auto* cases =
      command
          ->add_option("--cases", values->cases,
                       "Folder of cases written by `holebench cases export` (searched to any "
                       "depth for case.json), repeatable")
          ->check(CLI::ExistingPath);
  command
      ->add_option("--repaired", values->repaired,
                   "With --cases: the folder of repaired meshes, one per case, named "
                   "<case>.ply (each '/' of the case id made '_'; also .off .obj .stl), or as "
                   "`run --repaired-meshes` names them. With --complete: the repaired mesh file")
      ->required()
      ->check(CLI::ExistingPath);
  command->add_option("--method", values->method,
                      "With --cases: the name the records give the method that made the repairs");
  command->add_option("--user", values->user,
                      "With --cases: the user the job ids name (no_user, oracle; default no_user)");
  command->add_option("--out", values->run.out_dir,
                      "With --cases: the output folder, as `run` writes it (results.json, "
                      "snapshots/, ...), for report, compare, history and figures");
  command->add_flag("--no-snapshots", values->run.no_snapshots,
                    "With --cases: do not render a PNG per job");
  command->add_flag("--no-viewer-meshes", values->run.no_viewer_meshes,
                    "With --cases: do not write the report's 3D viewer meshes");
  command
      ->add_option("--workers,-j", values->run.workers,
                   "With --cases: jobs at once (default: the number of cores)")
      ->check(CLI::NonNegativeNumber);
  command
      ->add_option("--timeout", values->timeout,
                   "With --cases: seconds a job's evaluation may take (default 300)")
      ->check(CLI::NonNegativeNumber);
  add_catalog_flags(command, values->catalog, values->run.no_cad);
  auto* complete =
      command
          ->add_option("--complete", values->complete,
                       "One pair: the complete mesh (ground truth), any mesh file (OFF, OBJ, "
                       "STL, PLY)")
          ->check(CLI::ExistingFile);
  command
      ->add_option("--holed", values->holed,
                   "With --complete: the holed mesh the repair was made from (adds the "
                   "hole-region metrics)")
      ->check(CLI::ExistingFile);
  command->add_flag("--json", values->json, "With --complete: print the metrics as JSON");
  command
      ->add_option("--hausdorff-error-bound", values->hausdorff_error_bound_rel_diag,
                   "Error bound of the Hausdorff distance, relative to the diagonal")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cases->excludes(complete);
  return {command, [values, cases, complete] {
            if (complete->count() > 0)
              return evaluate_pair(*values);
            if (cases->count() > 0)
              return evaluate_cases(*values);
            throw std::invalid_argument("evaluate needs --cases DIR or --complete FILE");
          }};
}

}  // namespace holebench::harness::cli
