// `holebench run`: every selected case x method as a job, records written to a folder.
#pragma once

#include "harness/cluster/shard.h"
#include "harness/run/job.h"
#include "harness/run/runner.h"
#include "harness/run/suite.h"

#include <filesystem>
#include <string>
#include <vector>

namespace holebench::harness {

struct RunOptions {
  std::filesystem::path out_dir;
  /// Case ids or wildcard patterns ('*', '?'); empty: default_case_patterns().
  std::vector<std::string> case_patterns;
  std::vector<std::string> method_ids;  ///< built-in or external method ids; empty: every built-in
  /// External methods defined for this run (--external, a suite's "external_methods"): each
  /// runs beside `method_ids`. A predefined one (meshlab_close_holes) may also be named in
  /// `method_ids` without being defined here.
  std::vector<ExternalMethodSpec> external_methods;
  std::vector<std::string> users{"no_user"};  ///< "no_user", "oracle"
  std::vector<double> noise_levels{0.0};      ///< % of 1 % of the diagonal
  std::vector<std::uint64_t> seeds{0};
  generators::CatalogOptions catalog;
  bool snapshots = true;
  /// With the snapshots, the report's 3D viewer meshes (meshes/, outputs/viewer/viewer_mesh.h).
  bool viewer_meshes = true;
  EvaluationOptions evaluation;
  std::string suite_name = "ad hoc";  ///< written into the results' context
  RunnerOptions runner;               ///< workers, timeout, resume, progress
  int method_repetitions = 1;         ///< runs of the method per job (JobOptions)
  /// The slice of the jobs to run (harness/cluster/shard.h); the default, 0/1, is every job.
  ShardSpec shard;
  /// Run each job in this process instead of a child process (tests; no isolation).
  bool in_process = false;
};

/// The run options of a suite (its cases, methods, users, noise levels, seeds, options).
RunOptions run_options_from_suite(const Suite& suite);

struct RunSummary {
  std::vector<JobRecord> records;
  std::size_t failures = 0;  ///< jobs whose status is not ok
  double seconds = 0.0;
  std::filesystem::path results_json;
  std::filesystem::path results_csv;
};

/// The jobs of `options` over `catalog`, in a fixed order (case, method, noise, seed); the
/// methods are `method_ids` (every built-in if empty), then the external methods not named
/// there. Throws std::invalid_argument for an unknown case or method id, and for an external
/// method whose name is a built-in's or is defined twice.
std::vector<Job> plan_jobs(const RunOptions& options, const generators::CaseCatalog& catalog);

/// The catalog options `run_jobs` builds its catalog with: `options.catalog`, limited to the
/// families of the case patterns.
generators::CatalogOptions run_catalog_options(const RunOptions& options);

/// Runs the jobs of `options.shard` (isolated, in parallel: harness/run/runner.h) and writes
/// records.jsonl (as jobs finish), results.json, results.csv and snapshots/ into `options.out_dir`.
/// Holds the folder's lock meanwhile (harness/run/output_folder_lock.h): throws OutputFolderInUse,
/// before running anything, when another process holds it.
RunSummary run_jobs(const RunOptions& options);

}  // namespace holebench::harness
