#include "harness/results_reader.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace holebench::harness
