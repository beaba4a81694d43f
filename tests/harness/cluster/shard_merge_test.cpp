// A sharded run's status and merge on hand-made shard folders (no Slurm, no real jobs): the
// status names missing and incomplete shards, the merge refuses them unless told, and the
// merged records come in plan order under an unsharded context.
#include "harness/cluster/shard_merge.h"

#include "harness/cluster/shard_manifest.h"
#include "harness/cluster/shard_status.h"
#include "harness/results/output_folder_lock.h"
#include "harness/results/record_json.h"
#include "harness/results/results_file.h"
#include "harness/run/shard.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace holebench::harness {
namespace {

constexpr std::size_t kShards = 3;

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("holebench_shard_merge_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Ten jobs, planned in an order that is not the order of their ids.
std::vector<Job> plan() {
  std::vector<Job> jobs;
  for (int i = 9; i >= 0; --i)
    jobs.push_back({"case/" + std::to_string(i), "fake", 0.0, 0, "no_user"});
  return jobs;
}

JobRecord record_of(const Job& job) {
  JobRecord record;
  record.job = job;
  record.metrics = {{"case_number", static_cast<double>(job.case_id.back() - '0')}};
  record.method_seconds = 0.5;
  record.snapshot = "snapshots/" + job.case_id.substr(5) + ".png";
  return record;
}

ShardManifest manifest_of(const std::vector<Job>& jobs) {
  ShardManifest manifest;
  manifest.suite = "fake";
  manifest.shard_count = kShards;
  for (const auto& job : jobs)
    manifest.job_ids.push_back(job.id());
  return manifest;
}

// Writes shard `index` as `holebench run --shard` would: `recorded` of its jobs in
// records.jsonl, and results.json when all are there.
void write_shard(const std::filesystem::path& dir, std::size_t index, std::size_t recorded) {
  const auto jobs = jobs_of_shard(plan(), {index, kShards});
  const auto folder = shard_dir(dir, index);
  std::filesystem::create_directories(folder);
  std::vector<JobRecord> records;
  std::ofstream jsonl(folder / "records.jsonl");
  for (std::size_t i = 0; i < recorded && i < jobs.size(); ++i) {
    records.push_back(record_of(jobs[i]));
    jsonl << record_to_json_line(records.back()) << '\n';
  }
  if (recorded >= jobs.size()) {
    RunContext context = current_context("fake");
    context.host = "node-" + std::to_string(index);
    context.shard = to_string(ShardSpec{index, kShards});
    write_results_json(folder / "results.json", context, records);
  }
}

TEST(ShardStatus, NamesMissingAndIncompleteShards) {
  const auto dir = fresh_dir("status");
  write_shard_manifest(dir, manifest_of(plan()));
  write_shard(dir, 0, 100);
  write_shard(dir, 1, 1);  // shard 2: never ran
  const auto report = shard_status(dir);
  ASSERT_EQ(report.shards.size(), kShards);
  EXPECT_EQ(report.shards[0].state, ShardState::Complete);
  EXPECT_EQ(report.shards[0].planned_jobs, 4u);  // jobs 0, 3, 6, 9 of the plan
  EXPECT_EQ(report.shards[1].state, ShardState::Incomplete);
  EXPECT_EQ(report.shards[1].recorded_jobs, 1u);
  EXPECT_EQ(report.shards[2].state, ShardState::Missing);
  EXPECT_EQ(report.unfinished(), (std::vector<std::size_t>{1, 2}));
  const auto text = format_shard_status(report);
  EXPECT_NE(text.find("not complete: shard-1, shard-2."), std::string::npos) << text;
  EXPECT_NE(text.find("holebench slurm resubmit --out"), std::string::npos) << text;
  EXPECT_NE(text.find("array indices 1-2"), std::string::npos) << text;
}

TEST(ShardStatus, AFolderWithoutManifestIsNotASharedRun) {
  EXPECT_THROW(shard_status(fresh_dir("no_manifest")), std::invalid_argument);
}

TEST(ShardMerge, RefusesIncompleteShardsUnlessAllowed) {
  const auto dir = fresh_dir("incomplete");
  write_shard_manifest(dir, manifest_of(plan()));
  write_shard(dir, 0, 100);
  write_shard(dir, 1, 2);
  ShardMergeOptions options;
  options.dir = dir;
  const auto refused = merge_shards(options);
  EXPECT_FALSE(refused.written);
  EXPECT_FALSE(std::filesystem::exists(dir / "results.json"));

  options.allow_incomplete = true;
  const auto partial = merge_shards(options);
  ASSERT_TRUE(partial.written);
  EXPECT_EQ(partial.merged.records.size(), 6u);  // 4 + 2 of shard 1 (from records.jsonl)
  EXPECT_EQ(partial.missing_jobs.size(), 4u);
}

TEST(ShardMerge, RecordsInPlanOrderUnderAnUnshardedContext) {
  const auto dir = fresh_dir("complete");
  write_shard_manifest(dir, manifest_of(plan()));
  for (std::size_t i = 0; i < kShards; ++i)
    write_shard(dir, i, 100);
  ShardMergeOptions options;
  options.dir = dir;
  options.out_dir = dir / "merged";
  const auto result = merge_shards(options);
  ASSERT_TRUE(result.written);
  EXPECT_TRUE(result.missing_jobs.empty());
  const auto jobs = plan();
  const auto merged = read_results_json(result.results_json);
  ASSERT_EQ(merged.records.size(), jobs.size());
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    SCOPED_TRACE(jobs[i].id());
    const auto expected = record_of(jobs[i]);
    EXPECT_EQ(merged.records[i].job.id(), expected.job.id());
    ASSERT_EQ(merged.records[i].metrics.size(), 1u);
    EXPECT_EQ(merged.records[i].metrics[0].value, expected.metrics[0].value);
    // Shard I's snapshots/x.png, seen from the output folder.
    EXPECT_EQ(merged.records[i].snapshot,
              "../" + shard_folder_name(i % kShards) + "/" + expected.snapshot);
  }
  EXPECT_EQ(merged.context.shard, "");
  EXPECT_EQ(merged.context.suite, "fake");
  EXPECT_EQ(merged.context.host, "node-0,node-1,node-2");
  EXPECT_TRUE(std::filesystem::exists(dir / "merged" / "results.csv"));
}

// The merge writes its output folder alone: while another holds the folder's lock, it
// refuses, naming the holder, and writes nothing.
TEST(ShardMerge, RefusesAnOutputFolderInUse) {
  const auto dir = fresh_dir("in_use");
  write_shard_manifest(dir, manifest_of(plan()));
  for (std::size_t i = 0; i < kShards; ++i)
    write_shard(dir, i, 100);
  ShardMergeOptions options;
  options.dir = dir;
  {
    const OutputFolderLock holder(dir);
    try {
      merge_shards(options);
      ADD_FAILURE() << "merged into a folder in use";
    } catch (const OutputFolderInUse& e) {
      EXPECT_EQ(e.holder_pid(), ::getpid());
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "results.json"));
  }
  EXPECT_TRUE(merge_shards(options).written);  // released with its holder
}

}  // namespace
}  // namespace holebench::harness
