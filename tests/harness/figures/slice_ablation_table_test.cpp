// The slice paper's Table 2 by ablation (harness/figures/slice_ablation_table.h): each row
// compares the jobs on which both methods gave their own result; a job where either failed
// or handed a hole to a fallback is left out and counted.
#include "harness/figures/slice_ablation_table.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace holebench::harness {
namespace {

JobRecord record(const std::string& case_id, const std::string& method, double hole_mean,
                 const std::string& fallback = "", JobStatus status = JobStatus::Ok) {
  JobRecord r;
  r.job.case_id = case_id;
  r.job.method_id = method;
  r.status = status;
  HoleRecord hole;
  hole.fallback = fallback;
  r.holes.push_back(hole);
  r.metrics = {{"hole_mean_distance_rel_diag", hole_mean}};
  return r;
}

const SliceAblationRow* paper_row(const std::vector<SliceAblationRow>& rows) {
  for (const auto& row : rows) {
    if (row.pair.loft == "slice_loft" && row.measure == "hole mean distance")
      return &row;
  }
  return nullptr;
}

TEST(SliceAblationTable, ComparesOnlyTheMethodsOwnResults) {
  ResultsData data;
  // Two jobs the loft wins, one direct wins; one where direct's hole went to a fallback (the
  // fallback is far better: it must not count for direct), one where the loft failed.
  data.records = {record("a", "slice_loft", 1.0),
                  record("a", "slice_direct", 2.0),
                  record("b", "slice_loft", 1.0),
                  record("b", "slice_direct", 3.0),
                  record("c", "slice_loft", 5.0),
                  record("c", "slice_direct", 4.0),
                  record("d", "slice_loft", 9.0),
                  record("d", "slice_direct", 0.1, "liepa"),
                  record("e", "slice_loft", 9.0, "", JobStatus::MethodFailed),
                  record("e", "slice_direct", 0.1)};
  const auto rows = slice_ablation_rows(data);
  const SliceAblationRow* row = paper_row(rows);
  ASSERT_NE(row, nullptr);
  EXPECT_EQ(row->holes, 3u);
  EXPECT_EQ(row->left_out, 2u);
  EXPECT_EQ(row->loft_better, 2u);
  EXPECT_EQ(row->direct_better, 1u);
  EXPECT_DOUBLE_EQ(row->loft_median, 1.0);
  EXPECT_DOUBLE_EQ(row->direct_median, 3.0);
}

TEST(SliceAblationTable, EveryJobLeftOutStillGivesARowThatSaysSo) {
  ResultsData data;
  data.records = {record("a", "slice_loft", 1.0, "one_portion_without_features"),
                  record("a", "slice_direct", 2.0)};
  const SliceAblationRow* row = paper_row(slice_ablation_rows(data));
  ASSERT_NE(row, nullptr);
  EXPECT_EQ(row->holes, 0u);
  EXPECT_EQ(row->left_out, 1u);
}

}  // namespace
}  // namespace holebench::harness
