#include "harness/outputs/viewer/viewer_page.h"

#include "generators/case_catalog.h"
#include "harness/outputs/viewer/viewer_mesh.h"
#include "tests/harness/text_file.h"

#include <gtest/gtest.h>

#include <fstream>

namespace holebench::viewer {
namespace {

using harness::test_support::read_text;

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// A results folder with one record of liepa_cgal on box/corner and its meshes (the holed
/// mesh stands in for the repaired one: the page does not look inside).
harness::ResultsData one_job(const std::filesystem::path& dir) {
  harness::JobRecord record;
  record.job.case_id = "box/corner";
  record.job.method_id = "liepa_cgal";
  const Case c = generators::make_case("box/corner");
  write_job_meshes(c, c.input, record.job, dir);
  harness::ResultsData data;
  data.records.push_back(record);
  return data;
}

/// Stand-ins for three.js's two files.
std::filesystem::path fake_three(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir / "examples" / "js" / "controls");
  std::ofstream(dir / "three.min.js") << "// three\n";
  std::ofstream(dir / "examples" / "js" / "controls" / "OrbitControls.js") << "// orbit\n";
  return dir;
}

// With meshes and three.js: three.js and the script copied, no copy of the meshes (the page
// links the run's files), and the section with the canvas and the case list.
TEST(ViewerPage, WritesTheFilesAndTheSection) {
  const auto dir = fresh_dir("viewer_page_files");
  const auto data = one_job(dir);
  ViewerOptions options;
  options.three_dir = fake_three(dir / "three");
  const ViewerSection section = write_viewer(data, dir, dir / "report", options);
  EXPECT_TRUE(section.note.empty()) << section.note;
  EXPECT_EQ(section.cases, 1u);
  const std::vector<std::string> files = {"viewer/OrbitControls.js", "viewer/three.min.js",
                                          "viewer/viewer.js"};
  EXPECT_EQ(section.files, files);
  for (const auto& file : files)
    EXPECT_TRUE(std::filesystem::exists(dir / "report" / file)) << file;
  EXPECT_FALSE(std::filesystem::exists(dir / "report/viewer/data"));
  EXPECT_EQ(read_text(dir / "report/viewer/three.min.js"), "// three\n");
  for (const char* link :
       {"../meshes/box_corner_0_0.complete.js", "../meshes/box_corner_0_0.holed.js",
        "../meshes/box_corner_liepa_cgal_no_user_0_0.patch.js"}) {
    EXPECT_NE(section.html.find(link), std::string::npos) << link;
    EXPECT_TRUE(std::filesystem::exists(dir / "report" / link)) << link;
  }
  const std::string holed = read_text(dir / "meshes/box_corner_0_0.holed.js");
  EXPECT_EQ(holed.rfind("holebenchViewer.receiveMesh(\"box_corner_0_0.holed.js\", \"", 0), 0u);
  EXPECT_NE(section.html.find("id=\"viewer-canvas\""), std::string::npos);
  EXPECT_NE(section.html.find("box/corner (noise 0 %, seed 0)"), std::string::npos);
}

// No three.js: no viewer files, and the section and note say what to install.
TEST(ViewerPage, MissingThreeJsIsSaid) {
  const auto dir = fresh_dir("viewer_page_no_three");
  const auto data = one_job(dir);
  ViewerOptions options;
  options.three_dir = dir / "nowhere";
  const ViewerSection section = write_viewer(data, dir, dir / "report", options);
  EXPECT_NE(section.note.find("libjs-three"), std::string::npos);
  EXPECT_TRUE(section.files.empty());
  EXPECT_NE(section.html.find("No 3D viewer"), std::string::npos);
}

// No meshes (a run without snapshots): the section says so.
TEST(ViewerPage, NoMeshesIsSaid) {
  const auto dir = fresh_dir("viewer_page_no_meshes");
  harness::ResultsData data;
  data.records.emplace_back();
  data.records.back().job.case_id = "box/corner";
  const ViewerSection section = write_viewer(data, dir, dir / "report");
  EXPECT_EQ(section.cases, 0u);
  EXPECT_NE(section.note.find("no case has viewer meshes"), std::string::npos);
}

}  // namespace
}  // namespace holebench::viewer
