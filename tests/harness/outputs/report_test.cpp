// `holebench report` on the hand-written fixture tests/harness/fixtures/report_results.json.
// Its records, by row (method x case kind x noise level):
//
//   row  method         case kind          noise  jobs (status)       hausdorff_rel_diag  time
//   0    brep_guidance  box/face_interior  0      2 ok                0, 0.001            .5, .7
//   1    brep_guidance  box/face_interior  5      1 partial           0.1                 .6
//   2    brep_guidance  brep/k3/inner      0      1 method_failed     -                   -
//   3    liepa_cgal     box/face_interior  0      2 ok                .125, .25           1, 1.5
//   4    liepa_cgal     box/face_interior  5      2 ok                .375, .875          2, 2
//   5    liepa_cgal     brep/k3/inner      0      1 ok                0.2                 3
//   6    liepa_cgal     brep/k3/inner      5      1 crash             -                   -
//
// Fallback share: brep_guidance's partial job guided its one hole instead of closing it: 1 of
// 1 in row 1, 0 of 2 in row 0; rows without holes have none. Quantiles interpolate linearly at
// p * (n - 1) in the sorted values: row 3's Hausdorff median (0.125 + 0.25) / 2 = 0.1875, q1
// 0.125 + 0.25 * 0.125 = 0.15625, q3 0.21875; its time median 1.25, IQR 0.25. No row is
// flagged: no column is short because of a job that failed with values missing beside ok
// ones, and no column has three values. The flags are tested on records made in the test.
#include "harness/outputs/report/report.h"

#include "tests/harness/text_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

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

TEST(Report, SummaryRowsHaveTheHandComputedMedians) {
  const auto table = summarize(read_results_json(kFixture));
  ASSERT_EQ(table.metrics, summary_metrics());  // every column is present in the fixture
  ASSERT_EQ(table.rows.size(), 7u);
  EXPECT_EQ(table.rows[0].method, "brep_guidance");
  EXPECT_EQ(table.rows[1].noise_percent, 5.0);
  EXPECT_EQ(table.rows[2].case_kind, "brep/k3/inner");
  const auto& liepa = table.rows[3];
  EXPECT_EQ(liepa.method, "liepa_cgal");
  EXPECT_EQ(liepa.case_kind, "box/face_interior");
  EXPECT_EQ(liepa.noise_percent, 0.0);
  EXPECT_EQ(liepa.jobs, 2u);
  EXPECT_EQ(liepa.ok, 2u);
  EXPECT_EQ(liepa.holes, 2u);
  EXPECT_EQ(liepa.fallback_share(), 0.0);
  EXPECT_EQ(liepa.stats[0]->median, 0.1875);
  EXPECT_EQ(liepa.stats[4]->median, 1.25);
  EXPECT_EQ(liepa.stats[4]->iqr(), 0.25);
  EXPECT_FALSE(liepa.stats[3]);  // no classification for liepa_cgal
  EXPECT_EQ(table.rows[4].stats[0]->median, 0.625);
  const auto& guided = table.rows[1];
  EXPECT_EQ(guided.jobs, 1u);
  EXPECT_EQ(guided.ok, 0u);  // the partial job is not ok
  EXPECT_EQ(guided.holes, 1u);
  EXPECT_EQ(guided.fallback_holes, 1u);
  EXPECT_EQ(guided.fallback_share(), 1.0);
  EXPECT_EQ(table.rows[0].fallback_share(), 0.0);
  EXPECT_FALSE(table.rows[2].fallback_share());  // no hole reported
  EXPECT_EQ(table.rows[0].stats[0]->median, 0.0005);
  EXPECT_EQ(table.rows[0].stats[3]->median, 1.0);
  for (const auto& row : table.rows)
    EXPECT_FALSE(row.flagged()) << row.method << " " << row.case_kind << " " << row.note();
}

// A record of method "m" on a box case of kind `kind` at `noise` with `status` and `metrics`.
JobRecord summary_record(const std::string& kind, double noise, JobStatus status,
                         std::vector<MetricValue> metrics) {
  JobRecord r;
  r.job.case_id = "box/" + kind;
  r.job.method_id = "m";
  r.job.noise_percent = noise;
  r.case_family = "box";
  r.case_kind = kind;
  r.status = status;
  r.metrics = std::move(metrics);
  return r;
}

