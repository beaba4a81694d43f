// The memory limit of a job (harness/run/memory_limit.h): sizes as people write them, a job
// that allocates without bound stopped by the limit with the status out_of_memory while the
// run goes on, and an external program that does the same, end to end.
#include "harness/run/memory_limit.h"

#include "harness/results/results_reader.h"
#include "harness/results/validate_results.h"
#include "harness/run/process_pool.h"
#include "harness/run/run_jobs.h"

#include <gtest/gtest.h>

#include <csignal>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <vector>

namespace holebench::harness {
namespace {

TEST(MemoryLimit, SizesReadWithBinaryUnits) {
  EXPECT_EQ(parse_memory_size("4G"), 4 * kGibibyte);
  EXPECT_EQ(parse_memory_size("4GiB"), 4 * kGibibyte);
  EXPECT_EQ(parse_memory_size("512M"), 512ull << 20);
  EXPECT_EQ(parse_memory_size("512 MiB"), 512ull << 20);
  EXPECT_EQ(parse_memory_size("1.5g"), 3 * kGibibyte / 2);
  EXPECT_EQ(parse_memory_size("65536K"), 64ull << 20);
  EXPECT_EQ(parse_memory_size("1000"), 1000u);
  EXPECT_EQ(parse_memory_size("0"), 0u);
  EXPECT_EQ(parse_memory_size("none"), 0u);
  for (const char* bad : {"", "G", "-1G", "4X", "4GG", "1e999", "lots", "4G5"})
    EXPECT_THROW(parse_memory_size(bad), std::invalid_argument) << bad;
  EXPECT_EQ(format_memory_size(4 * kGibibyte), "4 GiB");
  EXPECT_EQ(format_memory_size(512ull << 20), "512 MiB");
  EXPECT_EQ(format_memory_size(0), "none");
}

TEST(MemoryLimit, MessagesThatReportRunningOutOfMemory) {
  EXPECT_TRUE(
      message_reports_out_of_memory("the program failed: exit code 1; its stderr "
                                    "ends:\nMemoryError"));
  EXPECT_TRUE(message_reports_out_of_memory("std::bad_alloc"));
  EXPECT_TRUE(message_reports_out_of_memory("mmap: Cannot allocate memory"));
  EXPECT_FALSE(message_reports_out_of_memory("the program failed: exit code 1"));
}

// Allocates 64 MiB blocks, touching one byte of each (the limit is on address space, so
// the machine's memory is hardly used), until an allocation fails.
JobRecord allocate_without_bound(const Job& job) {
  if (job.case_id == "greedy") {
    std::vector<std::unique_ptr<char[]>> blocks;
    for (;;) {
      blocks.emplace_back(new char[64u << 20]);
      blocks.back()[0] = 1;
      if (blocks.size() > 100000)  // 6 TiB: no limit was applied
        throw std::runtime_error("no limit");
    }
  }
  if (job.case_id == "killed")
    std::raise(SIGKILL);  // as the kernel's out-of-memory killer does
  JobRecord record;
  record.job = job;
  record.metrics = {{"length_count", 1.0}};
  return record;
}

std::vector<Job> jobs(const std::vector<std::string>& cases) {
  std::vector<Job> list;
  for (const auto& c : cases)
    list.push_back({c, "fake", 0.0, 0, "no_user"});
  return list;
}

std::filesystem::path fresh_file(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "holebench_memory_limit_test";
  std::filesystem::create_directories(dir);
  std::filesystem::remove(dir / name);
  return dir / name;
}

TEST(MemoryLimit, AJobPastTheLimitIsOutOfMemoryAndTheRunGoesOn) {
  ProcessPoolOptions options;
  options.workers = 2;
  options.progress = false;
  options.memory_limit_bytes = 2 * kGibibyte;
  const auto path = fresh_file("greedy.jsonl");
  const auto result =
      run_isolated(jobs({"a", "greedy", "killed", "b"}), allocate_without_bound, path, options);
  ASSERT_EQ(result.records.size(), 4u);
  EXPECT_EQ(result.records[0].status, JobStatus::Ok);
  EXPECT_EQ(result.records[1].status, JobStatus::OutOfMemory) << result.records[1].message;
  EXPECT_NE(result.records[1].message.find("allocation failed"), std::string::npos);
  EXPECT_EQ(result.records[2].status, JobStatus::OutOfMemory) << result.records[2].message;
  EXPECT_EQ(result.records[3].status, JobStatus::Ok);
  // The status reads back and passes validation (a job without metrics that did not finish).
  const auto read = read_records_jsonl(path);
  ASSERT_EQ(read.size(), 4u);
  for (const auto& record : read) {
    if (record.job.case_id == "greedy") {
      EXPECT_EQ(record.status, JobStatus::OutOfMemory);
      EXPECT_TRUE(validate_record(record).empty());
    }
  }
}

// An external method that allocates without bound (a Python program): the limit reaches the
// program the job starts, its MemoryError makes the job out_of_memory, the other job is ok.
TEST(MemoryLimit, AnExternalProgramPastTheLimitIsOutOfMemory) {
  RunOptions options;
  options.out_dir = std::filesystem::temp_directory_path() / "holebench_test_memory_limit_run";
  std::filesystem::remove_all(options.out_dir);
  options.suite.case_patterns = {"box/corner"};
  options.suite.methods = {"greedy", "fan_fill"};
  options.suite.external_methods = {
      {"greedy",
       "python3 -c 'blocks = [bytearray(1 << 24) for _ in iter(int, 1)]' {input} {output}",
       0.0,
       {}},
      {"fan_fill",
       "python3 '" + std::string(HOLEBENCH_SOURCE_DIR) + "/examples/fan_fill.py' {input} {output}",
       0.0,
       {}}};
  options.suite.include_cad = false;
  options.snapshots = false;
  options.progress = false;
  options.workers = 2;
  options.suite.memory_limit_bytes = 2 * kGibibyte;
  const RunSummary summary = run_jobs(options);
  ASSERT_EQ(summary.records.size(), 2u);
  EXPECT_EQ(summary.records[0].job.method_id, "greedy");
  EXPECT_EQ(summary.records[0].status, JobStatus::OutOfMemory) << summary.records[0].message;
  EXPECT_NE(summary.records[0].message.find("MemoryError"), std::string::npos);
  EXPECT_EQ(summary.records[1].status, JobStatus::Ok) << summary.records[1].message;
  // results.json reads back with the new status, and validates.
  const ResultsData data = read_results_json(summary.results_json);
  ASSERT_EQ(data.records.size(), 2u);
  EXPECT_EQ(data.records[0].status, JobStatus::OutOfMemory);
  const auto report = validate_results_files({summary.results_json});
  EXPECT_TRUE(report.ok()) << (report.ok() ? "" : format_violation(report.violations[0]));
}

}  // namespace
}  // namespace holebench::harness
