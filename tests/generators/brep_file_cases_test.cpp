// file/ cases from B-Rep files: a STEP part built in code (tests/core/occt/test_parts.h) is
// punched like a mesh file, and a file that is not STEP is skipped with its reason.
#include "generators/case_catalog.h"

#include "core/boundary_loops.h"
#include "tests/core/occt/test_parts.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <set>
#include <string>

namespace holebench::generators {
namespace {

CatalogOptions user_files_only(const std::filesystem::path& dir) {
  CatalogOptions options;
  options.include_cad = false;
  options.families = {"file"};
  options.user_meshes = {dir};
  return options;
}

// A folder with a STEP part and a garbage .step: the part's file/<stem>/... cases are listed
// and made (a closed complete model, a holed input, the same input twice), the garbage file
// is skipped with a one-line reason naming it.
TEST(BrepFileCases, StepPartsArePunchedAndBadStepFilesSkipped) {
  const auto dir = occt::test::fresh_temp_dir("brep_file_cases");
  occt::test::write_step(occt::test::block_with_pocket_and_hole(), dir / "block.step");
  std::ofstream(dir / "garbage.stp") << "ISO-10303-21;\nthis is not STEP\n";
  const CaseCatalog catalog(user_files_only(dir));
  std::set<std::string> kinds;
  for (const auto& c : catalog.cases()) {
    EXPECT_EQ(c.id.rfind("file/block/", 0), 0u) << c.id;
    kinds.insert(c.kind);
  }
  // A block with a pocket has planar faces, convex and reflex edges and corners.
  EXPECT_TRUE(kinds.count("face_interior"));
  EXPECT_TRUE(kinds.count("edge_convex"));
  EXPECT_TRUE(kinds.count("edge_reflex"));
  ASSERT_EQ(catalog.skipped().size(), 1u);
  const SkippedModel& skipped = catalog.skipped()[0];
  EXPECT_EQ(skipped.name, "file/garbage");
  EXPECT_NE(skipped.reason.find((dir / "garbage.stp").string() + ": not a readable STEP file"),
            std::string::npos)
      << skipped.reason;
  EXPECT_EQ(skipped.reason.find('\n'), std::string::npos);

  const Case a = catalog.make("file/block/edge_convex/small", 1, 5.0);
  EXPECT_TRUE(find_boundary_loops(a.complete).empty());
  EXPECT_EQ(find_boundary_loops(a.input).size(), 1u);
  EXPECT_EQ(a.input.n_faces() + a.holes[0].removed_faces.size(), a.complete.n_faces());
  const Case b = catalog.make("file/block/edge_convex/small", 1, 5.0);
  ASSERT_EQ(a.input.n_vertices(), b.input.n_vertices());
  for (auto v : a.input.vertices())
    EXPECT_EQ(a.input.point(v), b.input.point(b.input.vertex_handle(v.idx())));
}

}  // namespace
}  // namespace holebench::generators
