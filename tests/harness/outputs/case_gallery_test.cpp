#include "harness/outputs/case_gallery.h"

#include "harness/run/case_selection.h"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

namespace holebench::harness {
namespace {

// The gallery page shows one rendered picture per selected case, with its labels.
TEST(CaseGallery, OnePicturePerCaseWithItsLabels) {
  generators::CatalogOptions catalog_options;
  catalog_options.include_cad = false;
  catalog_options.families = {"brep"};
  const generators::CaseCatalog catalog(catalog_options);
  const auto selected =
      select_cases(catalog, {"brep/k1/inner/small", "brep/k3/inner/convex-convex-reflex/small"});
  ASSERT_EQ(selected.size(), 2u);
  const auto dir = std::filesystem::temp_directory_path() / "holebench_gallery_test";
  std::filesystem::remove_all(dir);
  GalleryOptions options;
  options.width = 120;
  options.height = 90;
  options.progress = false;
  const auto page = write_case_gallery(catalog, selected, dir, options);
  ASSERT_TRUE(std::filesystem::exists(page));
  std::ifstream in(page);
  std::ostringstream text;
  text << in.rdbuf();
  const std::string html = text.str();
  const std::regex image("<img src=\"(gallery/[^\"]+\\.png)\"");
  std::size_t images = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), image);
       it != std::sregex_iterator(); ++it) {
    ++images;
    const auto png = dir / (*it)[1].str();
    ASSERT_TRUE(std::filesystem::exists(png)) << png;
    EXPECT_GT(std::filesystem::file_size(png), 1000u) << png;
  }
  EXPECT_EQ(images, 2u);
  EXPECT_NE(html.find("brep/k3/inner/convex-convex-reflex/small"), std::string::npos);
  EXPECT_NE(html.find("k=3"), std::string::npos) << "the labels go with the pictures";
}

}  // namespace
}  // namespace holebench::harness
