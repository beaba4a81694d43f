// `holebench report` on the hand-written fixture tests/harness/fixtures/report_results.json:
//
// | method        | case kind         | jobs | ok | holes (fallback) | hausdorff_rel_diag values |
// time_method_s | | brep_guidance | box/face_interior | 3    | 2  | 3 (1)            | 0, 0.001,
// 0.1             | .5, .6, .7    | | brep_guidance | brep/k3/inner     | 1    | 0  | 0 | - | - |
// | liepa_cgal    | box/face_interior | 4    | 4  | 4 (0)            | .125, .25, .375, .875     |
// 1, 1.5, 2, 2  | | liepa_cgal    | brep/k3/inner     | 2    | 1  | 0                | 0.2 | 3 |
//
// Fallback share: 1 of the 3 holes of brep_guidance x box/face_interior (the partial job's,
// guided instead of closed) = 0.333; 0 of 4 for liepa_cgal; none without holes.
//
// Quantiles interpolate linearly at p * (n - 1) in the sorted values. For liepa_cgal x
// box/face_interior, Hausdorff: median = (0.25 + 0.375) / 2 = 0.3125; q1 at 0.75 =
// 0.125 + 0.75 * 0.125 = 0.21875; q3 at 2.25 = 0.375 + 0.25 * 0.5 = 0.5; IQR 0.28125 >
// 0.5 * 0.3125: flagged "spread". Time: median 1.75, q1 1.375, q3 2, IQR 0.625 (not
// flagged). new_vertex_mean_error_rel_diag is in 2 of its 4 jobs (0.001, 0.003): flagged
// "few" (< 3 values). brep_guidance x box/face_interior, Hausdorff median 0.001,
// classification 0.5, 1, 1: median 1.
#include "harness/outputs/report/report.h"

