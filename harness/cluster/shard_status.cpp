#include "harness/cluster/shard_status.h"

#include "harness/run/process_pool.h"
#include "harness/run/shard.h"

#include <fmt/format.h>

#include <fstream>
#include <set>

namespace holebench::harness {

const char* to_string(ShardState state) {
  switch (state) {
    case ShardState::Complete:
      return "complete";
    case ShardState::Incomplete:
      return "incomplete";
    case ShardState::Missing:
      return "missing";
  }
  return "?";
}

bool ShardStatusReport::all_complete() const {
  return unfinished().empty();
}

std::vector<std::size_t> ShardStatusReport::unfinished() const {
  std::vector<std::size_t> indices;
  for (const auto& shard : shards) {
    if (shard.state != ShardState::Complete)
      indices.push_back(shard.index);
  }
  return indices;
}

namespace {

std::string last_non_empty_line(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string last;
  for (std::string line; std::getline(in, line);) {
    if (line.find_first_not_of(" \t\r") != std::string::npos)
      last = line;
  }
  return last;
}

ShardStatus status_of_shard(const std::filesystem::path& dir, const ShardManifest& manifest,
                            std::size_t index) {
  ShardStatus status;
  status.index = index;
  status.name = shard_folder_name(index);
  status.folder = shard_dir(dir, index);
  status.log = slurm_log_path(dir, index);
  const auto planned = shard_job_ids(manifest, index);
  status.planned_jobs = planned.size();
  const std::set<std::string> wanted(planned.begin(), planned.end());
  std::set<std::string> recorded;
  for (const auto& record : read_records_jsonl(status.folder / "records.jsonl")) {
    const auto id = record.job.id();
    if (!wanted.count(id) || !recorded.insert(id).second)
      continue;
    if (record.status == JobStatus::Crash || record.status == JobStatus::Timeout)
      ++status.crashed_or_timed_out;
  }
  status.recorded_jobs = recorded.size();
  status.results_written = std::filesystem::exists(status.folder / "results.json");
  if (status.recorded_jobs == status.planned_jobs && status.results_written) {
    status.state = ShardState::Complete;
  } else if (status.recorded_jobs > 0 || status.results_written) {
    status.state = ShardState::Incomplete;
  } else {
    status.state = ShardState::Missing;
  }
  if (std::filesystem::exists(status.log))
    status.log_tail = last_non_empty_line(status.log);
  return status;
}

}  // namespace

ShardStatusReport shard_status(const std::filesystem::path& dir) {
  ShardStatusReport report;
  report.dir = dir;
  report.manifest = read_shard_manifest(dir);
  for (std::size_t i = 0; i < report.manifest.shard_count; ++i)
    report.shards.push_back(status_of_shard(dir, report.manifest, i));
  return report;
}

std::string format_shard_status(const ShardStatusReport& report) {
  std::string text = fmt::format("{}: suite {}, {} jobs in {} shards\n", report.dir.string(),
                                 report.manifest.suite, report.manifest.job_ids.size(),
                                 report.manifest.shard_count);
  std::size_t complete = 0;
  for (const auto& shard : report.shards) {
    std::string notes;
    if (shard.state == ShardState::Complete)
      ++complete;
    if (shard.state == ShardState::Incomplete && shard.recorded_jobs == shard.planned_jobs)
      notes += "  (every job recorded, no results.json: the task ended before writing it)";
    if (shard.crashed_or_timed_out > 0)
      notes += fmt::format("  ({} crashed or timed out)", shard.crashed_or_timed_out);
    text += fmt::format("  {:<10} {:<10} {:>5}/{} jobs{}\n", shard.name, to_string(shard.state),
                        shard.recorded_jobs, shard.planned_jobs, notes);
    if (shard.state != ShardState::Complete && !shard.log_tail.empty())
      text += fmt::format("             last line of {}: {}\n", shard.log.string(), shard.log_tail);
  }
  const auto unfinished = report.unfinished();
  if (unfinished.empty()) {
    text += fmt::format("all {} shards complete: holebench merge --shards {}\n", complete,
                        report.dir.string());
  } else {
    std::string names;
    for (auto index : unfinished)
      names += (names.empty() ? "" : ", ") + shard_folder_name(index);
    text += fmt::format(
        "{} of {} shards complete; not complete: {}.\n"
        "Once their Slurm tasks have ended, resubmit just these (array indices {}): holebench "
        "slurm resubmit --out {}\n",
        complete, report.shards.size(), names, shard_list_to_array_spec(unfinished),
        report.dir.string());
  }
  return text;
}

}  // namespace holebench::harness
