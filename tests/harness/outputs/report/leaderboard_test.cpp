// The leaderboard (harness/outputs/report/leaderboard.h) on records made here, with every
// expected number worked out by hand in the comments.
#include "harness/outputs/report/leaderboard.h"

#include "harness/outputs/report/report.h"

#include "tests/harness/text_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace holebench::harness::report {
namespace {

/// A record of `method` on `case_id` (family "box", kind `kind`) with hole Hausdorff
/// interval [hausdorff, hausdorff + width] and one hole.
JobRecord record(const std::string& method, const std::string& case_id, const std::string& kind,
                 double hausdorff, double width = 1e-4) {
  JobRecord r;
  r.job.case_id = case_id;
  r.job.method_id = method;
  r.case_family = "box";
  r.case_kind = kind;
  r.metrics = {{"hole_hausdorff_rel_diag", hausdorff},
               {"hole_hausdorff_upper_rel_diag", hausdorff + width}};
  HoleRecord hole;
  hole.closed = true;
  r.holes = {hole};
  r.method_seconds = 1.0;
  return r;
}

const LeaderboardEntry& entry(const LeaderboardGroup& group, const std::string& method) {
  for (const auto& e : group.entries) {
    if (e.method == method)
      return e;
  }
  throw std::runtime_error("no entry " + method);
}

std::size_t column(const std::string& key) {
  const auto& columns = leaderboard_columns();
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (columns[c].key == key)
      return c;
  }
  throw std::runtime_error("no column " + key);
}

// Method "a" and "b" on four edge cases and two corner cases.
//   edge:   a = 0.125, 0.25, 0.375, 0.5   b = 0.625, 0.75, 0.875, 1   (a wholly below)
//   corner: a = 0.5, 0.75                 b = 0.5625, 0.125
// (binary fractions: the differences are exact). Corner 1: [0.5, 0.5001] vs [0.5625,
// 0.5626]: a better; corner 2: a worse. So over the family a is better on 5 of 6 jobs:
// differences -0.5 (x4), -0.0625, +0.625 with ranks 1 (0.0625), 2..5 for the four 0.5s
// (midrank 3.5), 6 (0.625): W+ = 6, W- = 15; exactly over 64 sign
// patterns of ranks {1, 3.5, 3.5, 3.5, 3.5, 6}: P(W+ <= 6) = #{subsets with sum <= 6} / 64 =
// (1 empty + 1 {1} + 4 {3.5} + 4 {1, 3.5} + 1 {6}) / 64 = 11/64, p = 22/64 = 0.34375.
ResultsData two_methods() {
  ResultsData data;
  const double a_edge[] = {0.125, 0.25, 0.375, 0.5}, b_edge[] = {0.625, 0.75, 0.875, 1.0};
  for (int i = 0; i < 4; ++i) {
    const std::string id = "box/edge/" + std::to_string(i);
    data.records.push_back(record("a", id, "edge", a_edge[i]));
    data.records.push_back(record("b", id, "edge", b_edge[i]));
  }
  data.records.push_back(record("a", "box/corner/0", "corner", 0.5));
  data.records.push_back(record("b", "box/corner/0", "corner", 0.5625));
  data.records.push_back(record("a", "box/corner/1", "corner", 0.75));
  data.records.push_back(record("b", "box/corner/1", "corner", 0.125));
  return data;
}

TEST(Leaderboard, GroupsAreFamiliesThenTheirKinds) {
  const auto board = compute_leaderboard(two_methods());
  ASSERT_EQ(board.groups.size(), 3u);
  EXPECT_TRUE(board.groups[0].is_family());
  EXPECT_EQ(board.groups[0].family, "box");
  EXPECT_EQ(board.groups[1].kind, "corner");
  EXPECT_EQ(board.groups[2].kind, "edge");
  EXPECT_EQ(entry(board.groups[0], "a").jobs, 6u);
  EXPECT_EQ(entry(board.groups[2], "b").jobs, 4u);
}

