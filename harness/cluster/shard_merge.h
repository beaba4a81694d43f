// `holebench merge --shards DIR`: the shards of a sharded run joined into one results file,
// equal to a single-machine run of the suite up to timings: the same records, in the
// suite's plan order, under the first shard's context without the shard (hosts listed).
// Snapshot paths are rewritten to stay valid relative to the output folder.
#pragma once

#include "harness/cluster/shard_status.h"
#include "harness/results/results_reader.h"

#include <filesystem>
#include <string>
#include <vector>

namespace holebench::harness {

struct ShardMergeOptions {
  std::filesystem::path dir;      ///< the sharded run's folder (with shards.json)
  std::filesystem::path out_dir;  ///< empty: `dir`
  /// Merge what there is when some shards are not complete (their records.jsonl), instead of
  /// writing nothing.
  bool allow_incomplete = false;
};

struct ShardMergeResult {
  ShardStatusReport status;
  ResultsData merged;                     ///< empty unless written
  std::vector<std::string> missing_jobs;  ///< planned jobs without a record, in plan order
  bool written = false;                   ///< false: shards not complete, nothing written
  std::filesystem::path results_json;
  std::filesystem::path results_csv;
};

/// Merges the shards of `options.dir` into `out_dir`/results.json and results.csv. Writes
/// nothing (written = false) when a shard is not complete, unless `allow_incomplete`. Holds
/// `out_dir`'s lock while it writes (harness/results/output_folder_lock.h): throws
/// OutputFolderInUse when another process holds it. Throws InvalidInputError if `dir` is not a
/// sharded run's folder.
ShardMergeResult merge_shards(const ShardMergeOptions& options);

}  // namespace holebench::harness
