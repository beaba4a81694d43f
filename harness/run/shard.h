// Shards: a deterministic 1/N slice of a run's jobs, so that N machines (or the N tasks of a
// Slurm job array) together run a suite, each job exactly once.
//
// The plan's jobs (plan_jobs order, which depends only on the suite and the catalog, not on
// the number of workers) are dealt to the shards by case instance (Job::case_instance: case
// id, noise level and seed), so that a shard makes each of its cases once: the g-th case
// instance to appear in the plan, with all its jobs, belongs to shard g mod N. Shards are
// numbered 0 to N-1, like the tasks of `sbatch --array=0-(N-1)`; shard I of N is written "I/N".
#pragma once

#include "harness/results/record.h"

#include <cstddef>
#include <string>
#include <vector>

namespace holebench::harness {

struct ShardSpec {
  std::size_t index = 0;  ///< 0 .. count-1
  std::size_t count = 1;  ///< 1: the whole run
};

/// Reads "I/N" (0 <= I < N, N >= 1). Throws std::invalid_argument saying what is wrong.
ShardSpec parse_shard(const std::string& text);

/// "I/N".
std::string to_string(const ShardSpec& shard);

/// The shard of each job of a plan, among `shard_count`, from the jobs' case instances in plan
/// order (Job::case_instance): the g-th distinct instance goes to shard g mod shard_count.
std::vector<std::size_t> shard_of_each(const std::vector<std::string>& case_instances,
                                       std::size_t shard_count);

/// The jobs of `shard`, in plan order.
std::vector<Job> jobs_of_shard(const std::vector<Job>& plan, const ShardSpec& shard);

/// The output folder name of shard `index` inside a sharded run's folder: "shard-<index>".
std::string shard_folder_name(std::size_t index);

/// Reads a list of shard indices "1,3,5" or ranges "0-2,7" (each < shard_count), sorted and
/// without repeats. Throws std::invalid_argument naming the bad item.
std::vector<std::size_t> parse_shard_list(const std::string& text, std::size_t shard_count);

/// The list in Slurm's --array form: "0-3", "1,3", "0-2,7".
std::string shard_list_to_array_spec(const std::vector<std::size_t>& indices);

}  // namespace holebench::harness