TEST(Leaderboard, MediansAndBestMarks) {
  const auto board = compute_leaderboard(two_methods());
  const auto h = column("hole_hausdorff_rel_diag_median");
  const auto& family = board.groups[0];
  // a: .125 .25 .375 .5 .5 .75 -> (.375 + .5) / 2; b: .125 .5625 .625 .75 .875 1 -> .6875.
  EXPECT_EQ(*entry(family, "a").values[h], 0.4375);
  EXPECT_EQ(*entry(family, "b").values[h], 0.6875);
  EXPECT_TRUE(entry(family, "a").best[h]);
  EXPECT_FALSE(entry(family, "b").best[h]);
  // Corner: a 0.625, b 0.34375: b is best there.
  EXPECT_TRUE(entry(board.groups[1], "b").best[h]);
  // No new-vertex error anywhere: no value, nothing marked.
  const auto nv = column("new_vertex_mean_error_rel_diag_median");
  EXPECT_FALSE(entry(family, "a").values[nv]);
  EXPECT_FALSE(entry(family, "a").best[nv]);
  // Equal times: both best.
  const auto t = column("method_seconds_median");
  EXPECT_TRUE(entry(family, "a").best[t]);
  EXPECT_TRUE(entry(family, "b").best[t]);
}

TEST(Leaderboard, SuccessNeedsOkAndEveryHoleClosedAndFallbackCountsHoles) {
  auto data = two_methods();
  // b: one job partial, one ok with an open hole, one with a second hole a stand-in closed.
  data.records[1].status = JobStatus::Partial;
  data.records[3].holes[0].closed = false;
  HoleRecord stand_in;
  stand_in.closed = true;
  stand_in.fallback = "liepa";
  data.records[5].holes.push_back(stand_in);
  data.records[7].status = JobStatus::Crash;  // b on edge/3: no method time
  data.records[7].method_seconds = 0.0;
  const auto board = compute_leaderboard(data);
  const auto& b = entry(board.groups[0], "b");
  EXPECT_EQ(b.successes, 3u);  // 6 jobs - partial - open hole - crash
  EXPECT_DOUBLE_EQ(*b.values[column("success_share")], 0.5);
  EXPECT_EQ(b.holes, 7u);
  EXPECT_EQ(b.fallback_holes, 1u);
  EXPECT_DOUBLE_EQ(*b.values[column("fallback_share")], 1.0 / 7.0);
  EXPECT_TRUE(entry(board.groups[0], "a").best[column("success_share")]);
  EXPECT_TRUE(entry(board.groups[0], "a").best[column("fallback_share")]);
  EXPECT_EQ(*b.values[column("method_seconds_median")], 1.0);  // the crash is left out
}

// a: valid 1, 1, 0, 0 (all ok and closed): valid 0.5, closed but invalid 0.5. b: a crash (no
// metrics: not valid) and three valid: 0.75 and 0. g guides: its holes are open with an
// arrow, so its first column is the mean decision measure over (1, 0.5, a crash's 0), the ok
// job without the metric left out: 0.5, marked and not ranked.
TEST(Leaderboard, ValidShareClosedButInvalidAndTheDecisionMeasure) {
  ResultsData data;
  const double a_valid[] = {1, 1, 0, 0};
  for (int i = 0; i < 4; ++i) {
    auto r = record("a", "box/edge/" + std::to_string(i), "edge", 0.1);
    r.metrics.push_back({"valid_repair_ok", a_valid[i]});
    data.records.push_back(r);
    auto b = record("b", "box/edge/" + std::to_string(i), "edge", 0.1);
    b.metrics.push_back({"valid_repair_ok", 1.0});
    if (i == 0) {
      b.status = JobStatus::Crash;
      b.metrics.clear();
    }
    data.records.push_back(b);
    auto g = record("g", "box/edge/" + std::to_string(i), "edge", 0.1);
    g.holes[0].closed = false;
    g.holes[0].arrow = GuidanceArrow{};
    const double handled[] = {1.0, 0.5, -1.0, -1.0};
    if (handled[i] >= 0.0)
      g.metrics.push_back({"decision_handled_fraction", handled[i]});
    if (i == 2) {
      g.status = JobStatus::Crash;
      g.metrics.clear();
    }
    data.records.push_back(g);
  }
  EXPECT_EQ(methods_that_guide(data), (std::set<std::string>{"g"}));
  const auto board = compute_leaderboard(data);
  const auto valid = column("valid_share"), invalid = column("closed_invalid_share");
  const auto& family = board.groups[0];
  EXPECT_DOUBLE_EQ(*entry(family, "a").values[valid], 0.5);
  EXPECT_DOUBLE_EQ(*entry(family, "a").values[invalid], 0.5);
  EXPECT_DOUBLE_EQ(*entry(family, "b").values[valid], 0.75);
  EXPECT_DOUBLE_EQ(*entry(family, "b").values[invalid], 0.0);
  const auto& g = entry(family, "g");
  EXPECT_TRUE(g.judged_by_decision);
  EXPECT_DOUBLE_EQ(*g.values[valid], 0.5);
  EXPECT_EQ(leaderboard_entry_cell(g, valid), "0.5 (decision)");
  EXPECT_EQ(leaderboard_entry_cell(entry(family, "a"), valid), "0.5");
  EXPECT_TRUE(entry(family, "b").best[valid]);
  EXPECT_FALSE(g.best[valid]);
  EXPECT_FALSE(entry(family, "a").best[valid]);
}