#include "tests/harness/text_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace holebench::harness::report {
namespace {

const std::filesystem::path kFixture = std::filesystem::path(HOLEBENCH_SOURCE_DIR) / "tests" /
                                       "harness" / "fixtures" / "report_results.json";

using test_support::read_text;

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

ReportOptions no_plots() {
  ReportOptions options;
  options.python.clear();
  options.warnings_to_stderr = false;
  return options;
}

bool matplotlib_available() {
  return std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") == 0;
}

TEST(Report, StatsInterpolateQuantilesLinearly) {
  const auto s = compute_stats({0.875, 0.125, 0.375, 0.25});
  ASSERT_TRUE(s);
  EXPECT_EQ(s->n, 4u);
  EXPECT_EQ(s->median, 0.3125);
  EXPECT_EQ(s->q1, 0.21875);
  EXPECT_EQ(s->q3, 0.5);
  EXPECT_EQ(s->min, 0.125);
  EXPECT_EQ(s->max, 0.875);
  EXPECT_FALSE(compute_stats({}));
  const auto one = compute_stats({2.0});
  EXPECT_EQ(one->median, 2.0);
  EXPECT_EQ(one->iqr(), 0.0);
}

TEST(Report, SummaryRowsHaveTheHandComputedMediansAndFlags) {
  const auto table = summarize(read_results_json(kFixture));
  ASSERT_EQ(table.metrics, summary_metrics());  // every column is present in the fixture
  ASSERT_EQ(table.rows.size(), 4u);
  EXPECT_EQ(table.rows[0].method, "brep_guidance");
  EXPECT_EQ(table.rows[1].case_kind, "brep/k3/inner");
  const auto& liepa = table.rows[2];
  EXPECT_EQ(liepa.method, "liepa_cgal");
  EXPECT_EQ(liepa.case_kind, "box/face_interior");
  EXPECT_EQ(liepa.jobs, 4u);
  EXPECT_EQ(liepa.ok, 4u);
  EXPECT_EQ(liepa.holes, 4u);
  EXPECT_EQ(liepa.fallback_share(), 0.0);
  EXPECT_EQ(liepa.stats[0]->median, 0.3125);
  EXPECT_EQ(liepa.stats[4]->median, 1.75);
  EXPECT_EQ(liepa.stats[4]->iqr(), 0.625);
  EXPECT_FALSE(liepa.stats[3]);  // no classification for liepa_cgal
  EXPECT_EQ(liepa.note(),
            "few: new_vertex_mean_error_rel_diag; spread: hausdorff_rel_diag, "
            "hole_mean_distance_rel_diag");
  const auto& guidance = table.rows[0];
  EXPECT_EQ(guidance.jobs, 3u);
  EXPECT_EQ(guidance.ok, 2u);  // the partial job is not ok
  EXPECT_EQ(guidance.holes, 3u);
  EXPECT_EQ(guidance.fallback_holes, 1u);
  EXPECT_EQ(guidance.fallback_share(), 1.0 / 3.0);
  EXPECT_FALSE(table.rows[1].fallback_share());  // no hole reported
  EXPECT_EQ(guidance.stats[0]->median, 0.001);
  EXPECT_EQ(guidance.stats[3]->median, 1.0);
  EXPECT_FALSE(table.rows[1].flagged());        // no values at all: nothing to flag
  EXPECT_EQ(table.rows[3].note(), "few: n=1");  // every column of liepa_cgal x brep has 1 value
}

TEST(Report, WritesEveryFileWithTheRightNumbers) {
  const auto dir = fresh_dir("holebench_report_files");
  const auto data = read_results_json(kFixture);
  const auto summary = write_report(data, dir, no_plots());
  const auto report = dir / "report";
  EXPECT_EQ(summary.dir, report);
  for (const char* file : {"leaderboard.md", "leaderboard.tex", "summary.md", "summary.csv",
                           "tables.tex", "report.html", "plots/plot_data.json"}) {
    EXPECT_TRUE(std::filesystem::exists(report / file)) << file;
  }
  EXPECT_FALSE(summary.plots_written);
  EXPECT_EQ(summary.rows, 4u);
  EXPECT_EQ(summary.flagged_rows, 3u);

  const auto md = read_text(report / "summary.md");
  EXPECT_EQ(md, console_summary(data, no_plots()));
  EXPECT_NE(md.find("| liepa_cgal | box/face_interior | 4 | 4 | 0 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| - | - | 1.75 | 0.625 | few: new_vertex"), std::string::npos) << md;
  EXPECT_NE(md.find("| brep_guidance | box/face_interior | 3 | 2 | 0.333 | 0.001 |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| brep_guidance | brep/k3/inner | 1 | 0 | - | - | - |"), std::string::npos);

  const auto csv = read_text(report / "summary.csv");
  EXPECT_EQ(csv.rfind("method,case_kind,jobs,ok,holes,fallback_holes,metric,n,median,q1,q3,iqr,"
                      "min,max,note\n",
                      0),
            0u);
  EXPECT_NE(csv.find("liepa_cgal,box/face_interior,4,4,4,0,hausdorff_rel_diag,4,0.3125,0.21875,"
                     "0.5,0.28125,0.125,0.875,\"few: "),
            std::string::npos)
      << csv;
  EXPECT_NE(csv.find("brep_guidance,box/face_interior,3,2,3,1,time_method_s,"), std::string::npos);
  EXPECT_NE(csv.find("brep_guidance,brep/k3/inner,1,0,0,0,time_method_s,0,,,,,,,\n"),
            std::string::npos);

  const auto tex = read_text(report / "tables.tex");
  EXPECT_NE(tex.find("liepa\\_cgal & box/face\\_interior & 4 & 4 & 0 \\\\"), std::string::npos)
      << tex;
  EXPECT_NE(tex.find("& box/face\\_interior & 3 & 2 & 0.333 \\\\"), std::string::npos) << tex;
  EXPECT_NE(tex.find("& brep/k3/inner & 1 & 0 & -- \\\\"), std::string::npos) << tex;
  EXPECT_NE(tex.find("\\texttt{hausdorff\\_rel\\_diag}"), std::string::npos);
  EXPECT_NE(tex.find("0.312"), std::string::npos);
  for (const char* rule : {"\\toprule", "\\midrule", "\\bottomrule"}) {
    EXPECT_NE(tex.find(rule), std::string::npos) << rule;
  }
  for (std::size_t at = tex.find('_'); at != std::string::npos; at = tex.find('_', at + 1)) {
    ASSERT_GT(at, 0u);
    EXPECT_EQ(tex[at - 1], '\\') << "unescaped underscore near: " << tex.substr(at - 20, 40);
  }

  // The plot data: liepa_cgal's Hausdorff at noise 0 is the median of 0.125, 0.25 and 0.2
  // (the brep job), at noise 5 of 0.375 and 0.875 (the crashed job has none).
  const auto plot = nlohmann::json::parse(read_text(report / "plots" / "plot_data.json"));
  EXPECT_EQ(plot["noise_percent"], nlohmann::json::array({0.0, 5.0}));
  EXPECT_EQ(plot["error_vs_noise"]["hausdorff_rel_diag"]["liepa_cgal"],
            nlohmann::json::array({0.2, 0.625}));
  EXPECT_EQ(plot["success_rate"]["liepa_cgal"], nlohmann::json::array({1.0, 0.5}));
  EXPECT_EQ(plot["success_rate"]["brep_guidance"][1], 0.0);
  EXPECT_EQ(plot["time_method_s"]["brep_guidance"], nlohmann::json::array({0.5, 0.6, 0.7}));

  const auto html = read_text(report / "report.html");
  EXPECT_NE(html.find("src=\"../snapshots/box_face_interior_liepa_cgal_no_user_0_0.png\""),
            std::string::npos);
  EXPECT_NE(html.find("No plots: plots were switched off"), std::string::npos);
  EXPECT_EQ(html.find("gallery.html"), std::string::npos);  // there is no gallery
}

TEST(Report, LinksTheCaseGalleryWhenItExists) {
  const auto dir = fresh_dir("holebench_report_gallery");
  std::ofstream(dir / "gallery.html") << "<html></html>\n";
  write_report(read_results_json(kFixture), dir, no_plots());
  EXPECT_NE(read_text(dir / "report" / "report.html").find("href=\"../gallery.html\""),
            std::string::npos);
}

TEST(Report, MissingPythonCostsThePlotsOnly) {
  const auto dir = fresh_dir("holebench_report_nopython");
  auto options = no_plots();
  options.python = "/nonexistent/python3";
  ReportSummary summary;
  ASSERT_NO_THROW(summary = write_report(read_results_json(kFixture), dir, options));
  EXPECT_FALSE(summary.plots_written);
  EXPECT_NE(summary.plots_note.find("/nonexistent/python3"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir / "report" / "report.html"));
  EXPECT_NE(read_text(dir / "report" / "report.html").find("No plots: no Python interpreter"),
            std::string::npos);
}

TEST(Report, SameResultsGiveTheSameBytes) {
  // Two folders, with plots when Debian's Python has matplotlib: every file, PNGs included,
  // is the same bytes.
  const auto data = read_results_json(kFixture);
  ReportOptions options;
  options.warnings_to_stderr = false;
  const auto first = write_report(data, fresh_dir("holebench_report_same_a"), options);
  const auto second = write_report(data, fresh_dir("holebench_report_same_b"), options);
  EXPECT_EQ(first.plots_written, matplotlib_available()) << first.plots_note;
  ASSERT_EQ(first.files, second.files);
  for (const auto& file : first.files) {
    const auto a = read_text(first.dir / file);
    EXPECT_FALSE(a.empty()) << file;
    EXPECT_EQ(a, read_text(second.dir / file)) << file;
  }
  if (first.plots_written) {
    EXPECT_EQ(first.files.size(), 10u);  // 2 leaderboard, 3 summary, HTML, plot data, 3 PNG
    EXPECT_NE(read_text(first.dir / "report.html").find("src=\"plots/error_vs_noise.png\""),
              std::string::npos);
  }
}

}  // namespace
}  // namespace holebench::harness::report
