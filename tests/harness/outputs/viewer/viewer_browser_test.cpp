// The report's 3D viewer in a real browser: a report of one job (liepa_cgal on the box
// corner) is loaded in headless Chromium (WebGL through SwiftShader), and the screenshot must
// show the model in the viewer's canvas. Skipped, with the reason, where Chromium is not
// installed ($HOLEBENCH_CHROMIUM names another binary).
#include "harness/outputs/render/image.h"
#include "harness/outputs/report/report.h"
#include "harness/results/results_file.h"
#include "harness/run/job.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace holebench::viewer {
namespace {

/// The Chromium binary: $HOLEBENCH_CHROMIUM, else chromium on PATH; empty when neither.
std::string find_chromium() {
  if (const char* path = std::getenv("HOLEBENCH_CHROMIUM"); path && *path)
    return std::filesystem::exists(path) ? path : "";
  const char* path_list = std::getenv("PATH");
  std::string paths = path_list ? path_list : "/usr/bin";
  std::size_t start = 0;
  while (start <= paths.size()) {
    const std::size_t end = std::min(paths.find(':', start), paths.size());
    const auto candidate = std::filesystem::path(paths.substr(start, end - start)) / "chromium";
    if (!candidate.parent_path().empty() && std::filesystem::exists(candidate))
      return candidate.string();
    start = end + 1;
  }
  return "";
}

/// The viewer canvas's clear colour (viewer_page.cpp's #1d2433).
bool is_background(const render::Image& image, std::size_t pixel) {
  const int r = image.pixels[pixel * 3], g = image.pixels[pixel * 3 + 1],
            b = image.pixels[pixel * 3 + 2];
  return std::abs(r - 0x1d) <= 4 && std::abs(g - 0x24) <= 4 && std::abs(b - 0x33) <= 4;
}

struct CanvasInShot {
  int left = 0, top = 0, right = -1, bottom = -1;  ///< the background's bounding box
  std::size_t pixels = 0;
  std::size_t model_pixels = 0;  ///< in the box, not background
};

CanvasInShot find_canvas(const render::Image& shot) {
  CanvasInShot canvas;
  canvas.left = shot.width;
  canvas.top = shot.height;
  for (int y = 0; y < shot.height; ++y) {
    for (int x = 0; x < shot.width; ++x) {
      if (!is_background(shot, static_cast<std::size_t>(y) * shot.width + x))
        continue;
      canvas.left = std::min(canvas.left, x);
      canvas.right = std::max(canvas.right, x);
      canvas.top = std::min(canvas.top, y);
      canvas.bottom = std::max(canvas.bottom, y);
    }
  }
  for (int y = canvas.top; y <= canvas.bottom; ++y) {
    for (int x = canvas.left; x <= canvas.right; ++x) {
      ++canvas.pixels;
      if (!is_background(shot, static_cast<std::size_t>(y) * shot.width + x))
        ++canvas.model_pixels;
    }
  }
  return canvas;
}

/// A results folder with one job's record, picture and viewer meshes, and its report.
std::filesystem::path make_report(const std::filesystem::path& dir) {
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "snapshots");
  harness::Job job;
  job.case_id = "box/corner";
  job.method_id = "liepa_cgal";
  harness::JobOptions options;
  options.snapshot_dir = dir / "snapshots";
  options.viewer_mesh_dir = dir;
  harness::ResultsData data;
  data.context = harness::current_context("viewer test");
  data.records.push_back(harness::run_job(job, options));
  harness::report::ReportOptions report;
  report.python.clear();
  report.warnings_to_stderr = false;
  const auto summary = harness::report::write_report(data, dir, report);
  EXPECT_EQ(summary.viewer_cases, 1u) << summary.viewer_note;
  return summary.dir / "report.html";
}

// Headless Chromium draws the model: the canvas (found by its clear colour) is at least
// 400 x 300 pixels, and at least 3 % of it is not background (the box seen whole covers
// about a fifth; a blank canvas, a failed WebGL context or a script error leave none).
TEST(ViewerBrowser, HeadlessChromiumDrawsTheModel) {
  const std::string chromium = find_chromium();
  if (chromium.empty()) {
    GTEST_SKIP() << "chromium is not installed (Debian: apt-get install chromium; or set "
                    "HOLEBENCH_CHROMIUM): the 3D viewer was not tested in a browser";
  }
  const auto dir = std::filesystem::temp_directory_path() /
                   fmt::format("holebench_viewer_browser_{}", ::getpid());
  const auto page = make_report(dir);
  const auto shot = dir / "shot.png";
  const std::string command = fmt::format(
      "timeout 120 '{}' --headless --no-sandbox --use-angle=swiftshader "
      "--enable-unsafe-swiftshader --user-data-dir='{}' --window-size=1280,2600 "
      "--virtual-time-budget=10000 --screenshot='{}' 'file://{}' > '{}' 2>&1",
      chromium, (dir / "profile").string(), shot.string(), page.string(),
      (dir / "chromium.log").string());
  ASSERT_EQ(std::system(command.c_str()), 0) << command << "\nsee " << (dir / "chromium.log");
  const render::Image image = render::read_image(shot);
  const CanvasInShot canvas = find_canvas(image);
  ASSERT_GE(canvas.right - canvas.left + 1, 400) << "no viewer canvas in " << shot;
  ASSERT_GE(canvas.bottom - canvas.top + 1, 300) << "no viewer canvas in " << shot;
  EXPECT_GE(static_cast<double>(canvas.model_pixels), 0.03 * static_cast<double>(canvas.pixels))
      << "the canvas in " << shot << " is blank";
  if (!HasFailure())
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace holebench::viewer
