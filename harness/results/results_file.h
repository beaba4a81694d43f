// The results of a run: a context block (what produced them) plus one record per job,
// written as JSON (numbers as numbers) and as long-format CSV (one row per metric).
#pragma once

#include "harness/run/job.h"

#include <filesystem>
#include <string>
#include <vector>

namespace holebench::harness {

/// Version of the results file layout; readers ignore fields they do not know.
inline constexpr int kResultsSchemaVersion = 1;

struct RunContext {
  int schema_version = kResultsSchemaVersion;
  std::string code_version;  ///< git describe of the source tree
  std::string build_type;
  std::string host;
  std::string created_utc;  ///< ISO 8601
  std::string suite;
  std::string
      shard;  ///< "I/N" for one shard of a sharded run (harness/cluster/shard.h), else empty
  std::vector<std::pair<std::string, std::string>> libraries;  ///< name, version
};

/// The context of this process: code version, build type, library versions, host, time.
RunContext current_context(const std::string& suite);

/// Writes `dir/results.json`.
void write_results_json(const std::filesystem::path& path, const RunContext& context,
                        const std::vector<JobRecord>& records);

/// Writes the long-format CSV: job_id, case_id, method, seed, case_family, case_kind,
/// noise_percent, status, metric, value; a job without metrics has one row with an empty
/// metric.
void write_results_csv(const std::filesystem::path& path, const std::vector<JobRecord>& records);

}  // namespace holebench::harness
