// Baseline comparison on hand-written fixture files (tests/harness/fixtures/):
// base.json against new_regressed.json and new_improved.json, plus one-metric cases built in
// code for zero handling, direction and tolerances. Expected verdicts follow from the rule
// in docs/reports.md: a regression is a move the bad way by more than
// max(absolute, relative * |old|).
#include "harness/results/compare.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace holebench::harness {
namespace {

const std::filesystem::path kFixtures =
    std::filesystem::path(HOLEBENCH_SOURCE_DIR) / "tests" / "harness" / "fixtures";

ResultsData fixture(const std::string& name) {
  return read_results_json(kFixtures / name);
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The tolerances of suites/smoke.json: 5 % or 1e-6 by default, lower is better; the
/// classification fraction higher is better with no relative slack; times ignored.
Tolerances smoke_tolerances() {
  Tolerances t;
  t.default_tolerance = {true, 0.05, 1e-6};
  t.metrics["classification_all_correct_fraction"] = {false, 0.0, 1e-9};
  return t;
}

const JobComparison& job(const Comparison& c, const std::string& id) {
  const auto it = std::find_if(c.jobs.begin(), c.jobs.end(),
                               [&](const JobComparison& j) { return j.job_id == id; });
  if (it == c.jobs.end())
    throw std::runtime_error("no job " + id);
  return *it;
}

const MetricChange& metric(const JobComparison& j, const std::string& name) {
  const auto it = std::find_if(j.metrics.begin(), j.metrics.end(),
                               [&](const MetricChange& m) { return m.metric == name; });
  if (it == j.metrics.end())
    throw std::runtime_error("no metric " + name);
  return *it;
}

/// One job with one metric on each side.
MetricChange one_metric(double old_value, double new_value, const Tolerances& tolerances,
                        const std::string& name = "hausdorff_rel_diag") {
  JobRecord record;
  record.job = {"box/corner", "liepa_cgal", 0.0, 0};
  ResultsData base, now;
  record.metrics = {{name, old_value}};
  base.records = {record};
  record.metrics = {{name, new_value}};
  now.records = {record};
  const auto c = compare_results(base, now, tolerances);
  return c.jobs.at(0).metrics.at(0);
}

const std::string kCornerLiepa = "box/corner|liepa_cgal|no_user|0|0";
const std::string kEdgeLiepa = "box/edge|liepa_cgal|no_user|0|0";
const std::string kCornerGuidance = "box/corner|brep_guidance|no_user|0|0";
const std::string kFaceGuidance = "box/face_interior|brep_guidance|no_user|0|0";
const std::string kEdgeCrest = "box/edge|crest_feature|no_user|0|0";
const std::string kCornerSlice = "box/corner|slice_loft|no_user|0|0";

TEST(Compare, ZeroToZeroIsUnchangedWithRelativeChangeZero) {
  const auto m = one_metric(0.0, 0.0, smoke_tolerances());
  EXPECT_EQ(m.verdict, MetricVerdict::Unchanged);
  EXPECT_EQ(m.change, 0.0);
  EXPECT_EQ(m.relative_change, 0.0);
  EXPECT_FALSE(m.from_zero);
}

TEST(Compare, FromZeroIsInfiniteRelativeAndJudgedByTheAbsoluteTolerance) {
  const auto tolerances = smoke_tolerances();  // absolute 1e-6
  const auto small = one_metric(0.0, 5e-7, tolerances);
  EXPECT_TRUE(small.from_zero);
  EXPECT_TRUE(std::isinf(small.relative_change) && small.relative_change > 0);
  EXPECT_EQ(small.allowed, 1e-6);
  EXPECT_EQ(small.verdict, MetricVerdict::WithinTolerance);

  const auto large = one_metric(0.0, 2.0, tolerances, "self_intersections_count");
  EXPECT_TRUE(large.from_zero);
  EXPECT_EQ(large.verdict, MetricVerdict::Regressed);

  // Higher is better: falling from 0 to -1 is bad, the relative change is -infinity.
  const auto down = one_metric(0.0, -1.0, tolerances, "classification_all_correct_fraction");
  EXPECT_TRUE(std::isinf(down.relative_change) && down.relative_change < 0);
  EXPECT_EQ(down.verdict, MetricVerdict::Regressed);
}

TEST(Compare, DirectionDecidesWhichWayIsARegression) {
  auto tolerances = smoke_tolerances();
  // Lower is better (default): 0.01 -> 0.02 is worse, 0.02 -> 0.01 better.
  EXPECT_EQ(one_metric(0.01, 0.02, tolerances).verdict, MetricVerdict::Regressed);
  EXPECT_EQ(one_metric(0.02, 0.01, tolerances).verdict, MetricVerdict::Improved);
  // Higher is better: the same moves judged the other way.
  const std::string fraction = "classification_all_correct_fraction";
  EXPECT_EQ(one_metric(0.01, 0.02, tolerances, fraction).verdict, MetricVerdict::Improved);
  EXPECT_EQ(one_metric(0.02, 0.01, tolerances, fraction).verdict, MetricVerdict::Regressed);
}

// The share of holes handled by a stand-in is better lower: more fallbacks is a regression,
// by its name alone (it ends in _fraction, but is no correct-answer or coverage fraction).
TEST(Compare, MoreFallbackHolesIsARegression) {
  const std::string name = "fallback_holes_fraction";
  const Tolerances built_in;
  ASSERT_TRUE(built_in.find(name).has_value());
  EXPECT_TRUE(built_in.find(name)->lower_is_better);
  const auto tolerances = smoke_tolerances();
  EXPECT_EQ(one_metric(0.0, 0.5, tolerances, name).verdict, MetricVerdict::Regressed);
  EXPECT_EQ(one_metric(0.5, 0.0, tolerances, name).verdict, MetricVerdict::Improved);
}

TEST(Compare, ToleranceIsTheLargerOfAbsoluteAndRelativeTimesOld) {
  auto tolerances = smoke_tolerances();  // relative 5 %, absolute 1e-6
  // 1.0 -> 1.04: +4 % <= 5 %; 1.0 -> 1.06: +6 % > 5 %.
  const auto within = one_metric(1.0, 1.04, tolerances);
  EXPECT_EQ(within.verdict, MetricVerdict::WithinTolerance);
  EXPECT_DOUBLE_EQ(within.allowed, 0.05);
  EXPECT_NEAR(within.relative_change, 0.04, 1e-12);
  EXPECT_EQ(one_metric(1.0, 1.06, tolerances).verdict, MetricVerdict::Regressed);
  // old = 1e-6: 5 % of it is 5e-8, the absolute 1e-6 dominates; +9e-7 (+90 %) is allowed.
  const auto tiny = one_metric(1e-6, 1.9e-6, tolerances);
  EXPECT_EQ(tiny.allowed, 1e-6);
  EXPECT_EQ(tiny.verdict, MetricVerdict::WithinTolerance);
  // Ignored metrics are reported, never judged.
  EXPECT_EQ(one_metric(1.0, 100.0, tolerances, "time_method_s").verdict, MetricVerdict::NotJudged);
}

TEST(Compare, RegressedFixture) {
  const auto c =
      compare_results(fixture("base.json"), fixture("new_regressed.json"), smoke_tolerances());
  ASSERT_EQ(c.jobs.size(), 6u);  // 5 in the baseline + 1 new
  EXPECT_TRUE(c.has_regression());
  EXPECT_EQ(c.base_label, "v1.0-base");
  EXPECT_EQ(c.new_label, "v1.1-regressed");

  // 0.01 -> 0.0104 (+4 %) within; 0 -> 2 self-intersections from zero: regression;
  // time 0.5 -> 5 ignored.
  const auto& corner = job(c, kCornerLiepa);
  EXPECT_EQ(metric(corner, "hausdorff_rel_diag").verdict, MetricVerdict::WithinTolerance);
  EXPECT_EQ(metric(corner, "self_intersections_count").verdict, MetricVerdict::Regressed);
  EXPECT_TRUE(metric(corner, "self_intersections_count").from_zero);
  EXPECT_EQ(metric(corner, "time_method_s").verdict, MetricVerdict::NotJudged);
  EXPECT_EQ(metric(corner, "new_faces_count").verdict, MetricVerdict::Unchanged);
  ASSERT_EQ(corner.regressed_metrics().size(), 1u);
  EXPECT_TRUE(corner.regression());

  // ok -> crash: a regression by status (its metrics disappear with it).
  const auto& edge = job(c, kEdgeLiepa);
  EXPECT_TRUE(edge.status_regressed());
  EXPECT_TRUE(edge.regression());
  EXPECT_EQ(metric(edge, "hausdorff_rel_diag").verdict, MetricVerdict::Disappeared);

  // Classification 1 -> 0.5 (higher is better) and Hausdorff +20 %: both regressed.
  const auto& guidance = job(c, kCornerGuidance);
  EXPECT_EQ(guidance.regressed_metrics().size(), 2u);

  // partial -> method_failed: changed, but not from ok: not a regression.
  const auto& face = job(c, kFaceGuidance);
  EXPECT_TRUE(face.status_changed());
  EXPECT_FALSE(face.status_regressed());
  EXPECT_FALSE(face.regression());

  const auto& missing = job(c, kEdgeCrest);
  EXPECT_EQ(missing.presence, JobPresence::Missing);
  EXPECT_TRUE(missing.regression());

  const auto& added = job(c, kCornerSlice);
  EXPECT_EQ(added.presence, JobPresence::New);
  EXPECT_FALSE(added.regression());

  EXPECT_EQ(c.regressed_jobs(), 4u);
}

TEST(Compare, ImprovedFixtureHasNoRegression) {
  const auto c =
      compare_results(fixture("base.json"), fixture("new_improved.json"), smoke_tolerances());
  EXPECT_FALSE(c.has_regression());
  EXPECT_EQ(c.regressed_jobs(), 0u);
  const auto& corner = job(c, kCornerLiepa);
  EXPECT_EQ(metric(corner, "hausdorff_rel_diag").verdict, MetricVerdict::Improved);
  EXPECT_DOUBLE_EQ(metric(corner, "hausdorff_rel_diag").relative_change, -0.5);
  EXPECT_EQ(metric(corner, "hole_mean_distance_rel_diag").verdict,
            MetricVerdict::WithinTolerance);  // +0.5 %
  // The patch's size describes the answer, not its quality: reported, not judged.
  EXPECT_EQ(metric(corner, "new_faces_count").verdict, MetricVerdict::NotJudged);  // -4 %
  EXPECT_EQ(metric(corner, "self_intersections_count").verdict, MetricVerdict::Unchanged);
  // partial -> ok: a status improvement; the new classification metric appears.
  const auto& face = job(c, kFaceGuidance);
  EXPECT_TRUE(face.status_changed());
  EXPECT_FALSE(face.regression());
  EXPECT_EQ(metric(face, "classification_all_correct_fraction").verdict, MetricVerdict::Appeared);
  const auto text = format_comparison(c);
  EXPECT_EQ(text.find("REGRESSION"), std::string::npos) << text;
  EXPECT_NE(text.find(": OK\n"), std::string::npos) << text;
}

TEST(Compare, SameResultsHaveNoChanges) {
  const auto base = fixture("base.json");
  const auto c = compare_results(base, base, smoke_tolerances());
  EXPECT_FALSE(c.has_regression());
  for (const auto& j : c.jobs) {
    for (const auto& m : j.metrics)
      EXPECT_EQ(m.verdict, MetricVerdict::Unchanged) << m.metric;
  }
  EXPECT_NE(format_comparison(c).find("No changes."), std::string::npos);
}

// A job that ran with other settings says so, by method and setting, without being judged;
// a record without settings (written before records named them) says nothing.
TEST(Compare, ChangedMethodSettingsAreListedNotJudged) {
  ResultsData base = fixture("base.json");
  ResultsData now = base;
  ASSERT_FALSE(base.records.empty());
  base.records[0].job.method_options.add("tessellation.direct", false).add("slices", 10);
  now.records[0].job.method_options.add("tessellation.direct", true).add("slices", 10);
  const auto c = compare_results(base, now, smoke_tolerances());
  EXPECT_FALSE(c.has_regression());
  EXPECT_EQ(job(c, base.records[0].job.id()).changed_settings,
            std::vector<std::string>{"tessellation.direct: false -> true"});
  const auto text = format_comparison(c);
  EXPECT_NE(text.find("Method settings differ"), std::string::npos) << text;
  EXPECT_NE(text.find("(1 jobs): tessellation.direct: false -> true"), std::string::npos) << text;
  EXPECT_EQ(text.find("No changes."), std::string::npos) << text;
  EXPECT_NE(text.find(": OK\n"), std::string::npos) << text;

  now.records[0].job.method_options = MethodOptions();
  const auto older = compare_results(base, now, smoke_tolerances());
  EXPECT_TRUE(job(older, base.records[0].job.id()).changed_settings.empty());
  EXPECT_NE(format_comparison(older).find("No changes."), std::string::npos);
}

TEST(Compare, TableListsRegressionsFirstAndEndsWithASummaryLine) {
  const auto c =
      compare_results(fixture("base.json"), fixture("new_regressed.json"), smoke_tolerances());
  const auto text = format_comparison(c);
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  std::vector<std::string> flags;
  for (const auto& line : lines) {
    if (line.rfind("| ", 0) == 0 && line.rfind("| verdict |", 0) != 0 &&
        line.rfind("| --- |", 0) != 0) {
      flags.push_back(line.substr(2, line.find(" |", 2) - 2));
    }
  }
  // 1 status + 1 missing + 3 metric regressions first; then the other status change, the
  // new job and the change within tolerance.
  const std::vector<std::string> expected{"REGRESSION", "REGRESSION",      "REGRESSION",
                                          "REGRESSION", "REGRESSION",      "status changed",
                                          "new job",    "within tolerance"};
  EXPECT_EQ(flags, expected) << text;
  // The job id's '|' is escaped so the Markdown table keeps its columns.
  EXPECT_NE(text.find("box/corner\\|liepa_cgal\\|no_user\\|0\\|0"), std::string::npos);
  EXPECT_EQ(lines.back(),
            "4 jobs compared, 1 missing, 1 new; 4 regressed jobs (1 status, 3 metrics), 0 "
            "improved metrics, 1 changed within tolerance: REGRESSION");
  EXPECT_NE(text.find("new from 0"), std::string::npos);
}

TEST(Compare, OutputIsStableAndIndependentOfRecordOrder) {
  auto base = fixture("base.json");
  auto now = fixture("new_regressed.json");
  const auto text = format_comparison(compare_results(base, now, smoke_tolerances()));
  std::reverse(base.records.begin(), base.records.end());
  std::reverse(now.records.begin(), now.records.end());
  EXPECT_EQ(format_comparison(compare_results(base, now, smoke_tolerances())), text);
  // The reviewed expected output (regenerate by hand when the format changes on purpose).
  EXPECT_EQ(text, read_text(kFixtures / "compare_regressed.expected.md"));
}

TEST(Compare, PrintWritesTheFormattedText) {
  const auto c =
      compare_results(fixture("base.json"), fixture("new_improved.json"), smoke_tolerances());
  const auto path = std::filesystem::temp_directory_path() / "holebench_compare_print.md";
  std::FILE* file = std::fopen(path.c_str(), "wb");
  ASSERT_NE(file, nullptr);
  print_comparison(c, file);
  std::fclose(file);
  EXPECT_EQ(read_text(path), format_comparison(c));
}

// --- JUnit ----------------------------------------------------------------------------------

struct XmlElement {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;
  std::vector<XmlElement> children;
  std::string text;
  std::string attribute(const std::string& key) const {
    for (const auto& [k, v] : attributes) {
      if (k == key)
        return v;
    }
    return "";
  }
};

/// A small strict XML reader for the subset JUnit uses (declaration, elements, attributes
/// in double quotes, text, the five entities and &#N;). Throws on anything malformed.
class XmlReader {
 public:
  explicit XmlReader(std::string text) : s_(std::move(text)) {}

  XmlElement document() {
    skip_space();
    if (s_.compare(i_, 5, "<?xml") == 0)
      i_ = s_.find("?>", i_) + 2;
    skip_space();
    XmlElement root = element();
    skip_space();
    if (i_ != s_.size())
      fail("content after the root element");
    return root;
  }

 private:
  [[noreturn]] void fail(const std::string& what) {
    throw std::runtime_error("XML: " + what + " at " + std::to_string(i_));
  }
  void skip_space() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_])))
      ++i_;
  }
  std::string name() {
    const auto start = i_;
    while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '-' ||
                              s_[i_] == '_' || s_[i_] == ':'))
      ++i_;
    if (start == i_)
      fail("expected a name");
    return s_.substr(start, i_ - start);
  }
  std::string decode(const std::string& raw) {
    std::string out;
    for (std::size_t k = 0; k < raw.size(); ++k) {
      if (raw[k] == '<')
        fail("raw '<' in text");
      if (raw[k] != '&') {
        out += raw[k];
        continue;
      }
      const auto end = raw.find(';', k);
      if (end == std::string::npos)
        fail("unterminated entity");
      const auto entity = raw.substr(k + 1, end - k - 1);
      if (entity == "amp")
        out += '&';
      else if (entity == "lt")
        out += '<';
      else if (entity == "gt")
        out += '>';
      else if (entity == "quot")
        out += '"';
      else if (entity == "apos")
        out += '\'';
      else if (entity.size() > 1 && entity[0] == '#')
        out += static_cast<char>(std::stoi(entity.substr(1)));
      else
        fail("unknown entity &" + entity + ";");
      k = end;
    }
    return out;
  }
  XmlElement element() {
    if (s_[i_] != '<')
      fail("expected '<'");
    ++i_;
    XmlElement e;
    e.name = name();
    for (;;) {
      skip_space();
      if (s_.compare(i_, 2, "/>") == 0) {
        i_ += 2;
        return e;
      }
      if (s_[i_] == '>') {
        ++i_;
        break;
      }
      const auto key = name();
      if (s_.compare(i_, 2, "=\"") != 0)
        fail("expected =\"");
      i_ += 2;
      const auto end = s_.find('"', i_);
      if (end == std::string::npos)
        fail("unterminated attribute");
      for (const auto& [k, v] : e.attributes) {
        if (k == key)
          fail("duplicate attribute " + key);
      }
      e.attributes.emplace_back(key, decode(s_.substr(i_, end - i_)));
      i_ = end + 1;
    }
    for (;;) {
      const auto next = s_.find('<', i_);
      if (next == std::string::npos)
        fail("unclosed <" + e.name + ">");
      e.text += decode(s_.substr(i_, next - i_));
      i_ = next;
      if (s_.compare(i_, 2, "</") == 0) {
        i_ += 2;
        if (name() != e.name)
          fail("mismatched closing tag for " + e.name);
        if (s_[i_] != '>')
          fail("expected '>'");
        ++i_;
        return e;
      }
      e.children.push_back(element());
    }
  }

  std::string s_;
  std::size_t i_ = 0;
};

