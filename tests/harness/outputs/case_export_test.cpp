#include "harness/outputs/case_export.h"
#include "harness/outputs/file_names.h"

#include "core/mesh_io.h"
#include "generators/case_catalog.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

namespace holebench::harness {
namespace {

// An exported case reads back as the same meshes, regions and ground truth.
TEST(CaseExport, WritesMeshesAndGroundTruthThatReadBack) {
  const Case c = generators::make_case("box/corner", 2, 5.0);
  const auto dir =
      std::filesystem::temp_directory_path() / "holebench_export_test" / file_stem_of_id(c.id);
  std::filesystem::remove_all(dir);
  export_case(c, dir);
  EXPECT_EQ(file_stem_of_id("box/corner"), "box_corner");
  EXPECT_EQ(file_stem_of_id("box/corner|liepa_cgal|no_user|0|0"),
            "box_corner_liepa_cgal_no_user_0_0");

  const Mesh input = read_mesh(dir / "input.ply");
  ASSERT_EQ(input.n_vertices(), c.input.n_vertices());
  for (auto v : input.vertices())
    EXPECT_EQ(input.point(v), c.input.point(v));
  const Mesh complete = read_mesh(dir / "complete.ply");
  ASSERT_EQ(complete.n_faces(), c.complete.n_faces());
  for (auto f : complete.faces())
    EXPECT_EQ(region(complete, f), region(c.complete, f));
  EXPECT_EQ(read_mesh(dir / "input.off").n_faces(), c.input.n_faces());

  std::ifstream in(dir / "case.json");
  const auto json = nlohmann::json::parse(in);
  EXPECT_EQ(json["id"], "box/corner");
  EXPECT_EQ(json["seed"], 2);
  EXPECT_EQ(json["noise_percent"], 5.0);
  const auto& hole = json["holes"][0];
  EXPECT_EQ(hole["removed_faces"].size(), c.holes[0].removed_faces.size());
  EXPECT_EQ(hole["labels"]["k"], 3);
  EXPECT_EQ(hole["labels"]["orientation"], "inner");
  EXPECT_EQ(hole["missing_corners"][0][0], c.holes[0].missing_corners[0][0]);
}

}  // namespace
}  // namespace holebench::harness
