// The folder of a sharded run and its manifest, shards.json: which suite, in how many shards,
// which jobs (in plan order), how each shard runs, and the Slurm submissions so far. Written
// by `holebench slurm submit`, read by `slurm status`, `slurm resubmit` and `merge --shards`,
// so that these know the run's jobs without building the case catalog again.
//
//   DIR/shards.json          the manifest
//   DIR/shard-I/             shard I's output folder (`holebench run --shard I/N --out ...`)
//   DIR/slurm/shards.sbatch  the job array script, one task per shard
//   DIR/slurm/shard-I.log    shard I's Slurm output (appended to on resubmission)
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace holebench::harness {

struct SlurmSubmission {
  std::string slurm_job_id;  ///< empty for a dry run
  std::string array;         ///< the --array value: "0-3", "1,3"
  std::string submitted_utc;
};

struct ShardManifest {
  std::string suite;                 ///< the suite's name
  std::filesystem::path suite_file;  ///< absolute; what each shard passes to `run --suite`
  std::size_t shard_count = 1;
  std::vector<std::string> job_ids;         ///< every job of the suite, in plan order
  std::filesystem::path holebench;          ///< the binary the shards run
  std::vector<std::string> run_arguments;   ///< added to each shard's `holebench run`
  std::vector<std::string> sbatch_options;  ///< passed to sbatch on submission
  std::vector<SlurmSubmission> submissions;
};

std::filesystem::path shard_manifest_path(const std::filesystem::path& dir);
std::filesystem::path shard_dir(const std::filesystem::path& dir, std::size_t index);
std::filesystem::path slurm_script_path(const std::filesystem::path& dir);
std::filesystem::path slurm_log_path(const std::filesystem::path& dir, std::size_t index);
/// The --output pattern of the job array (%a: the array index).
std::filesystem::path slurm_log_pattern(const std::filesystem::path& dir);

/// The ids of shard `index`'s jobs, in plan order.
std::vector<std::string> shard_job_ids(const ShardManifest& manifest, std::size_t index);

/// Writes DIR/shards.json (creating DIR). Throws std::runtime_error if it cannot.
void write_shard_manifest(const std::filesystem::path& dir, const ShardManifest& manifest);

/// Reads DIR/shards.json. Throws InvalidInputError when there is none (DIR is not a sharded
/// run's folder) or it is malformed.
ShardManifest read_shard_manifest(const std::filesystem::path& dir);

}  // namespace holebench::harness
