#include "harness/run/run_jobs.h"

#include "core/stopwatch.h"
#include "generators/case_catalog.h"
#include "harness/outputs/render/image.h"
#include "harness/results/output_folder_lock.h"
#include "harness/results/results_file.h"
#include "harness/run/case_selection.h"
#include "harness/run/oracle_user.h"
#include "methods/external/predefined_external_methods.h"
#include "methods/registry.h"

#include <fmt/format.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <future>
#include <map>
#include <memory>
#include <stdexcept>

namespace holebench::harness {

namespace {

bool is_builtin_method(const std::string& id) {
  return find_method(id) != nullptr;
}

// The external methods by name: those defined for the run, each once and none named like a
// built-in.
std::map<std::string, ExternalMethodSpec> defined_external_methods(const RunOptions& options) {
  std::map<std::string, ExternalMethodSpec> defined;
  for (const auto& spec : options.suite.external_methods) {
    check_external_method_name(spec.name);
    check_command_template(spec.command);
    if (is_builtin_method(spec.name)) {
      throw std::invalid_argument("external method '" + spec.name +
                                  "': that is a built-in method's id");
    }
    if (!defined.emplace(spec.name, spec).second)
      throw std::invalid_argument("external method '" + spec.name + "' is defined twice");
  }
  return defined;
}

// The suite's case patterns; none: the default ones.
std::vector<std::string> case_patterns_of(const Suite& suite) {
  return suite.case_patterns.empty() ? default_case_patterns() : suite.case_patterns;
}

}  // namespace

std::vector<Job> plan_jobs(const RunOptions& options, const generators::CaseCatalog& catalog) {
  const auto cases = select_cases(catalog, case_patterns_of(options.suite));
  std::map<std::string, ExternalMethodSpec> external = defined_external_methods(options);
  std::vector<std::string> methods = options.suite.methods;
  if (methods.empty()) {
    for (const auto& method : make_all_methods())
      methods.push_back(method->id());
  }
  for (const auto& id : methods) {
    if (external.count(id) || is_builtin_method(id))
      continue;
    if (auto predefined = find_predefined_external_method(id))
      external.emplace(id, *predefined);
    else
      make_method(id);  // throws for an unknown id
  }
  for (const auto& spec : options.suite.external_methods) {
    if (std::find(methods.begin(), methods.end(), spec.name) == methods.end())
      methods.push_back(spec.name);
  }
  for (const auto& user : options.suite.users)
    check_user_kind(user);
  std::map<std::string, MethodOptions> builtin_options;
  for (const auto& id : methods) {
    if (!external.count(id))
      builtin_options[id] = make_method(id)->options();
  }
  std::vector<Job> jobs;
  for (const auto& c : cases) {
    for (const auto& method_id : methods) {
      for (const auto& user : options.suite.users) {
        for (double noise : options.suite.noise_levels) {
          for (auto seed : options.suite.seeds) {
            Job job;
            job.case_id = c.id;
            job.method_id = method_id;
            job.noise_percent = noise;
            job.seed = seed;
            job.user = user;
            if (const auto it = external.find(method_id); it != external.end())
              job.external = it->second;
            else
              job.method_options = builtin_options.at(method_id);
            jobs.push_back(std::move(job));
          }
        }
      }
    }
  }
  return jobs;
}

generators::CatalogOptions run_catalog_options(const RunOptions& options) {
  generators::CatalogOptions catalog_options;
  catalog_options.cad_data_dir = options.cad_data_dir;
  catalog_options.include_cad = options.suite.include_cad;
  catalog_options.user_meshes = options.suite.meshes;
  catalog_options.prepare = options.prepare;
  catalog_options.families = families_of_patterns(case_patterns_of(options.suite));
  return catalog_options;
}

ProcessPoolOptions runner_options_of(const RunOptions& options) {
  ProcessPoolOptions runner;
  runner.workers = options.workers;
  runner.timeout_seconds = options.suite.timeout_seconds;
  runner.memory_limit_bytes = options.suite.memory_limit_bytes;
  runner.resume = options.resume;
  runner.progress = options.progress;
  return runner;
}

int threads_per_job_of(int workers) {
  return std::max(1, worker_count_of(0) / worker_count_of(workers));
}

RunSummary run_jobs(const RunOptions& options) {
  const auto start = SteadyClock::now();
  const OutputFolderLock lock(options.out_dir);  // one run per folder, until this returns
  // The image-file module and its plugins load (about 0.4 s) while the catalogue is made;
  // waited for before the first fork, so that every job's process finds them loaded.
  std::future<void> png_writer;
  if (options.snapshots)
    png_writer = std::async(std::launch::async, render::load_png_writer);
  const generators::CaseCatalog catalog(run_catalog_options(options));
  print_catalog_notes(catalog);
  const std::vector<Job> jobs = jobs_of_shard(
      options.jobs.empty() ? plan_jobs(options, catalog) : options.jobs, options.shard);
  std::filesystem::create_directories(options.out_dir);
  JobOptions job_options;
  job_options.catalog = &catalog;
  job_options.evaluation = options.suite.evaluation;
  job_options.method_repetitions = options.suite.method_repetitions;
  if (options.snapshots) {
    job_options.snapshot_dir = options.out_dir / "snapshots";
    if (options.viewer_meshes)
      job_options.viewer_mesh_dir = options.out_dir;
    std::filesystem::create_directories(job_options.snapshot_dir);
    png_writer.get();  // loaded once here, not in every job's process
  }
  if (options.repaired_meshes) {
    job_options.repaired_mesh_dir = options.out_dir / "repaired";
    std::filesystem::create_directories(job_options.repaired_mesh_dir);
  }
  if (options.scored_repairs)
    job_options.scored_repairs = &*options.scored_repairs;
  if (options.layers) {
    job_options.layers_dir = options.out_dir / "layers";
    std::filesystem::create_directories(job_options.layers_dir);
  }
  RunSummary summary;
  const JobFunction run_one = [&](const Job& job) { return run_job(job, job_options); };
  if (options.in_process) {
    for (const auto& job : jobs) {
      summary.records.push_back(run_one(job));
      if (summary.records.back().status != JobStatus::Ok)
        ++summary.failures;
    }
  } else {
    ProcessPoolOptions runner = runner_options_of(options);
    std::map<std::string, std::pair<std::string, std::string>> family_kind;
    for (const auto& d : catalog.cases())
      family_kind[d.id] = {d.family, d.kind};
    runner.case_family_kind = [&family_kind](const std::string& id) {
      const auto it = family_kind.find(id);
      return it != family_kind.end() ? it->second : std::pair<std::string, std::string>();
    };
    // The jobs of one case instance (id, noise level, seed) share its making: their group
    // makes it once and runs each job on it (in a child process of its own). The first job
    // of a group carries the case's time in its "case" stage, the others 0.
    const GroupKeyFunction case_instance = [](const Job& job) { return job.case_instance(); };
    // A group's threads (making the case, the evaluation's parallel searches, Embree's
    // builds): the cores shared among the workers, so that the workers do not take turns on
    // the same cores. The limit is set in the group's process and held by its job function,
    // so it covers the making of the case and every job forked from it.
    const int threads_per_job = threads_per_job_of(runner.workers);
    const GroupFunction prepare = [&job_options,
                                   threads_per_job](const std::vector<Job>& group) -> JobFunction {
      auto threads = std::make_shared<const tbb::global_control>(
          tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads_per_job));
      auto made = std::make_shared<PreparedCase>(prepare_case(group.front(), job_options));
      if (group.size() > 1)
        share_case_work(*made, job_options);
      std::shared_ptr<const PreparedCase> prepared = std::move(made);
      const std::string first = group.front().id();
      return [threads, prepared, first, &job_options](const Job& job) {
        return run_job_on_case(job, *prepared, job.id() == first, job_options);
      };
    };
    ProcessPoolResult result =
        run_grouped(jobs, case_instance, prepare, options.out_dir / "records.jsonl", runner);
    summary.records = std::move(result.records);
    summary.failures = result.failures;
  }
  summary.results_json = options.out_dir / "results.json";
  summary.results_csv = options.out_dir / "results.csv";
  RunContext context = current_context(options.suite.name);
  if (options.shard.count > 1)
    context.shard = to_string(options.shard);
  write_results_json(summary.results_json, context, summary.records);
  write_results_csv(summary.results_csv, summary.records);
  summary.seconds = seconds_since(start);
  return summary;
}

}  // namespace holebench::harness
