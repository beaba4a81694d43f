// `holebench run`: every selected case x method as a job, records written to a folder.
#pragma once

#include "harness/run/job.h"
#include "harness/run/process_pool.h"
#include "harness/run/shard.h"
#include "harness/run/suite.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace holebench::harness {

struct RunOptions {
  /// What runs and how it is judged: the suite's cases, methods, external methods, users,
  /// noise levels, seeds, CAD models and meshes, timeout, memory limit, method repetitions and
  /// evaluation options, with the command line's overrides already applied
  /// (harness/run/resolve_run_options.h). Its name goes into the results' context. Default:
  /// an ad hoc suite of the built-in defaults (ad_hoc_suite()).
  Suite suite = ad_hoc_suite();
  std::filesystem::path out_dir;
  /// Where the CGAL data set's models are (generators/case_catalog.h).
  std::filesystem::path cad_data_dir = generators::default_cad_data_dir();
  generators::PrepareOptions prepare;  ///< how model files are read (B-Rep tessellation)
  bool snapshots = true;
  /// With the snapshots, the report's 3D viewer meshes (meshes/, outputs/viewer/viewer_mesh.h).
  bool viewer_meshes = true;
  /// Ask the methods for their steps as geometry and draw them into layers/ (`--layers`,
  /// JobOptions::layers_dir).
  bool layers = false;
  /// Write each job's repaired mesh and its method's record into repaired/ (`--repaired-meshes`,
  /// harness/run/scored_repairs.h), to be scored again by `holebench evaluate --cases`.
  bool repaired_meshes = false;
  /// Set (`holebench evaluate --cases`): exactly these jobs, instead of the suite's plan (whose
  /// cases must still name their families, for the catalog), ...
  std::vector<Job> jobs;
  /// ... and their results read from files instead of running their methods.
  std::optional<ScoredRepairs> scored_repairs;
  int workers = 0;       ///< processes at once; 0: the number of cores
  bool resume = false;   ///< keep the records already in the folder's records.jsonl
  bool progress = true;  ///< progress on stderr
  /// The slice of the jobs to run (harness/run/shard.h); the default, 0/1, is every job.
  ShardSpec shard;
  /// Run each job in this process instead of a child process (tests; no isolation).
  bool in_process = false;
};

struct RunSummary {
  std::vector<JobRecord> records;
  std::size_t failures = 0;  ///< jobs whose status is not ok
  double seconds = 0.0;
  std::filesystem::path results_json;
  std::filesystem::path results_csv;
};

/// The jobs of `options` over `catalog`, in a fixed order (case, method, noise, seed); the
/// methods are the suite's `methods` (every built-in if empty), then its external methods not
/// named there. Throws std::invalid_argument for an unknown case or method id, and for an external
/// method whose name is a built-in's or is defined twice.
std::vector<Job> plan_jobs(const RunOptions& options, const generators::CaseCatalog& catalog);

/// The catalog options `run_jobs` builds its catalog with: the suite's CAD models and meshes,
/// `cad_data_dir` and `prepare`, limited to the families of the suite's case patterns.
generators::CatalogOptions run_catalog_options(const RunOptions& options);

/// The threads one job may use when `workers` (0: one per core) run at once: the cores shared
/// among them, at least one.
int threads_per_job_of(int workers);

/// The process pool's options: workers, resume and progress from `options`, the timeout and
/// memory limit of each job from its suite.
ProcessPoolOptions runner_options_of(const RunOptions& options);

/// Runs the jobs of `options.shard` (isolated, in parallel: harness/run/process_pool.h) and writes
/// records.jsonl (as jobs finish), results.json, results.csv and snapshots/ into `options.out_dir`.
/// Holds the folder's lock meanwhile (harness/results/output_folder_lock.h): throws
/// OutputFolderInUse, before running anything, when another process holds it.
RunSummary run_jobs(const RunOptions& options);

}  // namespace holebench::harness
