#include "harness/run/run_summary_table.h"

#include <gtest/gtest.h>

namespace holebench::harness {
namespace {

// The table `holebench run` prints, on two hand-made records: numbers as the columns say
// (3 significant digits; ms with one decimal), "-" for a metric a record does not have.
TEST(RunSummaryTable, OneRowPerJobThenTheCounts) {
  RunSummary summary;
  JobRecord ok;
  ok.job.case_id = "box/edge";
  ok.job.method_id = "liepa_cgal";
  ok.job.noise_percent = 5.0;
  ok.metrics = {{"hausdorff_rel_diag", 0.047312}, {"new_faces_count", 100.0}};
  ok.method_seconds = 0.0034;
  JobRecord failed;
  failed.job.case_id = "box/corner";
  failed.job.method_id = "slice_loft";
  failed.status = JobStatus::MethodFailed;
  failed.method_seconds = 0.25;
  summary.records = {ok, failed};
  summary.failures = 1;
  summary.seconds = 7.06;
  summary.results_json = "out/results.json";
  summary.results_csv = "out/results.csv";
  EXPECT_EQ(
      format_run_summary(summary),
      "\n| case | method | noise % | status | hausdorff (rel. diag) | new faces | time (ms) |\n"
      "|---|---|---:|---|---:|---:|---:|\n"
      "| box/edge | liepa_cgal | 5 | ok | 0.0473 | 100 | 3.4 |\n"
      "| box/corner | slice_loft | 0 | method_failed | - | - | 250.0 |\n"
      "\n2 jobs, 1 not ok, 7.1 s. Results: out/results.json and out/results.csv\n");
}

}  // namespace
}  // namespace holebench::harness
