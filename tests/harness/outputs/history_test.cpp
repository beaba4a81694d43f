// `holebench history` (harness/outputs/history.h) on three results files made from the smoke
// baseline: two unchanged runs, then one in which liepa_cgal's hole Hausdorff distance grew
// by 0.05 of the diagonal on every job. The smoke suite's tolerance for it is 2e-4 (absolute),
// so `compare` flags every such job of the third run, and only those: the history must mark
// liepa_cgal at run 3 and nothing else.
#include "harness/outputs/history.h"

#include "harness/results/results_file.h"
#include "harness/run/suite.h"

#include "tests/harness/text_file.h"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace holebench::harness {
namespace {

const std::filesystem::path kSmoke =
    std::filesystem::path(HOLEBENCH_SOURCE_DIR) / "results" / "baselines" / "smoke.json";
const std::string kChanged = "liepa_cgal";

using test_support::read_text;

std::size_t count_of(const std::string& text, const std::string& needle) {
  std::size_t count = 0;
  for (auto at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1))
    ++count;
  return count;
}

/// Run `night` (1, 2, 3) of the smoke baseline, dated 2026-11-0<night>; the third with
/// kChanged's hole Hausdorff interval moved up by 0.05. `changed_jobs` counts the jobs moved.
ResultsData night(int night, std::size_t* changed_jobs = nullptr) {
  ResultsData data = read_results_json(kSmoke);
  data.context.created_utc = "2026-11-0" + std::to_string(night) + "T03:00:00Z";
  data.context.code_version = "v" + std::to_string(night);
  data.context.suite = "smoke";
  std::size_t changed = 0;
  if (night == 3) {
    for (auto& record : data.records) {
      if (record.job.method_id != kChanged)
        continue;
      bool moved = false;
      for (auto& metric : record.metrics) {
        if (metric.name == "hole_hausdorff_rel_diag" ||
            metric.name == "hole_hausdorff_upper_rel_diag") {
          metric.value += 0.05;
          moved = true;
        }
      }
      changed += moved ? 1 : 0;
    }
  }
  if (changed_jobs)
    *changed_jobs = changed;
  return data;
}

std::size_t method_index(const History& history, const std::string& method) {
  const auto it = std::find(history.methods.begin(), history.methods.end(), method);
  EXPECT_NE(it, history.methods.end()) << method;
  return static_cast<std::size_t>(it - history.methods.begin());
}

TEST(History, MarksTheRegressionOfTheChangedMethodOnly) {
  std::size_t changed = 0;
  // Given out of order: the history orders them by date.
  std::vector<HistoryRun> runs{{"c", night(3, &changed)}, {"a", night(1)}, {"b", night(2)}};
  ASSERT_GT(changed, 0u);
  HistoryOptions options;  // as the command line judges: each run by the suite it names
  options.tolerances_of_suite = [](const std::string& named_suite, bool* used_defaults) {
    return comparison_tolerances("", named_suite, used_defaults);
  };
  const auto history = compute_history(std::move(runs), options);
  ASSERT_EQ(history.runs.size(), 3u);
  EXPECT_EQ(history.runs[0].name, "a");
  EXPECT_EQ(history.runs[2].name, "c");
  EXPECT_EQ(history.runs[2].label(), "2026-11-03 v3");
  EXPECT_TRUE(history.notes.empty());  // the smoke suite's tolerances judged

  const std::size_t k = method_index(history, kChanged);
  for (std::size_t m = 0; m < history.methods.size(); ++m) {
    for (std::size_t r = 0; r < 3; ++r) {
      const bool expected = m == k && r == 2;
      EXPECT_EQ(history.regressions[m][r].empty(), !expected)
          << history.methods[m] << " run " << r + 1;
    }
  }
  EXPECT_EQ(history.regressions[k][2].size(), changed);

  // The median hole Hausdorff distance (first headline metric) moved up by the change; the
  // success share did not move.
  ASSERT_EQ(history_metrics()[0].key, "hole_hausdorff_rel_diag_median");
  ASSERT_TRUE(history.values[0][k][0] && history.values[0][k][2]);
  EXPECT_NEAR(*history.values[0][k][2] - *history.values[0][k][0], 0.05, 1e-12);
  const auto& metrics = history_metrics();
  const auto success = static_cast<std::size_t>(
      std::find_if(metrics.begin(), metrics.end(),
                   [](const HistoryMetric& m) { return m.key == "success_share"; }) -
      metrics.begin());
  ASSERT_LT(success, metrics.size());
  EXPECT_EQ(history.values[success][k][0], history.values[success][k][2]);
}

TEST(History, TheCommandWritesThePageWithTheMarks) {
  const auto dir = std::filesystem::temp_directory_path() / "holebench_history_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  for (int n = 1; n <= 3; ++n) {
    const auto data = night(n);
    write_results_json(dir / ("night" + std::to_string(n) + ".json"), data.context, data.records);
  }
  const std::string command =
      std::string(HOLEBENCH_BINARY) + " history " + (dir / "night3.json").string() + " " +
      (dir / "night1.json").string() + " " + (dir / "night2.json").string() + " --out " +
      (dir / "out").string() + " > " + (dir / "log").string() + " 2>&1";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  ASSERT_EQ(WEXITSTATUS(status), 0) << read_text(dir / "log");
  const auto html = read_text(dir / "out" / "history.html");
  // One mark per chart (five headline metrics), all on the changed method at run 3.
  EXPECT_EQ(count_of(html, "class=\"regression\""), 5u) << html;
  EXPECT_EQ(count_of(html, "class=\"regression\" data-method=\"liepa_cgal\" data-run=\"3\""), 5u);
  EXPECT_EQ(count_of(html, "<svg"), 5u);

  // A missing file and a file that is not a results file: exit code 2, one line naming it.
  const auto fails_with = [&](const std::filesystem::path& file, const std::string& words) {
    const std::string bad = std::string(HOLEBENCH_BINARY) + " history " + file.string() +
                            " --out " + (dir / "bad").string() + " > " +
                            (dir / "bad.log").string() + " 2>&1";
    const int code = std::system(bad.c_str());
    EXPECT_TRUE(WIFEXITED(code) && WEXITSTATUS(code) == 2) << file;
    const auto log = read_text(dir / "bad.log");
    EXPECT_EQ(count_of(log, "\n"), 1u) << log;
    EXPECT_NE(log.find(file.string()), std::string::npos) << log;
    EXPECT_NE(log.find(words), std::string::npos) << log;
  };
  fails_with(dir / "missing.json", "cannot open");
  std::ofstream(dir / "not_results.json") << "{\"context\": {}}\n";
  fails_with(dir / "not_results.json", "not a holebench results file");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace holebench::harness
