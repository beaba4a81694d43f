// One job: a case x a method x a seed, and the record it produces.
#pragma once

#include "core/statistics.h"  // median_of: a job's method time over repetitions
#include "generators/case_catalog.h"
#include "methods/external/external_method_spec.h"
#include "methods/method.h"
#include "metrics/case_evaluation.h"
#include "metrics/evaluation.h"

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace holebench::render {
class CasePicture;
}

namespace holebench::harness {

struct Job {
  std::string case_id;
  std::string method_id;
  double noise_percent = 0.0;  ///< vertex noise of the input, % of 1 % of the diagonal
  std::uint64_t seed = 0;
  std::string user = "no_user";  ///< who answers the method's questions: "no_user", "oracle"
  /// Set when the method is an external program (`method_id` is its name): the command the
  /// job runs, which its record names ("method_options").
  std::optional<ExternalMethodSpec> external;
  /// A built-in method's settings (Method::options, set when the run is planned), which its
  /// record names ("method_options"); empty for an external method (see `external`).
  MethodOptions method_options{};

  /// Stable key used to match records across runs: "case_id|method_id|user|noise|seed".
  std::string id() const;
  /// The case instance the job runs on, "case_id|noise|seed": the jobs that share it (every
  /// method and user) share the making of the case (run_jobs.h) and a shard (shard.h).
  std::string case_instance() const;
};

/// Job::case_instance of the job whose Job::id is `job_id` ("" where it has not five fields).
std::string case_instance_of_job_id(const std::string& job_id);

/// How a job ended. Everything but `Ok` carries a message.
enum class JobStatus {
  Ok,            ///< the method returned and every metric was computed
  Partial,       ///< the method left some holes open (it said so)
  MethodFailed,  ///< the method returned a failure status
  InvalidInput,  ///< the case could not be generated or read
  Error,         ///< an exception escaped the method or a metric
  Crash,         ///< the job's process died (a signal: segmentation fault, abort, ...)
  Timeout,       ///< the job ran past the time limit and was stopped
  /// The job ran out of memory under its limit (harness/run/memory_limit.h): an allocation
  /// failed (std::bad_alloc, an external program's MemoryError or ENOMEM), or the kernel
  /// killed its process (SIGKILL that the runner did not send).
  OutOfMemory,
};
const char* to_string(JobStatus status);

/// A record's holes are the method's own hole reports (core/method_result.h). The results
/// files keep every field but `new_vertices` and `seconds` (harness/results/record_json.h),
/// so a record read back has those two at zero.
using HoleRecord = HoleReport;

/// The names of a job's stages (JobRecord::stages, the records' `stages_s`): written by the
/// runner (job.cpp, process_pool.cpp) and read by what sums them
/// (harness/outputs/time_breakdown.h).
namespace stage_names {
/// A job forked from its group's process copying the heap pages it will write, before the job
/// starts (process_pool.h).
constexpr const char* kHeapWarmup = "heap_warmup";
constexpr const char* kCase = "case";  ///< making the case (the group's first job)
constexpr const char* kMethod = "method";
constexpr const char* kEvaluation = "evaluation";
constexpr const char* kSnapshot = "snapshot";
constexpr const char* kLayers = "layers";
}  // namespace stage_names

struct JobRecord {
  Job job;
  std::string case_family;
  std::string case_kind;
  std::string user = "no_user";
  int user_interventions = 0;
  /// The same count by kind (User::interventions_by_kind); written only where non-empty.
  std::map<std::string, int> user_interventions_by_kind;
  JobStatus status = JobStatus::Ok;
  std::string message;
  std::vector<MetricValue> metrics;
  std::vector<PhaseTiming> phases;
  std::vector<HoleRecord> holes;
  /// Wall time of the method: the median of `method_run_seconds`.
  double method_seconds = 0.0;
  /// Wall time of each run of the method (JobOptions::method_repetitions; one by default).
  std::vector<double> method_run_seconds;
  /// Wall time of the job's stages, named as in stage_names, in the order they ran.
  std::vector<PhaseTiming> stages;
  /// Wall time of the evaluation's steps (metrics/evaluation.h, evaluation_phases), and for
  /// the first job of a group evaluation_phases::kSharedCaseWork: what the case's jobs share, built
  /// in the group's process and counted in this job's "evaluation" stage. Empty where the job was
  /// not evaluated.
  std::vector<PhaseTiming> evaluation_phases;
  std::string snapshot;  ///< PNG path relative to the output folder, or empty

