// The plain data of harness/run/job.h (a job's id, a record's metric lookup, the names of the
// statuses), apart from run_job, so that the results readers need nothing but this.
#include "harness/run/job.h"

#include <fmt/format.h>

namespace holebench::harness {

std::string Job::id() const {
  return fmt::format("{}|{}|{}|{}|{}", case_id, method_id, user, noise_percent, seed);
}

const double* JobRecord::metric(const std::string& name) const {
  for (const auto& m : metrics) {
    if (m.name == name)
      return &m.value;
  }
  return nullptr;
}

const char* to_string(JobStatus status) {
  switch (status) {
    case JobStatus::Ok:
      return "ok";
    case JobStatus::Partial:
      return "partial";
    case JobStatus::MethodFailed:
      return "method_failed";
    case JobStatus::InvalidInput:
      return "invalid_input";
    case JobStatus::Error:
      return "error";
    case JobStatus::Crash:
      return "crash";
    case JobStatus::Timeout:
      return "timeout";
    case JobStatus::OutOfMemory:
      return "out_of_memory";
  }
  return "unknown";
}

}  // namespace holebench::harness
