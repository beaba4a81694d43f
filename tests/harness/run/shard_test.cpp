// Shards: parsing I/N, and the slicing of a plan: the N shards together are the plan, each
// job exactly once, whatever N, the same on every call.
#include "harness/run/shard.h"

#include "harness/results/results_reader.h"
#include "harness/run/run_jobs.h"
#include "harness/run/suite.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace holebench::harness {
namespace {

std::vector<Job> smoke_plan() {
  RunOptions options;
  options.suite = load_suite("smoke");
  const generators::CaseCatalog catalog(run_catalog_options(options));
  return plan_jobs(options, catalog);
}

std::string error_of(const std::string& text) {
  try {
    parse_shard(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(Shard, ParsesIndexOverCount) {
  const auto shard = parse_shard("2/4");
  EXPECT_EQ(shard.index, 2u);
  EXPECT_EQ(shard.count, 4u);
  EXPECT_EQ(to_string(shard), "2/4");
  EXPECT_EQ(parse_shard("0/1").count, 1u);
}

TEST(Shard, BadTextSaysWhatIsWrong) {
  EXPECT_NE(error_of("5/4").find("must be below N"), std::string::npos) << error_of("5/4");
  EXPECT_NE(error_of("4/4").find("numbered 0 to 3"), std::string::npos) << error_of("4/4");
  EXPECT_NE(error_of("x").find("expected I/N"), std::string::npos) << error_of("x");
  EXPECT_NE(error_of("1/0").find("at least 1"), std::string::npos) << error_of("1/0");
  EXPECT_NE(error_of("a/4").find("not a number"), std::string::npos) << error_of("a/4");
  EXPECT_NE(error_of("-1/4").find("not a number"), std::string::npos) << error_of("-1/4");
  EXPECT_NE(error_of("1/").find("not a number"), std::string::npos) << error_of("1/");
  EXPECT_NE(error_of("1/4/2").find("not a number"), std::string::npos) << error_of("1/4/2");
}

TEST(Shard, UnionOfTheShardsIsThePlanEachJobOnce) {
  const auto plan = smoke_plan();
  ASSERT_GT(plan.size(), 100u);
  for (std::size_t count : {1u, 2u, 3u, 4u, 7u, 160u, 1000u}) {
    SCOPED_TRACE("N = " + std::to_string(count));
    std::map<std::string, int> seen;
    std::map<std::string, std::set<std::size_t>> shards_of_instance;
    std::size_t smallest = plan.size(), largest = 0;
    for (std::size_t index = 0; index < count; ++index) {
      const auto jobs = jobs_of_shard(plan, {index, count});
      std::set<std::string> instances;
      for (const auto& job : jobs) {
        ++seen[job.id()];
        instances.insert(job.case_instance());
        shards_of_instance[job.case_instance()].insert(index);
      }
      smallest = std::min(smallest, instances.size());
      largest = std::max(largest, instances.size());
    }
    EXPECT_EQ(seen.size(), plan.size());
    for (const auto& job : plan)
      EXPECT_EQ(seen[job.id()], 1) << job.id();
    for (const auto& [instance, shards] : shards_of_instance)
      EXPECT_EQ(shards.size(), 1u) << instance << ": all its jobs in one shard";
    EXPECT_LE(largest - smallest, 1u) << "the shards are balanced by case instances";
  }
}

TEST(Shard, SlicingIsDeterministicAndFollowsPlanOrder) {
  const auto plan = smoke_plan();
  const auto again = smoke_plan();
  ASSERT_EQ(plan.size(), again.size());
  const auto shard = jobs_of_shard(plan, {1, 4});
  const auto shard_again = jobs_of_shard(again, {1, 4});
  ASSERT_EQ(shard.size(), shard_again.size());
  for (std::size_t i = 0; i < shard.size(); ++i)
    EXPECT_EQ(shard[i].id(), shard_again[i].id());
  // The g-th case instance of the plan goes to shard g mod N, its jobs in plan order.
  std::vector<std::string> instances;
  std::vector<std::string> expected;
  for (const auto& job : plan) {
    if (std::find(instances.begin(), instances.end(), job.case_instance()) == instances.end())
      instances.push_back(job.case_instance());
    const auto g =
        std::find(instances.begin(), instances.end(), job.case_instance()) - instances.begin();
    if (g % 4 == 1)
      expected.push_back(job.id());
  }
  ASSERT_EQ(shard.size(), expected.size());
  for (std::size_t i = 0; i < shard.size(); ++i)
    EXPECT_EQ(shard[i].id(), expected[i]);
  EXPECT_EQ(case_instance_of_job_id(plan[0].id()), plan[0].case_instance());
  EXPECT_EQ(case_instance_of_job_id("a|b"), "");
  EXPECT_THROW(jobs_of_shard(plan, {4, 4}), std::invalid_argument);
}

TEST(Shard, ShardListsAndTheirArraySpec) {
  EXPECT_EQ(parse_shard_list("3,1,1", 4), (std::vector<std::size_t>{1, 3}));
  EXPECT_EQ(parse_shard_list("0-2,7", 8), (std::vector<std::size_t>{0, 1, 2, 7}));
  EXPECT_THROW(parse_shard_list("4", 4), std::invalid_argument);
  EXPECT_THROW(parse_shard_list("2-1", 4), std::invalid_argument);
  EXPECT_THROW(parse_shard_list("1,,2", 4), std::invalid_argument);
  EXPECT_THROW(parse_shard_list("", 4), std::invalid_argument);
  EXPECT_EQ(shard_list_to_array_spec({0, 1, 2, 3}), "0-3");
  EXPECT_EQ(shard_list_to_array_spec({1, 3}), "1,3");
  EXPECT_EQ(shard_list_to_array_spec({0, 1, 2, 7, 9, 10}), "0-2,7,9-10");
}

TEST(Shard, RunWritesOnlyItsShardAndNamesItInTheContext) {
  RunOptions options;
  options.out_dir = std::filesystem::temp_directory_path() / "holebench_shard_run";
  std::filesystem::remove_all(options.out_dir);
  options.suite.case_patterns = {"box/*"};
  options.suite.methods = {"liepa_cgal"};
  options.suite.noise_levels = {0.0, 5.0};
  options.suite.include_cad = false;
  options.snapshots = false;
  options.progress = false;
  options.shard = {1, 4};
  const generators::CaseCatalog catalog(run_catalog_options(options));
  const auto expected = jobs_of_shard(plan_jobs(options, catalog), options.shard);
  const auto summary = run_jobs(options);
  ASSERT_EQ(summary.records.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_EQ(summary.records[i].job.id(), expected[i].id());
  const auto written = read_results_json(summary.results_json);
  EXPECT_EQ(written.context.shard, "1/4");
  EXPECT_EQ(written.records.size(), expected.size());
}

}  // namespace
}  // namespace holebench::harness
