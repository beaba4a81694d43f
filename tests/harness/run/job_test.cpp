#include "harness/run/job.h"

#include "harness/results/record_json.h"
#include "tests/harness/record_lookup.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <numeric>
#include <string>
#include <vector>

namespace holebench::harness {
namespace {

using test_support::metric;
using test_support::stage;

// Repetitions change the timing only: the method time is the median of the runs, the stage
// time their sum, and every other metric is the one-run record's.
TEST(Job, MethodRepetitionsGiveTheMedianTimeAndTheSameResult) {
  const Job job{"box/corner", "liepa_cgal", 0.0, 0, "no_user"};
  JobOptions once;
  const JobRecord single = run_job(job, once);
  ASSERT_EQ(single.status, JobStatus::Ok) << single.message;
  ASSERT_EQ(single.method_run_seconds.size(), 1u);
  EXPECT_EQ(single.method_seconds, single.method_run_seconds[0]);

  JobOptions thrice;
  thrice.method_repetitions = 3;
  const JobRecord repeated = run_job(job, thrice);
  ASSERT_EQ(repeated.status, JobStatus::Ok) << repeated.message;
  ASSERT_EQ(repeated.method_run_seconds.size(), 3u);
  EXPECT_EQ(repeated.method_seconds, median_of(repeated.method_run_seconds));
  EXPECT_EQ(metric(repeated, "time_method_s"), repeated.method_seconds);
  EXPECT_DOUBLE_EQ(
      stage(repeated, "method"),
      std::accumulate(repeated.method_run_seconds.begin(), repeated.method_run_seconds.end(), 0.0));
  ASSERT_EQ(repeated.metrics.size(), single.metrics.size());
  for (std::size_t i = 0; i < single.metrics.size(); ++i) {
    if (single.metrics[i].name == "time_method_s")
      continue;
    EXPECT_EQ(repeated.metrics[i].name, single.metrics[i].name);
    EXPECT_EQ(repeated.metrics[i].value, single.metrics[i].value) << single.metrics[i].name;
  }

  // The runs survive the record's JSON (results files, records.jsonl, --resume).
  const JobRecord back = record_from_json(nlohmann::json::parse(record_to_json(repeated).dump()));
  EXPECT_EQ(back.method_run_seconds, repeated.method_run_seconds);
  EXPECT_EQ(back.method_seconds, repeated.method_seconds);
}

// --layers: the job draws the method's layers (a PNG and an OBJ named after the job) and its
// record is the same as without them, timings aside.
TEST(Job, LayersAreDrawnAndChangeNoMetric) {
  const Job job{"box/corner", "slice_loft", 0.0, 0, "no_user"};
  const JobRecord plain = run_job(job, JobOptions{});
  ASSERT_EQ(plain.status, JobStatus::Ok) << plain.message;
  JobOptions layered;
  layered.layers_dir = std::filesystem::temp_directory_path() / "holebench_job_layers";
  std::filesystem::remove_all(layered.layers_dir);
  std::filesystem::create_directories(layered.layers_dir);
  const JobRecord drawn = run_job(job, layered);
  ASSERT_EQ(drawn.status, JobStatus::Ok) << drawn.message;
  const std::string stem = "box_corner_slice_loft_no_user_0_0";
  EXPECT_GT(std::filesystem::file_size(layered.layers_dir / (stem + ".png")), 1000u);
  EXPECT_GT(std::filesystem::file_size(layered.layers_dir / (stem + ".obj")), 1000u);
  EXPECT_GE(stage(drawn, "layers"), 0.0);
  ASSERT_EQ(drawn.metrics.size(), plain.metrics.size());
  for (std::size_t i = 0; i < plain.metrics.size(); ++i) {
    if (plain.metrics[i].name == "time_method_s")
      continue;
    EXPECT_EQ(drawn.metrics[i].name, plain.metrics[i].name);
    EXPECT_EQ(drawn.metrics[i].value, plain.metrics[i].value) << plain.metrics[i].name;
  }
  ASSERT_EQ(drawn.holes.size(), plain.holes.size());
  EXPECT_EQ(drawn.holes[0].note, plain.holes[0].note);
}

std::vector<std::string> names_of(const std::vector<PhaseTiming>& phases) {
  std::vector<std::string> names;
  for (const auto& phase : phases)
    names.push_back(phase.phase);
  return names;
}

// A job's record times the evaluation's steps; the first job of a group also counts the case's
// shared evaluation work there, as its evaluation stage does; a later job does not. The steps
// add up to the stage (the rest is the job's bookkeeping around the call), and they survive
// the record's JSON.
TEST(Job, TheEvaluationStepsAddUpToTheStage) {
  const Job job{"box/corner", "liepa_cgal", 0.0, 0, "no_user"};
  const JobOptions options;
  PreparedCase prepared = prepare_case(job, options);
  share_case_work(prepared, options);
  ASSERT_TRUE(prepared.evaluation);
  const JobRecord first = run_job_on_case(job, prepared, true, options);
  const JobRecord later = run_job_on_case(job, prepared, false, options);
  ASSERT_EQ(first.status, JobStatus::Ok) << first.message;
  const std::vector<std::string> steps{"kept_faces",
                                       "repaired_scene",
                                       "patch_mean_distance",
                                       "whole_model_distances",
                                       "hole_region_distances",
                                       "new_vertex_error",
                                       "literature_metrics",
                                       "feature_recovery",
                                       "validity",
                                       "classification",
                                       "arrow_visibility"};
  std::vector<std::string> first_steps = steps;
  first_steps.insert(first_steps.begin(), "shared_case_work");
  EXPECT_EQ(names_of(first.evaluation_phases), first_steps);
  EXPECT_EQ(names_of(later.evaluation_phases), steps);
  EXPECT_EQ(first.evaluation_phases[0].seconds, prepared.evaluation_seconds);
  for (const JobRecord* record : {&first, &later}) {
    double sum = 0.0;
    for (const auto& phase : record->evaluation_phases) {
      EXPECT_GE(phase.seconds, 0.0) << phase.phase;
      sum += phase.seconds;
    }
    EXPECT_LE(sum, stage(*record, "evaluation"));
    EXPECT_GT(sum, 0.5 * stage(*record, "evaluation"));
  }
  // (A results file read back has its timings by name, in the order of their names.)
  const JobRecord back = record_from_json(nlohmann::json::parse(record_to_json(first).dump()));
  std::map<std::string, double> written, read;
  for (const auto& phase : first.evaluation_phases)
    written[phase.phase] = phase.seconds;
  for (const auto& phase : back.evaluation_phases)
    read[phase.phase] = phase.seconds;
  EXPECT_EQ(read, written);
}

}  // namespace
}  // namespace holebench::harness
