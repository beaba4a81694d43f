// The record of a job: what ran (a case x a method x a user x a noise level x a seed) and what
// came of it (status, metrics, holes, timings). The plain data every room of harness/ reads and
// writes: the runner fills it (run/), the results files keep it (results/), the pages and
// tables read it (outputs/). Its functions are in record.cpp.
#pragma once

#include "core/method_result.h"
#include "methods/external/external_method_spec.h"
#include "methods/method.h"
#include "metrics/evaluation.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

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
/// files keep every field but `new_vertices` and `seconds` (record_json.h),
/// so a record read back has those two at zero.
using HoleRecord = HoleReport;

/// The names of a job's stages (JobRecord::stages, the records' `stages_s`): written by the
/// runner (run/job.cpp, run/process_pool.cpp) and read by what sums them
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

}  // namespace holebench::harness
