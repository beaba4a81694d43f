#include "harness/results/results_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace holebench::harness {
namespace {

JobRecord sample_record() {
  JobRecord record;
  record.job = {"box/edge", "liepa_cgal", 5.0, 3};
  record.case_family = "box";
  record.case_kind = "edge";
  record.status = JobStatus::Partial;
  record.message = "1 of 2 holes left open, \"quoted\"";
  record.metrics = {{"hausdorff_rel_diag", 0.046358123456789012}, {"new_faces_count", 92}};
  HoleRecord hole;
  hole.hole_index = 0;
  hole.loop_size = 24;
  hole.closed = true;
  hole.new_faces = 92;
  record.holes = {hole};
  return record;
}

TEST(ResultsFile, JsonKeepsNumbersAsNumbersAndExact) {
  const auto path = std::filesystem::temp_directory_path() / "holebench_results_test.json";
  write_results_json(path, current_context("unit"), {sample_record()});
  std::ifstream in(path);
  const auto json = nlohmann::json::parse(in);
  EXPECT_EQ(json["context"]["suite"], "unit");
  EXPECT_EQ(json["context"]["schema_version"], kResultsSchemaVersion);
  const auto& record = json["results"][0];
  EXPECT_EQ(record["job_id"], "box/edge|liepa_cgal|no_user|5|3");
  EXPECT_EQ(record["noise_percent"], 5.0);
  EXPECT_EQ(record["status"], "partial");
  EXPECT_EQ(record["seed"], 3);
  EXPECT_EQ(record["metrics"]["hausdorff_rel_diag"].get<double>(), 0.046358123456789012);
  EXPECT_EQ(record["holes"][0]["new_faces"], 92);
}

TEST(ResultsFile, CsvQuotesTextAndWritesOneRowPerMetric) {
  const auto path = std::filesystem::temp_directory_path() / "holebench_results_test.csv";
  JobRecord failed = sample_record();
  failed.job.case_id = "a,b";
  failed.metrics.clear();
  write_results_csv(path, {sample_record(), failed});
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  ASSERT_EQ(lines.size(), 1u + 2u + 1u);
  // The value is written so that it reads back to the same double.
  const std::string key = ",hausdorff_rel_diag,";
  const auto at = lines[1].find(key);
  ASSERT_NE(at, std::string::npos);
  EXPECT_EQ(std::stod(lines[1].substr(at + key.size())), 0.046358123456789012);
  EXPECT_NE(lines[3].find("\"a,b\""), std::string::npos);
  EXPECT_EQ(lines[3].substr(lines[3].size() - 2), ",,");
}

}  // namespace
}  // namespace holebench::harness
