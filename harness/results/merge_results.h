// Joining results files: records matched by job id, snapshot paths following the merged
// file (`holebench merge FILES --out DIR`; the shards of a sharded run are joined by
// harness/cluster/shard_merge.h, in plan order).
#pragma once

#include "harness/results/results_reader.h"

#include <filesystem>
#include <string>
#include <vector>

namespace holebench::harness {

/// A record's snapshot path (relative to the folder `from_dir` of its results file) made
/// relative to `to_dir`, where a merged results file goes; empty stays empty.
std::string snapshot_relative_to(const std::string& snapshot, const std::filesystem::path& from_dir,
                                 const std::filesystem::path& to_dir);

/// Merges result sets: records matched by job id; a later set's record replaces an earlier
/// one with the same id. The context is the first set's. Records are ordered by job id.
ResultsData merge_results(const std::vector<ResultsData>& sets);

struct MergedFiles {
  ResultsData merged;
  std::filesystem::path results_json;  ///< out_dir/results.json (results.csv beside it)
};

/// Reads the results.json `files`, makes each record's snapshot path relative to `out_dir`
/// (the report finds the pictures), merges them (merge_results) and writes
/// out_dir/results.json and out_dir/results.csv. Holds the folder's lock meanwhile
/// (harness/results/output_folder_lock.h): throws OutputFolderInUse, before reading anything, when
/// another process holds it; throws InvalidInputError naming a file that cannot be read.
MergedFiles merge_results_files(const std::vector<std::filesystem::path>& files,
                                const std::filesystem::path& out_dir);

}  // namespace holebench::harness
