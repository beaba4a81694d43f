// What produced a results file: its context block (code version, build, host, time, suite,
// shard, library versions), written before the records.
#pragma once

#include <string>
#include <utility>
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
  std::string shard;  ///< "I/N" for one shard of a sharded run (harness/run/shard.h), else empty
  std::vector<std::pair<std::string, std::string>> libraries;  ///< name, version
};

/// The context of this process: code version, build type, library versions, host, time.
RunContext current_context(const std::string& suite);

}  // namespace holebench::harness