TEST(Report, SummaryFlagsFireOnlyWhereAReaderShouldActWithTheReason) {
  const std::string hd = "hausdorff_rel_diag", vertices = "new_vertex_mean_error_rel_diag",
                    time = "time_method_s";
  ResultsData data;
  // Two of three jobs failed: the one value stands for the survivor only.
  data.records.push_back(summary_record("edge", 0, JobStatus::Ok, {{hd, 0.1}}));
  data.records.push_back(summary_record("edge", 0, JobStatus::MethodFailed, {}));
  data.records.push_back(summary_record("edge", 0, JobStatus::Crash, {}));
  // Every job ok; new vertices in one of them only (a patch without interior vertices has
  // none): not a reason.
  data.records.push_back(summary_record("corner", 0, JobStatus::Ok, {{hd, 0.1}, {vertices, 1}}));
  data.records.push_back(summary_record("corner", 0, JobStatus::Ok, {{hd, 0.2}}));
  // The same kind at another noise level is a row of its own.
  data.records.push_back(summary_record("corner", 5, JobStatus::Ok, {{hd, 3.0}}));
  // Exact closings beside approximate ones: quartiles 1.75e-16 and 0.00125; the time's
  // quartiles are as far apart, but time is not judged.
  const double hds[] = {1e-16, 2e-16, 0.001, 0.002}, times[] = {0.01, 0.02, 1, 2};
  for (int i = 0; i < 4; ++i) {
    data.records.push_back(
        summary_record("face_interior", 0, JobStatus::Ok, {{hd, hds[i]}, {time, times[i]}}));
  }
  // Three values within a factor of 10: no spread, whatever the IQR against the median.
  for (double value : {0.01, 0.05, 0.09})
    data.records.push_back(summary_record("island", 0, JobStatus::Ok, {{hd, value}}));

  const auto table = summarize(data);
  ASSERT_EQ(table.rows.size(), 5u);  // corner 0, corner 5, edge, face_interior, island
  EXPECT_EQ(table.rows[0].case_kind, "box/corner");
  EXPECT_EQ(table.rows[1].noise_percent, 5.0);
  EXPECT_FALSE(table.rows[0].flagged()) << table.rows[0].note();
  EXPECT_FALSE(table.rows[1].flagged()) << table.rows[1].note();
  EXPECT_EQ(table.rows[2].note(), "few: n=1 of 3 jobs, some not ok");
  EXPECT_EQ(table.rows[3].spread, std::vector<std::string>{hd});
  EXPECT_EQ(table.rows[3].note(), "spread: hausdorff_rel_diag (q1 1.75e-16, q3 0.00125)");
  EXPECT_FALSE(table.rows[4].flagged()) << table.rows[4].note();
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
  EXPECT_EQ(summary.rows, 7u);
  EXPECT_EQ(summary.flagged_rows, 0u);

  const auto md = read_text(report / "summary.md");
  EXPECT_EQ(md, console_summary(data, no_plots()));
  EXPECT_NE(md.find("| liepa_cgal | box/face_interior | 0 | 2 | 2 | 0 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| - | - | 1.25 | 0.25 |  |"), std::string::npos) << md;
  EXPECT_NE(md.find("| brep_guidance | box/face_interior | 5 | 1 | 0 | 1 | 0.1 |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| brep_guidance | brep/k3/inner | 0 | 1 | 0 | - | - | - |"),
            std::string::npos);
  EXPECT_NE(md.find("0 of 7 rows flagged"), std::string::npos) << md;

  const auto csv = read_text(report / "summary.csv");
  EXPECT_EQ(csv.rfind("method,case_kind,noise_percent,jobs,ok,holes,fallback_holes,metric,n,median,"
                      "q1,q3,iqr,min,max,note\n",
                      0),
            0u);
  EXPECT_NE(csv.find("liepa_cgal,box/face_interior,0,2,2,2,0,hausdorff_rel_diag,2,0.1875,0.15625,"
                     "0.21875,0.0625,0.125,0.25,\n"),
            std::string::npos)
      << csv;
  EXPECT_NE(csv.find("brep_guidance,box/face_interior,5,1,0,1,1,time_method_s,"),
            std::string::npos);
  EXPECT_NE(csv.find("brep_guidance,brep/k3/inner,0,1,0,0,0,time_method_s,0,,,,,,,\n"),
            std::string::npos);

  const auto tex = read_text(report / "tables.tex");
  EXPECT_NE(tex.find("liepa\\_cgal & box/face\\_interior & 0 & 2 & 2 & 0 \\\\"), std::string::npos)
      << tex;
  EXPECT_NE(tex.find("& box/face\\_interior & 5 & 1 & 0 & 1 \\\\"), std::string::npos) << tex;
  EXPECT_NE(tex.find("& brep/k3/inner & 0 & 1 & 0 & -- \\\\"), std::string::npos) << tex;
  EXPECT_NE(tex.find("\\texttt{hausdorff\\_rel\\_diag}"), std::string::npos);
  EXPECT_NE(tex.find("& box/face\\_interior & 5 & 2 & 0.625 &"), std::string::npos) << tex;
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
