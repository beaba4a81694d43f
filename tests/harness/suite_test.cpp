#include "harness/suite.h"

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
  const MetricTolerance* correct = suite.tolerances.find("classification_all_correct_fraction");
  ASSERT_NE(correct, nullptr);
  EXPECT_FALSE(correct->lower_is_better);
  const MetricTolerance* other = suite.tolerances.find("hausdorff_rel_diag");
  ASSERT_NE(other, nullptr);
  EXPECT_TRUE(other->lower_is_better);
  EXPECT_EQ(suite.tolerances.find("time_method_s"), nullptr);
}

TEST(Suite, BadSuitesAreClearErrors) {
  EXPECT_THROW(load_suite("no_such_suite"), InvalidInputError);
  const auto path = std::filesystem::temp_directory_path() / "holebench_bad_suite.json";
  std::ofstream(path) << "{\"cases\": []}";
  try {
    load_suite(path.string());
    FAIL() << "an empty case list must be rejected";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("cases"), std::string::npos);
  }
  std::ofstream(path) << "{not json";
  EXPECT_THROW(load_suite(path.string()), InvalidInputError);
  std::ofstream(path) << "{\"cases\": [\"box/*\"], \"method_repetitions\": 0}";
  try {
    load_suite(path.string());
    FAIL() << "zero method repetitions must be rejected";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("method_repetitions"), std::string::npos);
  }
  std::ofstream(path) << "{\"cases\": [\"box/*\"], \"method_repetitions\": 5}";
  EXPECT_EQ(load_suite(path.string()).method_repetitions, 5);
}

}  // namespace
}  // namespace holebench::harness
