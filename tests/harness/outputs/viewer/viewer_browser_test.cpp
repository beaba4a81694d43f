// The report's 3D viewer in a real browser: a report is loaded in headless Chromium (WebGL
// through SwiftShader), and the screenshot must show the model in the viewer's canvas, and,
// as the viewer opens at the case's first hole, the patch over a good part of it. Skipped,
// with the reason, where Chromium is not installed ($HOLEBENCH_CHROMIUM names another binary).
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
#include <optional>
#include <string>
#include <vector>

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

/// A patch pixel: coloured by the heat map (render/heat_map.h: blue, cyan, green, yellow,
/// red), where kept faces are grey and the background a dark grey-blue (channels within 22).
bool is_patch(const render::Image& image, std::size_t pixel) {
  const int r = image.pixels[pixel * 3], g = image.pixels[pixel * 3 + 1],
            b = image.pixels[pixel * 3 + 2];
  return std::max({r, g, b}) - std::min({r, g, b}) > 60;
}

struct CanvasInShot {
  int left = 0, top = 0, right = -1, bottom = -1;  ///< the background's bounding box
  std::size_t pixels = 0;
  std::size_t model_pixels = 0;  ///< in the box, not background
  std::size_t patch_pixels = 0;  ///< in the box, in the heat map's colours
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
      const std::size_t pixel = static_cast<std::size_t>(y) * shot.width + x;
      if (!is_background(shot, pixel))
        ++canvas.model_pixels;
      if (is_patch(shot, pixel))
        ++canvas.patch_pixels;
    }
  }
  return canvas;
}

/// A results folder with the records, pictures and viewer meshes of `methods` on `case_id`,
/// and its report.
std::filesystem::path make_report(const std::filesystem::path& dir,
                                  const std::string& case_id = "box/corner",
                                  const std::vector<std::string>& methods = {"liepa_cgal"}) {
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "snapshots");
  harness::JobOptions options;
  options.snapshot_dir = dir / "snapshots";
  options.viewer_mesh_dir = dir;
  harness::ResultsData data;
  data.context = harness::current_context("viewer test");
  for (const auto& method : methods) {
    harness::Job job;
    job.case_id = case_id;
    job.method_id = method;
    data.records.push_back(harness::run_job(job, options));
  }
  harness::report::ReportOptions report;
  report.python.clear();
  report.warnings_to_stderr = false;
  const auto summary = harness::report::write_report(data, dir, report);
  EXPECT_EQ(summary.viewer_cases, 1u) << summary.viewer_note;
  return summary.dir / "report.html";
}

/// The screenshot of `page` in headless Chromium, as the viewer's first frame shows it; none
/// where Chromium failed (the failure is recorded).
std::optional<render::Image> screenshot(const std::string& chromium,
                                        const std::filesystem::path& page,
                                        const std::filesystem::path& dir) {
  const auto shot = dir / "shot.png";
  const std::string command = fmt::format(
      "timeout 120 '{}' --headless --no-sandbox --use-angle=swiftshader "
      "--enable-unsafe-swiftshader --user-data-dir='{}' --window-size=1280,2600 "
      "--virtual-time-budget=10000 --screenshot='{}' 'file://{}' > '{}' 2>&1",
      chromium, (dir / "profile").string(), shot.string(), page.string(),
      (dir / "chromium.log").string());
  const int status = std::system(command.c_str());
  EXPECT_EQ(status, 0) << command << "\nsee " << (dir / "chromium.log");
  if (status != 0 || !std::filesystem::exists(shot))
    return std::nullopt;
  return render::read_image(shot);
}

// Headless Chromium draws the model: the canvas (found by its clear colour) is at least
// 400 x 300 pixels, and at least 3 % of it is not background (a blank canvas, a failed WebGL
// context or a script error leave none).
TEST(ViewerBrowser, HeadlessChromiumDrawsTheModel) {
  const std::string chromium = find_chromium();
  if (chromium.empty()) {
    GTEST_SKIP() << "chromium is not installed (Debian: apt-get install chromium; or set "
                    "HOLEBENCH_CHROMIUM): the 3D viewer was not tested in a browser";
  }
  const auto dir = std::filesystem::temp_directory_path() /
                   fmt::format("holebench_viewer_browser_{}", ::getpid());
  const auto image = screenshot(chromium, make_report(dir), dir);
  ASSERT_TRUE(image) << "no screenshot in " << dir;
  const CanvasInShot canvas = find_canvas(*image);
  ASSERT_GE(canvas.right - canvas.left + 1, 400) << "no viewer canvas in " << dir;
  ASSERT_GE(canvas.bottom - canvas.top + 1, 300) << "no viewer canvas in " << dir;
  EXPECT_GE(static_cast<double>(canvas.model_pixels), 0.03 * static_cast<double>(canvas.pixels))
      << "the canvas in " << dir << " is blank";
  if (!HasFailure())
    std::filesystem::remove_all(dir);
}

// The viewer opens at the hole: on a 2 % hole at a corner of the L-block, with two methods'
// repairs side by side, the first frame shows the patches (the heat map's colours) over at
// least 5 % of the canvas.
TEST(ViewerBrowser, TheFirstFrameShowsThePatchOfTheChosenCase) {
  const std::string chromium = find_chromium();
  if (chromium.empty()) {
    GTEST_SKIP() << "chromium is not installed (Debian: apt-get install chromium; or set "
                    "HOLEBENCH_CHROMIUM): the 3D viewer was not tested in a browser";
  }
  const auto dir =
      std::filesystem::temp_directory_path() / fmt::format("holebench_viewer_hole_{}", ::getpid());
  const auto page =
      make_report(dir, "solid/l_block/corner_ccc/small", {"liepa_cgal", "cgal_triangulate"});
  const auto image = screenshot(chromium, page, dir);
  ASSERT_TRUE(image) << "no screenshot in " << dir;
  const CanvasInShot canvas = find_canvas(*image);
  ASSERT_GE(canvas.right - canvas.left + 1, 400) << "no viewer canvas in " << dir;
  EXPECT_GE(static_cast<double>(canvas.patch_pixels), 0.05 * static_cast<double>(canvas.pixels))
      << "the patch covers " << canvas.patch_pixels << " of " << canvas.pixels
      << " canvas pixels in " << dir;
  if (!HasFailure())
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace holebench::viewer
