#include "harness/run/process_pool.h"

#include "tests/harness/record_lookup.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <thread>

namespace holebench::harness {
namespace {

std::filesystem::path fresh_file(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "holebench_runner_test";
  std::filesystem::create_directories(dir);
  std::filesystem::remove(dir / name);
  return dir / name;
}

std::vector<Job> jobs_named(const std::vector<std::string>& cases) {
  std::vector<Job> jobs;
  for (const auto& c : cases)
    jobs.push_back({c, "fake", 0.0, 0, "no_user"});
  return jobs;
}

// A stand-in job: its behaviour is chosen by the case id, its record depends on the id only.
JobRecord fake_job(const Job& job) {
  if (job.case_id == "crash")
    std::raise(SIGSEGV);
  if (job.case_id == "hang")
    std::this_thread::sleep_for(std::chrono::hours(1));
  if (job.case_id == "throw")
    throw std::runtime_error("escaped");
  JobRecord record;
  record.job = job;
  record.metrics = {{"length_count", static_cast<double>(job.case_id.size())}};
  return record;
}

TEST(ProcessPool, CrashesHangsAndEscapesBecomeStatusesAndTheRunGoesOn) {
  ProcessPoolOptions options;
  options.workers = 2;
  options.timeout_seconds = 1.0;
  options.progress = false;
  const auto path = fresh_file("statuses.jsonl");
  const auto result =
      run_isolated(jobs_named({"a", "crash", "hang", "throw", "bb"}), fake_job, path, options);
  ASSERT_EQ(result.records.size(), 5u);
  EXPECT_EQ(result.records[0].status, JobStatus::Ok);
  EXPECT_EQ(result.records[1].status, JobStatus::Crash);
  EXPECT_NE(result.records[1].message.find("Segmentation"), std::string::npos)
      << result.records[1].message;
  EXPECT_EQ(result.records[2].status, JobStatus::Timeout);
  EXPECT_EQ(result.records[3].status, JobStatus::Error);  // the child catches what escapes the job
  EXPECT_NE(result.records[3].message.find("escaped"), std::string::npos);
  EXPECT_EQ(result.records[4].status, JobStatus::Ok);
  EXPECT_EQ(result.records[4].metrics[0].value, 2.0);
  EXPECT_EQ(result.failures, 3u);
  EXPECT_EQ(read_records_jsonl(path).size(), 5u);  // every record was appended as it finished
}

// A job that sends no record (a crash, a timeout) still names its case's family and kind, so
// that reports count it with its case and not in a group without a name.
TEST(ProcessPool, RecordsOfCrashesAndTimeoutsNameTheCaseFamily) {
  ProcessPoolOptions options;
  options.workers = 2;
  options.timeout_seconds = 1.0;
  options.progress = false;
  options.case_family_kind = [](const std::string& id) {
    return std::pair<std::string, std::string>("family of " + id, "kind of " + id);
  };
  const auto result =
      run_isolated(jobs_named({"crash", "hang"}), fake_job, fresh_file("families.jsonl"), options);
  ASSERT_EQ(result.records.size(), 2u);
  EXPECT_EQ(result.records[0].status, JobStatus::Crash);
  EXPECT_EQ(result.records[0].case_family, "family of crash");
  EXPECT_EQ(result.records[1].status, JobStatus::Timeout);
  EXPECT_EQ(result.records[1].case_kind, "kind of hang");
}

TEST(ProcessPool, SameRecordsWhateverTheNumberOfWorkers) {
  const auto jobs = jobs_named({"a", "bb", "ccc", "dddd", "eeeee", "ffffff"});
  ProcessPoolOptions options;
  options.progress = false;
  options.workers = 1;
  const auto one = run_isolated(jobs, fake_job, fresh_file("one.jsonl"), options);
  options.workers = 3;
  const auto three = run_isolated(jobs, fake_job, fresh_file("three.jsonl"), options);
  ASSERT_EQ(one.records.size(), three.records.size());
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    EXPECT_EQ(one.records[i].job.id(), jobs[i].id());
    EXPECT_EQ(one.records[i].job.id(), three.records[i].job.id());
    EXPECT_EQ(one.records[i].metrics[0].value, three.records[i].metrics[0].value);
  }
}

// Jobs grouped by case: the case id is the group, the method id the job's behaviour, and the
// group's preparation (which may crash or hang, by the case id) leaves a line in a file.
std::vector<Job> grouped_jobs(const std::vector<std::pair<std::string, std::string>>& jobs) {
  std::vector<Job> out;
  for (const auto& [case_id, method] : jobs) {
    Job job;
    job.case_id = case_id;
    job.method_id = method;
    out.push_back(job);
  }
  return out;
}

GroupFunction counting_preparation(const std::filesystem::path& log) {
  return [log](const std::vector<Job>& group) -> JobFunction {
    if (group.front().case_id == "crash_while_preparing")
      std::raise(SIGSEGV);
    if (group.front().case_id == "hang_while_preparing")
      std::this_thread::sleep_for(std::chrono::hours(1));
    std::ofstream(log, std::ios::app) << group.front().case_id << " " << group.size() << "\n";
    return [](const Job& job) {
      Job as_case = job;
      as_case.case_id = job.method_id;  // fake_job's behaviour by the method id
      JobRecord record = fake_job(as_case);
      record.job = job;
      return record;
    };
  };
}

std::vector<std::string> lines_of(const std::filesystem::path& path) {
  std::vector<std::string> lines;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

const GroupKeyFunction by_case = [](const Job& job) { return job.case_id; };

TEST(ProcessPool, GroupsPrepareTheirCaseOnceAndGiveTheSameRecords) {
  const auto jobs = grouped_jobs(
      {{"p", "a"}, {"q", "bb"}, {"p", "ccc"}, {"q", "dddd"}, {"p", "eeeee"}, {"r", "f"}});
  const auto log = fresh_file("preparations.txt");
  ProcessPoolOptions options;
  options.progress = false;
  options.workers = 2;
  const auto path = fresh_file("grouped.jsonl");
  const auto grouped = run_grouped(jobs, by_case, counting_preparation(log), path, options);
  // One preparation per case, with all of its jobs.
  auto prepared = lines_of(log);
  std::sort(prepared.begin(), prepared.end());
  EXPECT_EQ(prepared, (std::vector<std::string>{"p 3", "q 2", "r 1"}));
  ASSERT_EQ(grouped.records.size(), jobs.size());
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    EXPECT_EQ(grouped.records[i].job.id(), jobs[i].id());
    ASSERT_EQ(grouped.records[i].metrics.size(), 1u);
    EXPECT_EQ(grouped.records[i].metrics[0].value, static_cast<double>(jobs[i].method_id.size()));
  }
  EXPECT_EQ(read_records_jsonl(path).size(), jobs.size());
}

// A job forked from its group's process records the time of its heap warm-up as the stage
// `heap_warmup` (the stages add up to the job's work); without a warm-up there is none.
TEST(ProcessPool, AGroupedJobRecordsItsHeapWarmUpAsAStage) {
  const auto jobs = grouped_jobs({{"p", "a"}, {"p", "bb"}, {"q", "ccc"}});
  ProcessPoolOptions options;
  options.progress = false;
  options.workers = 2;
  const auto has_warmup = [](const JobRecord& record) {
    return std::any_of(record.stages.begin(), record.stages.end(),
                       [](const PhaseTiming& stage) { return stage.phase == "heap_warmup"; });
  };
  const auto warmed = run_grouped(jobs, by_case, counting_preparation(fresh_file("w.txt")),
                                  fresh_file("warmed.jsonl"), options);
  ASSERT_EQ(warmed.records.size(), jobs.size());
  for (const auto& record : warmed.records) {
    EXPECT_TRUE(has_warmup(record)) << record.job.id();
    EXPECT_GT(test_support::stage(record, "heap_warmup"), 0.0) << record.job.id();
  }
  options.job_heap_warmup_bytes = 0;
  const auto cold = run_grouped(jobs, by_case, counting_preparation(fresh_file("c.txt")),
                                fresh_file("cold.jsonl"), options);
  ASSERT_EQ(cold.records.size(), jobs.size());
  for (const auto& record : cold.records)
    EXPECT_FALSE(has_warmup(record)) << record.job.id();
}

// Each job of a group is still a process of its own: a crash, a hang or an escape is that
// job's status, and the group's other jobs run.
TEST(ProcessPool, AJobThatCrashesOrHangsInAGroupIsThatJobsStatusAlone) {
  const auto jobs = grouped_jobs(
      {{"p", "a"}, {"p", "crash"}, {"p", "hang"}, {"p", "throw"}, {"p", "bb"}, {"q", "ccc"}});
  ProcessPoolOptions options;
  options.progress = false;
  options.workers = 2;
  options.timeout_seconds = 1.0;
  const auto path = fresh_file("group_statuses.jsonl");
  const auto result =
      run_grouped(jobs, by_case, counting_preparation(fresh_file("p.txt")), path, options);
  ASSERT_EQ(result.records.size(), 6u);
  EXPECT_EQ(result.records[0].status, JobStatus::Ok);
  EXPECT_EQ(result.records[1].status, JobStatus::Crash);
  EXPECT_NE(result.records[1].message.find("Segmentation"), std::string::npos);
  EXPECT_EQ(result.records[2].status, JobStatus::Timeout);
  EXPECT_EQ(result.records[3].status, JobStatus::Error);
  EXPECT_EQ(result.records[4].status, JobStatus::Ok);
  EXPECT_EQ(result.records[5].status, JobStatus::Ok);
  EXPECT_EQ(result.failures, 3u);
  EXPECT_EQ(read_records_jsonl(path).size(), 6u);
}

// A group's process that dies or hangs while making its case: each of its jobs gets a
// record saying so, and the other groups run.
TEST(ProcessPool, AGroupThatDiesOrHangsWhilePreparingGivesEachOfItsJobsARecord) {
  const auto jobs = grouped_jobs({{"crash_while_preparing", "a"},
                                  {"hang_while_preparing", "b"},
                                  {"crash_while_preparing", "c"},
                                  {"p", "dd"}});
  ProcessPoolOptions options;
  options.progress = false;
  options.workers = 2;
  options.timeout_seconds = 0.5;
  options.group_stall_margin_seconds = 0.5;
  const auto result = run_grouped(jobs, by_case, counting_preparation(fresh_file("d.txt")),
                                  fresh_file("group_deaths.jsonl"), options);
  ASSERT_EQ(result.records.size(), 4u);
  for (std::size_t i : {0u, 2u}) {
    EXPECT_EQ(result.records[i].status, JobStatus::Crash);
    EXPECT_NE(result.records[i].message.find("making the job's case died"), std::string::npos)
        << result.records[i].message;
  }
  EXPECT_EQ(result.records[1].status, JobStatus::Timeout);
  EXPECT_NE(result.records[1].message.find("while making its case"), std::string::npos)
      << result.records[1].message;
  EXPECT_EQ(result.records[3].status, JobStatus::Ok);
}

// An interrupted run: the records file holds two finished jobs and a line cut short. With
// resume, those two are kept and only the others run.
TEST(ProcessPool, ResumeRunsOnlyWhatIsMissing) {
  const auto path = fresh_file("resume.jsonl");
  const auto jobs = jobs_named({"a", "bb", "ccc", "dddd"});
  {
    ProcessPoolOptions first;
    first.progress = false;
    run_isolated({jobs[0], jobs[1]}, fake_job, path, first);
    std::ofstream(path, std::ios::app) << "{\"case_id\": \"ccc\", \"meth";  // cut short
  }
  ProcessPoolOptions options;
  options.progress = false;
  options.resume = true;
  const auto result = run_isolated(jobs, fake_job, path, options);
  EXPECT_EQ(result.resumed, 2u);
  ASSERT_EQ(result.records.size(), 4u);
  for (const auto& r : result.records)
    EXPECT_EQ(r.status, JobStatus::Ok);
  // The two resumed records are the earlier run's: four lines in the file now (plus the cut one).
  EXPECT_EQ(read_records_jsonl(path).size(), 4u);
}

}  // namespace
}  // namespace holebench::harness