  /// The value of the metric `name`, or nullptr when the record does not have it.
  const double* metric(const std::string& name) const;
};

struct JobOptions {
  const generators::CaseCatalog* catalog = nullptr;  ///< nullptr: the default catalog
  EvaluationOptions evaluation;
  std::filesystem::path snapshot_dir;  ///< empty: no snapshot
  /// The output folder that gets the report's 3D viewer meshes (meshes/, written with the
  /// snapshot and timed in its stage; outputs/viewer/viewer_mesh.h); empty: none.
  std::filesystem::path viewer_mesh_dir;
  /// Where the method's steps go (`--layers`): the method is asked for its layers
  /// (MethodParameters::record_layers) and each job writes <stem>.png (layers_picture.h) and
  /// <stem>.obj (layers_obj.h) here, timed in its "layers" stage; empty: none asked.
  std::filesystem::path layers_dir;
  /// Runs of the method per job, for steadier timings: the record's method time is their
  /// median; the first run's result is the one evaluated (the methods are deterministic).
  int method_repetitions = 1;
};

/// The case of a job, made once for every job that shares it (the same case id, noise level
/// and seed: harness/run/job_groups.h), or why it could not be made.
struct PreparedCase {
  Case c;
  double seconds = 0.0;  ///< wall time of making it
  /// What the evaluations of its jobs share (metrics/case_evaluation.h), built once for a
  /// group of jobs (share_case_work); nullptr: each job's evaluation builds its own.
  std::shared_ptr<const CaseEvaluation> evaluation;
  double evaluation_seconds = 0.0;  ///< wall time of building `evaluation`
  /// What the pictures of its jobs share (harness/outputs/render/close_up.h), built once for
  /// a group of jobs that render snapshots; nullptr: each job's picture builds its own.
  std::shared_ptr<const render::CasePicture> picture;
  double picture_seconds = 0.0;  ///< wall time of building `picture`
  /// Set when the case could not be made: the status (invalid_input, out_of_memory) and
  /// message every job of it gets.
  std::optional<std::pair<JobStatus, std::string>> failure;
};

/// Makes the case of `job` (its id, noise level and seed). Never throws.
PreparedCase prepare_case(const Job& job, const JobOptions& options);

/// Builds what the evaluations and the pictures of a prepared case's jobs share
/// (PreparedCase::evaluation, PreparedCase::picture where `options` render snapshots), for a
/// group of jobs on one case. Where one cannot be built (out of memory, an exception), the
/// jobs build their own, as they would without it. The records are the same either way.
/// Never throws.
void share_case_work(PreparedCase& prepared, const JobOptions& options);

/// Runs the method of `job` on a prepared case, evaluates, renders. The first job of a
/// group (`first_of_group`) carries the making of the case in its "case" stage and the
/// building of the shared evaluation in its "evaluation" stage, the others 0 for them, so
/// that the stages of a run add up to its work (and the building of the shared picture in
/// its "snapshot" stage). Never throws: every failure becomes the
/// record's status and message.
JobRecord run_job_on_case(const Job& job, const PreparedCase& prepared, bool first_of_group,
                          const JobOptions& options);

/// Generates the case, runs the method with no user, evaluates, renders. Never throws:
/// every failure becomes the record's status and message.
JobRecord run_job(const Job& job, const JobOptions& options);

}  // namespace holebench::harness
