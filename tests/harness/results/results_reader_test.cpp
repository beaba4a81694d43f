#include "harness/results/results_reader.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

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

// A hole's fallback is written in every hole record ("" when the method's own path handled
// it) and reads back as written; a hole record of an older file without it reads as "".
TEST(RecordJson, HoleFallbackRoundTripsAndDefaultsToEmpty) {
  JobRecord r = record("box/corner", 0.5);
  HoleRecord own;
  own.hole_index = 0;
  own.closed = true;
  HoleRecord stood_in;
  stood_in.hole_index = 1;
  stood_in.closed = true;
  stood_in.note = "a sub-hole could not be stitched";
  stood_in.fallback = "cgal_triangulate_hole";
  r.holes = {own, stood_in};

  const std::string line = record_to_json_line(r);
  const auto json = nlohmann::json::parse(line);
  ASSERT_TRUE(json["holes"][0].contains("fallback"));
  EXPECT_EQ(json["holes"][0]["fallback"], "");
  EXPECT_EQ(json["holes"][1]["fallback"], "cgal_triangulate_hole");

  const JobRecord back = record_from_json_text(line);
  ASSERT_EQ(back.holes.size(), 2u);
  EXPECT_EQ(back.holes[0].fallback, "");
  EXPECT_EQ(back.holes[1].fallback, "cgal_triangulate_hole");
  EXPECT_EQ(back.holes[1].note, "a sub-hole could not be stitched");

  auto older = json;
  older["holes"][1].erase("fallback");
  EXPECT_EQ(record_from_json_text(older.dump()).holes[1].fallback, "");
}

}  // namespace
}  // namespace holebench::harness
