#include "harness/cluster/shard_merge.h"

#include "harness/results/merge_results.h"
#include "harness/results/output_folder_lock.h"
#include "harness/results/results_file.h"
#include "harness/run/process_pool.h"

#include <map>
#include <set>

namespace holebench::harness {
namespace {

// A shard's records: results.json when the shard finished writing it, else what the runner
// appended to records.jsonl so far.
std::vector<JobRecord> shard_records(const ShardStatus& shard, RunContext* context) {
  if (shard.results_written) {
    auto data = read_results_json(shard.folder / "results.json");
    if (context)
      *context = data.context;
    return std::move(data.records);
  }
  return read_records_jsonl(shard.folder / "records.jsonl");
}

}  // namespace

ShardMergeResult merge_shards(const ShardMergeOptions& options) {
  ShardMergeResult result;
  result.status = shard_status(options.dir);
  if (!result.status.all_complete() && !options.allow_incomplete)
    return result;
  const auto out_dir = options.out_dir.empty() ? options.dir : options.out_dir;
  const OutputFolderLock lock(out_dir);  // one writer per folder

  std::map<std::string, JobRecord> by_id;
  std::vector<RunContext> contexts;
  for (const auto& shard : result.status.shards) {
    RunContext context;
    const bool has_context = shard.results_written;
    for (auto& record : shard_records(shard, &context)) {
      record.snapshot = snapshot_relative_to(record.snapshot, shard.folder, out_dir);
      by_id[record.job.id()] = std::move(record);
    }
    if (has_context)
      contexts.push_back(context);
  }

  // The records in plan order: the order of a single-machine run.
  for (const auto& id : result.status.manifest.job_ids) {
    const auto it = by_id.find(id);
    if (it == by_id.end()) {
      result.missing_jobs.push_back(id);
    } else {
      result.merged.records.push_back(std::move(it->second));
    }
  }

  RunContext& context = result.merged.context;
  context = contexts.empty() ? current_context(result.status.manifest.suite) : contexts.front();
  context.shard.clear();
  std::set<std::string> seen_hosts{context.host};
  for (const auto& other : contexts) {
    if (seen_hosts.insert(other.host).second)
      context.host += "," + other.host;
  }

  std::filesystem::create_directories(out_dir);
  result.results_json = out_dir / "results.json";
  result.results_csv = out_dir / "results.csv";
  write_results_json(result.results_json, context, result.merged.records);
  write_results_csv(result.results_csv, result.merged.records);
  result.written = true;
  return result;
}

}  // namespace holebench::harness
