// Where a sharded run stands: for each shard of DIR/shards.json, whether its folder holds all
// of its jobs' records (complete), some (incomplete: still running, or its task failed or ran
// out of time) or none (missing: queued, or failed before its first job). Read from the
// files alone (records.jsonl, results.json, the Slurm log), so it works without Slurm's
// accounting and after the jobs have left the queue.
#pragma once

#include "harness/cluster/shard_manifest.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace holebench::harness {

enum class ShardState {
  Complete,    ///< every job recorded and results.json written
  Incomplete,  ///< some records, or all of them but no results.json
  Missing,     ///< no record at all
};
const char* to_string(ShardState state);

struct ShardStatus {
  std::size_t index = 0;
  std::string name;  ///< "shard-I"
  std::filesystem::path folder;
  ShardState state = ShardState::Missing;
  std::size_t planned_jobs = 0;
  std::size_t recorded_jobs = 0;  ///< records of the shard's planned jobs in records.jsonl
  bool results_written = false;   ///< results.json exists
  /// Recorded jobs that crashed or timed out: recorded, so a resubmission keeps them; rerun
  /// them with a fresh folder or a longer --timeout if the cause was the machine.
  std::size_t crashed_or_timed_out = 0;
  std::filesystem::path log;  ///< the shard's Slurm output
  std::string log_tail;       ///< its last non-empty line, if any (errors, "CANCELLED ...")
};

struct ShardStatusReport {
  std::filesystem::path dir;
  ShardManifest manifest;
  std::vector<ShardStatus> shards;  ///< by index

  bool all_complete() const;
  /// The indices of the shards that are not complete, to resubmit.
  std::vector<std::size_t> unfinished() const;
};

/// The status of every shard of the sharded run in `dir`. Throws InvalidInputError if `dir`
/// has no shards.json.
ShardStatusReport shard_status(const std::filesystem::path& dir);

/// One line per shard ("shard-2  incomplete  17/40 jobs ...") and a closing line saying what
/// to do: resubmit the unfinished shards by name, or merge.
std::string format_shard_status(const ShardStatusReport& report);

}  // namespace holebench::harness
