#include "harness/results/merge_results.h"

#include "harness/results/results_file.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace holebench::harness {
namespace {

JobRecord record(const std::string& case_id, double hausdorff) {
  JobRecord r;
  r.job.case_id = case_id;
  r.job.method_id = "liepa_cgal";
  r.metrics = {{"hausdorff_rel_diag", hausdorff}};
  return r;
}

// Records are matched by job id, a later set wins, and the result is ordered by id.
TEST(MergeResults, LaterSetsReplaceRecordsWithTheSameId) {
  ResultsData a, b;
  a.context.suite = "first";
  a.records = {record("box/edge", 1.0), record("box/corner", 2.0)};
  b.records = {record("box/corner", 3.0), record("box/face_interior", 4.0)};
  const ResultsData merged = merge_results({a, b});
  EXPECT_EQ(merged.context.suite, "first");
  ASSERT_EQ(merged.records.size(), 3u);
  EXPECT_EQ(merged.records[0].job.case_id, "box/corner");
  EXPECT_EQ(merged.records[0].metrics[0].value, 3.0);
  EXPECT_EQ(merged.records[1].job.case_id, "box/edge");
  EXPECT_EQ(merged.records[2].job.case_id, "box/face_interior");
}

// A snapshot path follows the results file it is merged into.
TEST(MergeResults, SnapshotPathsAreMadeRelativeToTheMergedFile) {
  EXPECT_EQ(snapshot_relative_to("snapshots/a.png", "/runs/one", "/runs/merged"),
            "../one/snapshots/a.png");
  EXPECT_EQ(snapshot_relative_to("snapshots/a.png", "/runs/one", "/runs/one"), "snapshots/a.png");
  EXPECT_EQ(snapshot_relative_to("", "/runs/one", "/runs/merged"), "");
}

// `holebench merge A/results.json B/results.json --out M`: M/results.json and results.csv
// hold the records of both (B's where both have a job), each snapshot path relative to M,
// and the context of A.
TEST(MergeResults, FilesAreMergedIntoTheOutputFolderWithSnapshotsFollowing) {
  const auto root = std::filesystem::temp_directory_path() / "holebench_merge_results_test";
  std::filesystem::remove_all(root);
  std::filesystem::create_directories(root / "a");
  std::filesystem::create_directories(root / "b");
  RunContext context_a;
  context_a.suite = "smoke";
  auto edge = record("box/edge", 1.0);
  edge.snapshot = "snapshots/edge.png";
  auto corner_a = record("box/corner", 2.0);
  write_results_json(root / "a" / "results.json", context_a, {edge, corner_a});
  RunContext context_b;
  context_b.suite = "other";
  auto corner_b = record("box/corner", 3.0);
  corner_b.snapshot = "snapshots/corner.png";
  write_results_json(root / "b" / "results.json", context_b, {corner_b});

  const auto out = root / "merged";
  const MergedFiles result =
      merge_results_files({root / "a" / "results.json", root / "b" / "results.json"}, out);
  EXPECT_EQ(result.results_json, out / "results.json");
  EXPECT_TRUE(std::filesystem::exists(out / "results.csv"));
  const ResultsData back = read_results_json(out / "results.json");
  EXPECT_EQ(back.context.suite, "smoke");
  ASSERT_EQ(back.records.size(), 2u);
  EXPECT_EQ(back.records[0].job.case_id, "box/corner");
  EXPECT_EQ(back.records[0].metrics[0].value, 3.0);
  EXPECT_EQ(back.records[0].snapshot, "../b/snapshots/corner.png");
  EXPECT_EQ(back.records[1].job.case_id, "box/edge");
  EXPECT_EQ(back.records[1].snapshot, "../a/snapshots/edge.png");
  std::filesystem::remove_all(root);
}

}  // namespace
}  // namespace holebench::harness
