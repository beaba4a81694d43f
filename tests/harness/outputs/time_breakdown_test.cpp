#include "harness/outputs/time_breakdown.h"

#include <gtest/gtest.h>

namespace holebench::harness {
namespace {

JobRecord record_of(const std::string& method, std::vector<PhaseTiming> stages,
                    std::vector<PhaseTiming> evaluation_phases = {}) {
  JobRecord record;
  record.job.case_id = "box/corner";
  record.job.method_id = method;
  record.stages = std::move(stages);
  record.evaluation_phases = std::move(evaluation_phases);
  return record;
}

// Sums by stage, by evaluation step and by method, each from the most time to the least;
// the time outside the method calls over the methods' own, with and without the heap warm-up.
TEST(TimeBreakdown, SumsEachStageStepAndMethod) {
  const std::vector<JobRecord> records{
      record_of("a", {{"heap_warmup", 0.5}, {"case", 1.5}, {"method", 2.0}, {"evaluation", 3.0}},
                {{"shared_case_work", 1.0}, {"whole_model_distances", 1.5}}),
      record_of("b", {{"heap_warmup", 0.5}, {"case", 0.0}, {"method", 1.0}, {"evaluation", 1.0}},
                {{"whole_model_distances", 0.5}}),
      record_of("a", {{"case", 0.0}, {"method", 1.0}})};  // the method failed: no evaluation
  const TimeBreakdown b = time_breakdown(records);
  EXPECT_EQ(b.records, 3u);
  ASSERT_EQ(b.stages.size(), 4u);
  // method and evaluation tie at 4 s: by name.
  EXPECT_EQ(b.stages[0].name, "evaluation");
  EXPECT_EQ(b.stages[0].seconds, 4.0);
  EXPECT_EQ(b.stages[0].records, 2u);
  EXPECT_EQ(b.stages[1].name, "method");
  EXPECT_EQ(b.stages[1].seconds, 4.0);
  EXPECT_EQ(b.stages[1].records, 3u);
  EXPECT_EQ(b.stages[2].name, "case");
  EXPECT_EQ(b.stages[2].seconds, 1.5);
  EXPECT_EQ(b.stages[3].name, "heap_warmup");
  EXPECT_EQ(b.stages[3].seconds, 1.0);
  EXPECT_EQ(b.stages[3].records, 2u);
  ASSERT_EQ(b.evaluation_phases.size(), 2u);
  EXPECT_EQ(b.evaluation_phases[0].name, "whole_model_distances");
  EXPECT_EQ(b.evaluation_phases[0].seconds, 2.0);
  EXPECT_EQ(b.evaluation_phases[0].records, 2u);
  EXPECT_EQ(b.evaluation_phases[1].name, "shared_case_work");
  ASSERT_EQ(b.methods.size(), 2u);
  EXPECT_EQ(b.methods[0].name, "a");
  EXPECT_EQ(b.methods[0].seconds, 3.0);
  EXPECT_EQ(b.methods[0].records, 2u);
  EXPECT_EQ(b.methods[1].name, "b");
  EXPECT_EQ(b.methods[1].seconds, 1.0);
  EXPECT_EQ(b.total_seconds, 10.5);
  EXPECT_EQ(b.method_seconds, 4.0);
  EXPECT_EQ(b.heap_warmup_seconds, 1.0);
  EXPECT_EQ(b.outside_over_methods, 6.5 / 4.0);
  EXPECT_EQ(b.outside_over_methods_without_warmup, 5.5 / 4.0);
}

TEST(TimeBreakdown, PrintsOneTableEach) {
  const std::vector<JobRecord> records{
      record_of("a", {{"method", 2.0}, {"evaluation", 6.0}}, {{"validity", 1.5}})};
  EXPECT_EQ(format_time_breakdown(time_breakdown(records)),
            "1 records, 8.0 worker-s. Outside the method calls / the methods' own: 3.00x (3.00x "
            "without the heap warm-up)\n"
            "\nStages (`stages_s`)\n\n| stage | worker-s | share of all | records |\n"
            "|---|---:|---:|---:|\n"
            "| evaluation | 6.0 | 75 % | 1 |\n"
            "| method | 2.0 | 25 % | 1 |\n"
            "\nEvaluation steps (`evaluation_phases_s`)\n\n"
            "| step | worker-s | share of evaluation | records |\n|---|---:|---:|---:|\n"
            "| validity | 1.5 | 25 % | 1 |\n"
            "\nMethods (the `method` stage)\n\n| method | worker-s | share of methods | records |\n"
            "|---|---:|---:|---:|\n"
            "| a | 2.0 | 100 % | 1 |\n");
}

// No record, or records without a method stage: zeros, no table, no division by zero.
TEST(TimeBreakdown, NoMethodTimeGivesNoRatio) {
  const TimeBreakdown empty = time_breakdown({});
  EXPECT_EQ(empty.outside_over_methods, 0.0);
  EXPECT_EQ(format_time_breakdown(empty),
            "0 records, 0.0 worker-s. Outside the method calls / the methods' own: 0.00x (0.00x "
            "without the heap warm-up)\n");
}

}  // namespace
}  // namespace holebench::harness
