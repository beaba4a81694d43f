// `holebench validate` on the fixtures in tests/harness/fixtures/validate/: clean.json is
// consistent (every metric in its range and order, an ok job whose open hole is guided, a
// partial job with an open hole, a failed job without metrics, a cross-metric difference
// within the 1e-12 slack); every other file holds one kind of violation, named after its
// check, with the values written into it by hand.
#include "harness/results/validate_results.h"

#include "core/errors.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>

namespace holebench::harness {
namespace {

const std::filesystem::path kFixtures =
    std::filesystem::path(HOLEBENCH_SOURCE_DIR) / "tests" / "harness" / "fixtures" / "validate";

ValidationReport validate(const std::string& file) {
  return validate_results_files({kFixtures / file});
}

std::string listing(const ValidationReport& report) {
  std::string text;
  for (const auto& v : report.violations)
    text += format_violation(v) + "\n";
  return text;
}

// The violations of `file`, as (job id, check) pairs, equal `expected` in file order; each
// message names the metrics it is about.
void expect_violations(const std::string& file,
                       const std::vector<std::pair<std::string, std::string>>& expected,
                       const std::vector<std::string>& mentioned = {}) {
  SCOPED_TRACE(file);
  const ValidationReport report = validate(file);
  std::vector<std::pair<std::string, std::string>> found;
  for (const auto& v : report.violations) {
    found.emplace_back(v.job_id, v.check);
    EXPECT_EQ(v.file, (kFixtures / file).string());
  }
  EXPECT_EQ(found, expected) << listing(report);
  for (const auto& text : mentioned)
    EXPECT_NE(listing(report).find(text), std::string::npos) << text << "\n" << listing(report);
  EXPECT_FALSE(report.ok());
}

const std::string kCorner = "box/corner|liepa_cgal|no_user|0|0";
const std::string kEdge = "box/edge|liepa_cgal|no_user|0|0";

TEST(ValidateResults, TheCleanFileHasNoViolation) {
  const ValidationReport report = validate("clean.json");
  EXPECT_EQ(report.records, 5u);
  EXPECT_TRUE(report.ok()) << listing(report);
  EXPECT_EQ(format_validation_summary(report), "5 records, 0 violations");
}

TEST(ValidateResults, FindsAnUnknownSchemaVersion) {
  expect_violations("schema_version.json", {{"", "schema_version"}}, {"context: schema_version 2"});
}

TEST(ValidateResults, FindsMissingRequiredFields) {
  expect_violations("required_field.json",
                    {{kCorner, "required_field"},
                     {"box/face_interior|crest_feature|no_user|0|0", "required_field"}},
                    {"\"case_id\" is missing", "\"metrics\" is missing"});
}

// A built-in method's record names its settings in a "method_options" object of flags,
// numbers and names (clean.json's first record), an external method's its command; a record
// whose method_options is neither is reported (field_type.json's first record is well formed).
TEST(ValidateResults, FindsMethodOptionsThatAreNotAnObjectWithACommand) {
  expect_violations("field_type.json", {{"box/edge|fan_fill|no_user|0|0", "field_type"}},
                    {"\"method_options\" is neither an object of flags, numbers and names"});
}

TEST(ValidateResults, FindsAnUnknownStatus) {
  expect_violations("status.json", {{kCorner, "status"}}, {"unknown job status 'fine'"});
}

TEST(ValidateResults, FindsADuplicateJobId) {
  expect_violations("duplicate_job_id.json", {{kCorner, "duplicate_job_id"}},
                    {"the job id of record 0 of"});
}

// Job ids are unique across the files given together: the clean file twice repeats each.
TEST(ValidateResults, JobIdsAreUniqueAcrossFiles) {
  const auto report = validate_results_files({kFixtures / "clean.json", kFixtures / "clean.json"});
  EXPECT_EQ(report.records, 10u);
  ASSERT_EQ(report.violations.size(), 5u) << listing(report);
  for (const auto& v : report.violations)
    EXPECT_EQ(v.check, "duplicate_job_id");
}

TEST(ValidateResults, FindsAJobIdThatIsNotTheIdOfItsFields) {
  expect_violations("job_id_mismatch.json", {{kCorner, "job_id_mismatch"}},
                    {"box/corner|liepa_cgal|no_user|5|0"});
}

TEST(ValidateResults, FindsAnOkJobWithoutMetrics) {
  expect_violations("metrics_missing.json", {{kCorner, "metrics_missing"}}, {"status ok"});
}

// A NaN or infinity is written as null; a string is no number either.
TEST(ValidateResults, FindsMetricsThatAreNotFiniteNumbers) {
  expect_violations("finite.json", {{kCorner, "finite"}, {kCorner, "finite"}},
                    {"hausdorff_rel_diag is null", "time_method_s is not a number: \"fast\""});
}

TEST(ValidateResults, FindsIntervalsOutOfOrder) {
  expect_violations(
      "interval.json",
      {{kCorner, "interval"},
       {kEdge, "interval"},
       {"box/face_interior|liepa_cgal|no_user|0|0", "interval"},
       {"solid/l_block/island/small|liepa_cgal|no_user|0|0", "interval"}},
      {"mean_distance_rel_diag = 0.0012 > mean_distance_upper_rel_diag = 0.0011 (value <= upper)",
       "rms_distance_lower_rel_diag = 0.00201 > rms_distance_rel_diag = 0.002 (lower <= value)",
       "hole_hausdorff_rel_diag = -0.001 is negative",
       "hausdorff_upper_rel_diag is a bound of hausdorff_rel_diag, which is missing"});
}

TEST(ValidateResults, FindsDistancesOutOfOrder) {
  expect_violations(
      "distance_order.json", {{kCorner, "distance_order"}, {kEdge, "distance_order"}},
      {"mean_distance_rel_diag = 0.0025 > rms_distance_rel_diag = 0.002",
       "hole_rms_distance_rel_diag = 0.005 > hole_hausdorff_upper_rel_diag = 0.0041"});
}

TEST(ValidateResults, FindsANewVertexErrorAboveTheHoleHausdorff) {
  expect_violations("new_vertex_error.json", {{kCorner, "new_vertex_error"}},
                    {"new_vertex_mean_error_rel_diag = 0.0042 > hole_hausdorff_upper_rel_diag"});
}

// Chamfer-L1 above the mean distance, Chamfer-L2 above the squared RMS distance (hole
// region), and a negative bound of a squared length.
TEST(ValidateResults, FindsChamferDistancesAboveTheDistancesTheyAverage) {
  expect_violations("chamfer.json",
                    {{kCorner, "interval"}, {kCorner, "chamfer"}, {kCorner, "chamfer"}},
                    {"chamfer_l2_lower_rel_diag2 = -1e-09 is negative",
                     "chamfer_l1_rel_diag = 0.0015 > mean_distance_rel_diag = 0.001",
                     "hole_chamfer_l2_rel_diag2 = 1e-05 > hole_rms_distance_rel_diag^2"});
}

// valid_repair_ok = 1 on an output that crosses itself and is not consistently oriented.
TEST(ValidateResults, FindsAValidRepairThatIsNot) {
  expect_violations("valid_repair.json", {{kCorner, "valid_repair"}, {kCorner, "valid_repair"}},
                    {"valid_repair_ok = 1 but is_consistently_oriented = 0",
                     "valid_repair_ok = 1 but patch_self_intersections_count = 3"});
}

TEST(ValidateResults, FindsFractionsFlagsAndCountsOutOfRange) {
  expect_violations("fraction_range.json", {{kCorner, "fraction_range"}},
                    {"missing_edge_present_fraction = 1.5 is outside [0, 1]"});
  expect_violations("flag_value.json", {{kCorner, "flag_value"}, {kCorner, "flag_value"}},
                    {"distance_converged_ok = 2", "is_closed = 0.5"});
  expect_violations("count_value.json", {{kCorner, "count_value"}, {kCorner, "count_value"}},
                    {"new_faces_count = 57.5", "open_boundary_loops_count = -1"});
}

TEST(ValidateResults, FindsAnOkJobWithAnOpenUnguidedHole) {
  expect_violations("open_hole.json", {{kCorner, "open_hole"}},
                    {"status ok, but hole 1 is open and has no guidance arrow"});
}

// A record in memory may hold what JSON cannot: an infinity is reported as not finite, once.
TEST(ValidateResults, AnInfiniteMetricInMemoryIsNotFinite) {
  JobRecord record;
  record.job = {"box/corner", "liepa_cgal"};
  record.metrics = {{"hausdorff_rel_diag", std::numeric_limits<double>::infinity()},
                    {"hausdorff_upper_rel_diag", 0.1}};
  const auto violations = validate_record(record);
  ASSERT_EQ(violations.size(), 1u);
  EXPECT_EQ(violations[0].check, "finite");
  EXPECT_EQ(violations[0].job_id, kCorner);
  EXPECT_EQ(violations[0].message, "hausdorff_rel_diag = inf is not a finite number");
}

// An unreadable file is an error naming the file, not a violation.
TEST(ValidateResults, AnUnreadableFileThrowsNamingIt) {
  const auto missing = kFixtures / "no_such_file.json";
  try {
    validate_results_files({kFixtures / "clean.json", missing});
    ADD_FAILURE() << "no error";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
  }
  const auto not_results = std::filesystem::temp_directory_path() / "holebench_not_results.json";
  std::ofstream(not_results) << "{\"records\": []}\n";
  EXPECT_THROW(validate_results_files({not_results}), InvalidInputError);
}

}  // namespace
}  // namespace holebench::harness
