#include "harness/run/suite.h"
#include "harness/run/run_jobs.h"

#include "core/errors.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <thread>

namespace holebench::harness {
namespace {

// The suites the README names exist, parse, and select something.
TEST(Suite, TheShippedSuitesLoad) {
  const auto names = list_suites();
  for (const char* name : {"default", "smoke", "nightly", "paper", "kicad"}) {
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

// Hostile suites: each is one line naming the file and the field.
TEST(Suite, HostileSuitesNameTheFileAndTheField) {
  const auto path = std::filesystem::temp_directory_path() / "holebench_hostile_suite.json";
  const auto refused = [&](const std::string& text, const std::string& field) {
    SCOPED_TRACE(text);
    std::ofstream(path) << text;
    try {
      load_suite(path.string());
      ADD_FAILURE() << "accepted";
    } catch (const InvalidInputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(path.string()), std::string::npos) << what;
      EXPECT_NE(what.find(field), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  };
  // An unknown key (a typo would silently run something else), at each level.
  refused(R"({"cases": ["box/*"], "noise": [5]})", "unknown field \"noise\"");
  refused(R"({"cases": ["box/*"], "evaluation": {"hausdorff_bound": 1}})",
          "evaluation.hausdorff_bound");
  refused(R"({"cases": ["box/*"], "tolerances": {"default": {"relativ": 1}}})",
          "tolerances.default.relativ");
  // Empty lists: nothing would run.
  refused(R"({"cases": []})", "\"cases\" is an empty list");
  refused(R"({"cases": ["box/*"], "users": []})", "\"users\" is an empty list");
  refused(R"({"cases": ["box/*"], "noise_percent": []})", "\"noise_percent\" is an empty list");
  refused(R"({"cases": ["box/*"], "seeds": []})", "\"seeds\" is an empty list");
  refused(R"({"methods": ["liepa_cgal"]})", "\"cases\" is missing");
  // Negative and out-of-range numbers.
  refused(R"({"cases": ["box/*"], "noise_percent": [0, -5]})", "noise_percent[1]");
  refused(R"({"cases": ["box/*"], "timeout_s": -1})", "timeout_s");
  refused(R"({"cases": ["box/*"], "seeds": [-1]})", "seeds[0]");
  refused(R"({"cases": ["box/*"], "seeds": [1e30]})", "seeds[0]");
  refused(R"({"cases": ["box/*"], "tolerances": {"metrics": {"x": {"relative": -0.1}}}})",
          "tolerances.metrics.x.relative");
  refused(R"({"cases": ["box/*"], "evaluation": {"mean_query_budget": 0}})",
          "evaluation.mean_query_budget");
  refused(R"({"cases": ["box/*"], "memory_limit": "lots"})", "memory_limit");
  // Wrong types.
  refused(R"({"cases": "box/*"})", "\"cases\": expected a list");
  refused(R"({"cases": ["box/*"], "noise_percent": ["5"]})", "noise_percent[0]");
  refused(R"({"cases": ["box/*"], "include_cad": "no"})", "include_cad");
  refused(R"({"cases": ["box/*"], "external_methods": [{"command": "x {input} {output}"}]})",
          "external_methods[0].name");
  refused(R"({"cases": ["box/*"], "noise_percent": [NaN]})", "line 1");
}

TEST(Suite, TheMemoryLimitIsReadWithItsUnitAndDefaultsToFourGibibytes) {
  EXPECT_EQ(load_suite("smoke").memory_limit_bytes, 4 * kGibibyte);
  const auto path = std::filesystem::temp_directory_path() / "holebench_memory_suite.json";
  std::ofstream(path) << R"({"cases": ["box/*"], "memory_limit": "512M"})";
  EXPECT_EQ(load_suite(path.string()).memory_limit_bytes, 512ull << 20);
  std::ofstream(path) << R"({"cases": ["box/*"], "memory_limit": 0})";
  EXPECT_EQ(load_suite(path.string()).memory_limit_bytes, 0u);
  RunOptions options;
  options.suite = load_suite("smoke");
  EXPECT_EQ(runner_options_of(options).memory_limit_bytes, 4 * kGibibyte);
}

// The workers share the cores: each job's threads times the workers never exceed the cores,
// and a job always has at least one thread.
TEST(Suite, JobsShareTheCoresAmongTheWorkers) {
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  EXPECT_EQ(threads_per_job_of(1), cores);
  EXPECT_EQ(threads_per_job_of(0), 1);  // 0 workers: one per core
  for (int workers = 1; workers <= 2 * cores + 1; ++workers) {
    EXPECT_GE(threads_per_job_of(workers), 1) << workers;
    if (workers <= cores)
      EXPECT_LE(threads_per_job_of(workers) * workers, cores) << workers;
  }
}

}  // namespace
}  // namespace holebench::harness