TEST(Compare, JUnitIsWellFormedWithOneTestcasePerJobAndAFailurePerRegression) {
  auto base = fixture("base.json");
  auto now = fixture("new_regressed.json");
  // A missing job whose id needs escaping.
  JobRecord odd = base.records.front();
  odd.job.case_id = "odd/<&\"'>";
  base.records.push_back(odd);
  const auto c = compare_results(base, now, smoke_tolerances());
  const auto path = std::filesystem::temp_directory_path() / "holebench_compare_junit.xml";
  write_junit_xml(c, path);
  const auto text = read_text(path);
  XmlElement root;
  ASSERT_NO_THROW(root = XmlReader(text).document()) << text;

  EXPECT_EQ(root.name, "testsuites");
  EXPECT_EQ(root.attribute("tests"), "7");
  EXPECT_EQ(root.attribute("failures"), "5");
  std::size_t testcases = 0, failures = 0;
  bool odd_seen = false;
  for (const auto& suite : root.children) {
    ASSERT_EQ(suite.name, "testsuite");
    std::size_t suite_failures = 0;
    for (const auto& testcase : suite.children) {
      ASSERT_EQ(testcase.name, "testcase");
      EXPECT_EQ(testcase.attribute("classname"), suite.attribute("name"));
      ++testcases;
      for (const auto& child : testcase.children) {
        if (child.name == "failure")
          ++suite_failures;
      }
      if (testcase.attribute("name") == "odd/<&\"'>|liepa_cgal|no_user|0|0")
        odd_seen = true;
      if (testcase.attribute("name") == kCornerGuidance) {
        // Its failure lists both regressed metrics.
        ASSERT_EQ(testcase.children.size(), 1u);
        const auto& failure = testcase.children[0];
        EXPECT_NE(failure.text.find("classification_all_correct_fraction: 1 -> 0.5"),
                  std::string::npos)
            << failure.text;
        EXPECT_NE(failure.text.find("hausdorff_rel_diag: 0.05 -> 0.06"), std::string::npos);
        EXPECT_EQ(failure.attribute("message"), "2 regressed metrics");
      }
    }
    EXPECT_EQ(suite.attribute("failures"), std::to_string(suite_failures));
    failures += suite_failures;
  }
  EXPECT_EQ(testcases, 7u);
  EXPECT_EQ(failures, 5u);
  EXPECT_TRUE(odd_seen);
  // Sorted by method: brep_guidance, crest_feature, liepa_cgal, slice_loft.
  ASSERT_EQ(root.children.size(), 4u);
  EXPECT_EQ(root.children[0].attribute("name"), "brep_guidance");
  EXPECT_EQ(root.children[3].attribute("name"), "slice_loft");
}

}  // namespace
}  // namespace holebench::harness
