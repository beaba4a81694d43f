#include "harness/run_command.h"

#include "generators/case_catalog.h"
#include "harness/case_selection.h"
#include "harness/oracle_user.h"
#include "harness/results_file.h"
#include "methods/registry.h"

#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <stdexcept>

namespace holebench::harness {

std::vector<Job> plan_jobs(const RunOptions& options, const generators::CaseCatalog& catalog) {
  const auto cases = select_cases(
      catalog, options.case_patterns.empty() ? default_case_patterns() : options.case_patterns);
  std::vector<std::string> methods = options.method_ids;
  if (methods.empty()) {
    for (const auto& method : make_all_methods())
      methods.push_back(method->id());
  } else {
    for (const auto& id : methods)
      make_method(id);  // throws for an unknown id
  }
  for (const auto& user : options.users)
    check_user_kind(user);
  std::vector<Job> jobs;
  for (const auto& c : cases) {
    for (const auto& method_id : methods) {
      for (const auto& user : options.users) {
        for (double noise : options.noise_levels) {
          for (auto seed : options.seeds)
            jobs.push_back({c.id, method_id, noise, seed, user});
        }
      }
    }
  }
  return jobs;
}

RunSummary run_jobs(const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  generators::CatalogOptions catalog_options = options.catalog;
  if (catalog_options.families.empty()) {
    catalog_options.families = families_of_patterns(
        options.case_patterns.empty() ? default_case_patterns() : options.case_patterns);
  }
  const generators::CaseCatalog catalog(catalog_options);
  const std::vector<Job> jobs = plan_jobs(options, catalog);
  std::filesystem::create_directories(options.out_dir);
  JobOptions job_options;
  job_options.catalog = &catalog;
  job_options.evaluation = options.evaluation;
  if (options.snapshots) {
    job_options.snapshot_dir = options.out_dir / "snapshots";
    std::filesystem::create_directories(job_options.snapshot_dir);
  }

  RunSummary summary;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const auto job_start = std::chrono::steady_clock::now();
    JobRecord record = run_job(jobs[i], job_options);
    if (record.status != JobStatus::Ok)
      ++summary.failures;
    if (options.progress) {
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - job_start).count();
      std::fprintf(stderr, "[%zu/%zu] %-56s %-8s %.2fs%s%s\n", i + 1, jobs.size(),
                   jobs[i].id().c_str(), to_string(record.status), seconds,
                   record.message.empty() ? "" : "  ", record.message.c_str());
    }
    summary.records.push_back(std::move(record));
  }
  summary.results_json = options.out_dir / "results.json";
  summary.results_csv = options.out_dir / "results.csv";
  write_results_json(summary.results_json, current_context("skeleton"), summary.records);
  write_results_csv(summary.results_csv, summary.records);
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace holebench::harness
