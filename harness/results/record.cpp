// The functions of the record's plain data (record.h): a job's id, a record's metric lookup,
// the names of the statuses.
#include "harness/results/record.h"

#include "core/split_text.h"

#include <fmt/format.h>

namespace holebench::harness {

std::string Job::id() const {
  return fmt::format("{}|{}|{}|{}|{}", case_id, method_id, user, noise_percent, seed);
}

std::string Job::case_instance() const {
  return fmt::format("{}|{}|{}", case_id, noise_percent, seed);
}

std::string case_instance_of_job_id(const std::string& job_id) {
  const std::vector<std::string> fields = split_text(job_id, '|');
  if (fields.size() != 5)
    return "";
  return fields[0] + "|" + fields[3] + "|" + fields[4];
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
