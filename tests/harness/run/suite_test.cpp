#include "harness/run/suite.h"

#include "core/errors.h"

#include <gtest/gtest.h>

#include <fstream>

namespace holebench::harness {
namespace {

// The suites the README names exist, parse, and select something.
TEST(Suite, TheShippedSuitesLoad) {
  const auto names = list_suites();
  for (const char* name : {"default", "smoke", "nightly", "paper"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
    const Suite suite = load_suite(name);
    EXPECT_EQ(suite.name, name);
    EXPECT_FALSE(suite.case_patterns.empty());
    EXPECT_FALSE(suite.noise_levels.empty());
  }
  EXPECT_FALSE(load_suite("smoke").include_cad) << "CI's suite must not need the CAD data";
}

TEST(Suite, TolerancesFallBackToTheDefaultAndIgnoreTimings) {
  const Suite suite = load_suite("nightly");
  const auto correct = suite.tolerances.find("classification_all_correct_fraction");
  ASSERT_TRUE(correct.has_value());
  EXPECT_FALSE(correct->lower_is_better);
  const auto other = suite.tolerances.find("hausdorff_rel_diag");
  ASSERT_TRUE(other.has_value());
  EXPECT_TRUE(other->lower_is_better);
  EXPECT_FALSE(suite.tolerances.find("time_method_s").has_value());
}

// A suite without tolerances (paper, default) still judges each metric the right way round.
TEST(Suite, UnlistedMetricsAreJudgedInTheDirectionTheirNameSays) {
  const Tolerances none;
  for (const char* higher :
       {"classification_k_correct_fraction", "is_closed", "original_faces_unchanged_ok",
        "missing_edge_present_fraction", "missing_edge_covered_fraction", "arrow_visible_fraction",
        "arrow_best_visible_fraction", "distance_converged_ok"}) {
    const auto tolerance = none.find(higher);
    ASSERT_TRUE(tolerance.has_value()) << higher;
    EXPECT_FALSE(tolerance->lower_is_better) << higher;
  }
  for (const char* lower :
       {"hausdorff_rel_diag", "hole_mean_distance_rel_diag", "missing_corner_error_max_rel_diag",
        "arrow_direction_error_deg", "self_intersections_count", "open_boundary_loops_count",
        "new_degenerate_faces_count", "patch_normal_deviation_mean_deg",
        "fallback_holes_fraction"}) {
    const auto tolerance = none.find(lower);
    ASSERT_TRUE(tolerance.has_value()) << lower;
    EXPECT_TRUE(tolerance->lower_is_better) << lower;
  }
  for (const char* size : {"input_faces_count", "new_faces_count", "arrows_count"})
    EXPECT_FALSE(none.find(size).has_value()) << size;
  // A suite's own entry wins over the name.
  Tolerances listed;
  listed.metrics["new_faces_count"] = MetricTolerance{true, 0.1, 1.0};
  ASSERT_TRUE(listed.find("new_faces_count").has_value());
}

// A suite file with `text` is refused with an InvalidInputError that names `field`.
void expect_refused(const std::filesystem::path& path, const std::string& text,
                    const std::string& field) {
  std::ofstream(path) << text;
  try {
    load_suite(path.string());
    ADD_FAILURE() << "accepted: " << text;
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
  }
}

TEST(Suite, BadSuitesAreClearErrors) {
  EXPECT_THROW(load_suite("no_such_suite"), InvalidInputError);
  const auto path = std::filesystem::temp_directory_path() / "holebench_bad_suite.json";
  expect_refused(path, "{\"cases\": []}", "cases");
  std::ofstream(path) << "{not json";
  EXPECT_THROW(load_suite(path.string()), InvalidInputError);
  expect_refused(path, "{\"cases\": [\"box/*\"], \"method_repetitions\": 0}", "method_repetitions");
  std::ofstream(path) << "{\"cases\": [\"box/*\"], \"method_repetitions\": 5}";
  EXPECT_EQ(load_suite(path.string()).method_repetitions, 5);
}

}  // namespace
}  // namespace holebench::harness