TEST(Leaderboard, PairsCountWinsTiesLossesWithinTheBounds) {
  auto data = two_methods();
  const auto board = compute_leaderboard(data);
  ASSERT_EQ(board.groups[0].pairs.size(), 1u);
  const auto& pair = board.groups[0].pairs[0];
  EXPECT_EQ(pair.first, "a");
  EXPECT_EQ(pair.second, "b");
  EXPECT_EQ(pair.shared_jobs, 6u);
  EXPECT_EQ(pair.pairs, 6u);
  EXPECT_EQ(pair.comparison.wins, 5u);
  EXPECT_EQ(pair.comparison.losses, 1u);
  EXPECT_EQ(pair.comparison.ties, 0u);
  EXPECT_DOUBLE_EQ(pair.comparison.test.p_value, 22.0 / 64.0);
  EXPECT_EQ(pair.better, "");  // not significant at 0.05
  // Edge alone: 4 wins of 4, p = 2/16 = 0.125 (exact).
  EXPECT_DOUBLE_EQ(board.groups[2].pairs[0].comparison.test.p_value, 0.125);

  // Wide bounds make corner 1 a tie: [0.5, 0.6] overlaps [0.5625, 0.5626].
  data.records[8].metrics[1].value = 0.6;
  const auto wide = compute_leaderboard(data);
  const auto& corner = wide.groups[1].pairs[0];
  EXPECT_EQ(corner.comparison.wins, 0u);
  EXPECT_EQ(corner.comparison.ties, 1u);
  EXPECT_EQ(corner.comparison.losses, 1u);
}

TEST(Leaderboard, ASignificantPairNamesTheBetterMethod) {
  // Six edge cases, a better on each: p = 2/64 = 0.03125 < 0.05.
  ResultsData data;
  for (int i = 0; i < 6; ++i) {
    const std::string id = "box/edge/" + std::to_string(i);
    data.records.push_back(record("b", id, "edge", 0.5 + 0.01 * i));
    data.records.push_back(record("a", id, "edge", 0.1 * i));
  }
  data.records.push_back(record("a", "box/edge/only_a", "edge", 0.0));  // not shared
  const auto board = compute_leaderboard(data);
  const auto& pair = board.groups[0].pairs[0];
  EXPECT_EQ(pair.shared_jobs, 6u);
  EXPECT_DOUBLE_EQ(pair.comparison.test.p_value, 0.03125);
  EXPECT_EQ(pair.better, "a");
}

using test_support::read_text;

TEST(Leaderboard, ReportWritesItFirstAndAsMarkdownAndLatex) {
  const auto dir = std::filesystem::temp_directory_path() / "holebench_leaderboard_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  ReportOptions options;
  options.python.clear();
  options.warnings_to_stderr = false;
  write_report(two_methods(), dir, options);
  const auto html = read_text(dir / "report" / "report.html");
  const auto leaderboard = html.find("id=\"leaderboard\"");
  ASSERT_NE(leaderboard, std::string::npos);
  EXPECT_LT(leaderboard, html.find("<table"));  // before every other table
  EXPECT_LT(html.find("id=\"paired\""), html.find("Summary: method"));
  const auto md = read_text(dir / "report" / "leaderboard.md");
  // The family row of a: no valid share (records without valid_repair_ok, as written before
  // it existed), success 1, no fallback or defect, time 1 (each tied with b: both bold), hole
  // Hausdorff 0.4375 to 3 digits (best, bold), no literature metrics, new-vertex error or
  // coverage.
  EXPECT_NE(md.find("| all | a | 6 | - | - | **1** | **0** | **0** | **0.438** | - | - | - | - | - "
                    "| **1** |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| box | edge | a | b | 4 | 4 | 4 | 0 | 0 | 0.12 | - |"), std::string::npos)
      << md;
  const auto tex = read_text(dir / "report" / "leaderboard.tex");
  EXPECT_NE(tex.find("\\textbf{0.438}"), std::string::npos);
  EXPECT_NE(tex.find("\\bottomrule"), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace holebench::harness::report
