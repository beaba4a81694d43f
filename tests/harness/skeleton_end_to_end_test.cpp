// The walking skeleton end to end: cases -> liepa_cgal -> metrics -> results and PNGs.
#include "harness/run/run_jobs.h"
#include "methods/registry.h"
#include "tests/harness/record_lookup.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace holebench::harness {
namespace {

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("holebench_test_" + name);
  std::filesystem::remove_all(dir);
  return dir;
}

using test_support::metric;

TEST(SkeletonEndToEnd, RunsEveryCaseAndWritesResultsAndSnapshots) {
  RunOptions options;
  options.out_dir = fresh_dir("skeleton");
  options.suite.case_patterns = {"box/*"};
  options.suite.methods = {"liepa_cgal"};
  options.suite.include_cad = false;
  options.progress = false;
  const RunSummary summary = run_jobs(options);
  ASSERT_EQ(summary.records.size(), 3u);
  EXPECT_EQ(summary.failures, 0u);

  for (const auto& record : summary.records) {
    SCOPED_TRACE(record.job.id());
    EXPECT_EQ(record.status, JobStatus::Ok) << record.message;
    EXPECT_EQ(metric(record, "open_boundary_loops_count"), 0.0);
    ASSERT_FALSE(record.snapshot.empty());
    EXPECT_TRUE(std::filesystem::exists(options.out_dir / record.snapshot));
    EXPECT_GT(std::filesystem::file_size(options.out_dir / record.snapshot), 1000u);
    if (record.job.case_id == "box/face_interior") {
      // A planar hole filled in its plane: the repaired mesh is the complete one.
      EXPECT_LT(metric(record, "hausdorff_rel_diag"), 1e-6);
    }
    if (record.job.case_id == "box/corner") {
      // Filling without feature recovery cuts the corner off: clearly not zero.
      EXPECT_GT(metric(record, "hausdorff_rel_diag"), 0.01);
    }
    EXPECT_LE(metric(record, "hausdorff_rel_diag"), metric(record, "hausdorff_upper_rel_diag"));
  }

  // The JSON file: a context block and one record per job, numbers as numbers.
  std::ifstream in(summary.results_json);
  const auto json = nlohmann::json::parse(in);
  ASSERT_TRUE(json.contains("context"));
  for (const char* key : {"schema_version", "code_version", "build_type", "host", "libraries"}) {
    EXPECT_TRUE(json["context"].contains(key)) << key;
  }
  EXPECT_TRUE(json["context"]["schema_version"].is_number_integer());
  ASSERT_EQ(json["results"].size(), 3u);
  for (const auto& record : json["results"]) {
    EXPECT_TRUE(record["metrics"]["hausdorff_rel_diag"].is_number_float());
    EXPECT_EQ(record["status"], "ok");
  }

  // The CSV: a header and one row per metric of each job.
  std::ifstream csv(summary.results_csv);
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line.rfind("job_id,case_id,method", 0), 0u);
  std::size_t rows = 0;
  while (std::getline(csv, line))
    ++rows;
  std::size_t metrics = 0;
  for (const auto& record : summary.records)
    metrics += record.metrics.size();
  EXPECT_EQ(rows, metrics);
}

TEST(SkeletonEndToEnd, SameInputsGiveTheSameRecords) {
  RunOptions options;
  options.suite.case_patterns = {"box/corner"};
  options.suite.methods = {"liepa_cgal"};
  options.suite.include_cad = false;
  options.snapshots = false;
  options.progress = false;
  options.out_dir = fresh_dir("repeat_a");
  const auto first = run_jobs(options);
  options.out_dir = fresh_dir("repeat_b");
  const auto second = run_jobs(options);
  ASSERT_EQ(first.records.size(), second.records.size());
  for (std::size_t i = 0; i < first.records.size(); ++i) {
    for (const char* name : {"hausdorff_rel_diag", "hausdorff_upper_rel_diag", "new_faces_count"}) {
      EXPECT_EQ(metric(first.records[i], name), metric(second.records[i], name)) << name;
    }
  }
}

TEST(SkeletonEndToEnd, UnknownCaseOrMethodIsRejectedBeforeRunning) {
  RunOptions options;
  options.out_dir = fresh_dir("unknown");
  options.suite.include_cad = false;
  const generators::CaseCatalog catalog(run_catalog_options(options));
  options.suite.case_patterns = {"no/such/case"};
  EXPECT_THROW(plan_jobs(options, catalog), std::invalid_argument);
  options.suite.case_patterns = {"box/*"};
  options.suite.methods = {"no_such_method"};
  EXPECT_THROW(plan_jobs(options, catalog), std::invalid_argument);
}

// Each planned job carries its method's settings, which its record names.
TEST(SkeletonEndToEnd, PlannedJobsCarryTheirMethodsSettings) {
  RunOptions options;
  options.suite.include_cad = false;
  options.suite.case_patterns = {"box/corner"};
  options.suite.methods = {"slice_loft", "slice_direct"};
  const generators::CaseCatalog catalog(run_catalog_options(options));
  const std::vector<Job> jobs = plan_jobs(options, catalog);
  ASSERT_EQ(jobs.size(), 2u);
  EXPECT_EQ(jobs[0].method_options, make_method("slice_loft")->options());
  EXPECT_EQ(jobs[1].method_options, make_method("slice_direct")->options());
  EXPECT_NE(jobs[0].method_options, jobs[1].method_options);
}

TEST(RunJob, AnUnknownCaseBecomesAnInvalidInputRecordNotACrash) {
  const JobRecord record = run_job({"no/such/case", "liepa_cgal", 0.0, 0, "no_user"}, {});
  EXPECT_EQ(record.status, JobStatus::InvalidInput);
  EXPECT_NE(record.message.find("no/such/case"), std::string::npos);
}

}  // namespace
}  // namespace holebench::harness
