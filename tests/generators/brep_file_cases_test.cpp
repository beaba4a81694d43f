// file/ cases from B-Rep files: a STEP part built in code (tests/core/occt/test_parts.h) is
// punched like a mesh file, and a file that is not STEP is skipped with its reason.
#include "generators/case_catalog.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"
#include "core/plane_fit.h"
#include "tests/core/occt/test_parts.h"
#include "tests/generators/label_geometry.h"

#include <gtest/gtest.h>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>

#include <array>
#include <cstdlib>
#include <fstream>
#include <iostream>
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

// An open shell (a box with one face missing: a surface model, not a solid) is not skipped: its
// missing face is a real hole (generators/real_holes.h), a case as it is and with its rings
// removed; the part beside it still gives its punched cases. Its four free edges were offered to
// sewing, which left them free, and the notes say so.
TEST(BrepFileCases, AnOpenShellGivesItsRealHole) {
  const auto dir = occt::test::fresh_temp_dir("brep_file_open_shell");
  occt::test::write_step(occt::test::block_with_pocket_and_hole(), dir / "block.step");
  TopoDS_Shell open_box;
  BRep_Builder builder;
  builder.MakeShell(open_box);
  int faces = 0;
  for (TopExp_Explorer face(BRepPrimAPI_MakeBox(1.0, 2.0, 3.0).Shape(), TopAbs_FACE); face.More();
       face.Next()) {
    if (faces++ > 0)  // every face but the first
      builder.Add(open_box, TopoDS::Face(face.Current()));
  }
  ASSERT_TRUE(BRepTools::Write(open_box, (dir / "open_box.brep").c_str()));
  const CaseCatalog catalog(user_files_only(dir));
  EXPECT_TRUE(catalog.skipped().empty());
  std::vector<std::string> real_holes;
  for (const auto& c : catalog.cases()) {
    if (c.id.rfind("file/open_box/", 0) == 0)
      real_holes.push_back(c.id);
    else
      EXPECT_EQ(c.id.rfind("file/block/", 0), 0u) << c.id;
  }
  // Ten triangles: 2 or 4 rings around the missing face would take every face, so only one is
  // listed.
  EXPECT_EQ(real_holes,
            (std::vector<std::string>{"file/open_box/hole/0", "file/open_box/hole/0/rings-1"}));
  std::vector<std::string> notes;
  for (const auto& note : catalog.model_notes())
    notes.push_back(note.name + ": " + note.note);
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_NE(notes[0].find("file/open_box: its faces were not sewn into a shell (4 free edges)"),
            std::string::npos)
      << notes[0];
  EXPECT_NE(notes[0].find(": 4 free edges left"), std::string::npos) << notes[0];
  EXPECT_NE(notes[1].find("file/open_box: an open mesh: 1 real hole"), std::string::npos)
      << notes[1];
  EXPECT_FALSE(catalog.make("file/open_box/hole/0").has_ground_truth);
}

// The input of a hole punched into a B-Rep file keeps the B-Rep's face ids (the B-Rep
// paper's input): every triangle has the face id of the complete model's triangle at the
// same place, and the ids are the B-Rep's faces (the block has 12), not a segmentation.
TEST(BrepFileCases, InputsPunchedIntoBrepFilesCarryTheFaceIds) {
  const auto dir = occt::test::fresh_temp_dir("brep_file_face_ids");
  occt::test::write_step(occt::test::block_with_pocket_and_hole(), dir / "block.step");
  const CaseCatalog catalog(user_files_only(dir));
  const Case c = catalog.make("file/block/edge_convex/small");
  std::map<std::array<double, 3>, int> complete_face_at;  // face centroid -> face id
  auto centroid_of = [](const Mesh& mesh, FaceHandle f) {
    Point sum(0, 0, 0);
    for (auto v : mesh.fv_range(f))
      sum += mesh.point(v);
    sum /= 3.0;
    return std::array<double, 3>{sum[0], sum[1], sum[2]};
  };
  std::set<int> ids;
  for (auto f : c.complete.faces()) {
    complete_face_at[centroid_of(c.complete, f)] = region(c.complete, f);
    ids.insert(region(c.complete, f));
  }
  EXPECT_EQ(ids.size(), 12u);
  for (auto f : c.input.faces()) {
    ASSERT_NE(region(c.input, f), kNoRegion);
    const auto it = complete_face_at.find(centroid_of(c.input, f));
    ASSERT_NE(it, complete_face_at.end());
    EXPECT_EQ(region(c.input, f), it->second);
  }
}

// The face, edge and corner holes of the B-Rep files in `dir` whose removed faces are all
// planar, and how many of them carry labels; every label is checked against the one read
// off the meshes (label_geometry::expect_punched_labels_agree).
struct PlanarHoleLabels {
  int planar_holes = 0;
  int labelled = 0;
};

PlanarHoleLabels check_planar_hole_labels(const std::filesystem::path& dir) {
  const CaseCatalog catalog(user_files_only(dir));
  PlanarHoleLabels counts;
  for (const auto& descriptor : catalog.cases()) {
    const std::string& kind = descriptor.kind;
    if (kind != "face_interior" && kind.rfind("edge_", 0) != 0 && kind.rfind("corner_", 0) != 0)
      continue;
    SCOPED_TRACE(descriptor.id);
    const Case c = catalog.make(descriptor.id);
    // B-Rep faces are the complete model's regions: a planar one fits a plane exactly.
    const auto planes = fit_region_planes(c.complete);
    const double tolerance = 1e-6 * bounding_box_diagonal(c.complete);
    bool planar = true;
    for (int f : c.holes[0].removed_faces) {
      const auto& fit = planes[region(c.complete, c.complete.face_handle(f))];
      planar = planar && fit.valid && fit.plane.rms_residual < tolerance;
    }
    if (!planar)
      continue;
    ++counts.planar_holes;
    const auto loops = find_boundary_loops(c.input);
    if (!c.holes[0].labels || loops.size() != 1)
      continue;
    ++counts.labelled;
    label_geometry::expect_punched_labels_agree(c, loops[0]);
  }
  return counts;
}

// Holes punched into B-Rep parts take their labels from the B-Rep's faces: of the face,
// edge and corner holes whose removed faces are all planar, at least 90 % are labelled, and
// every label agrees with the one read off the meshes.
TEST(BrepFileCases, PlanarHolesInBrepPartsAreLabelledFromTheFaces) {
  const auto dir = occt::test::fresh_temp_dir("brep_file_labels");
  for (const auto& part : occt::test::test_parts())
    occt::test::write_step(part.shape, dir / (part.name + ".step"));
  EXPECT_TRUE(CaseCatalog(user_files_only(dir)).skipped().empty());
  const PlanarHoleLabels counts = check_planar_hole_labels(dir);
  EXPECT_GE(counts.planar_holes, 20);
  EXPECT_GE(counts.labelled, 0.9 * counts.planar_holes)
      << counts.labelled << " of " << counts.planar_holes;
}

// IGES parts whose faces are not sewn into a shell (written face by face, as many part
// libraries' IGES files are) are sewn, then punched, and their labels pass the same check; each
// model's note says it was sewn.
TEST(BrepFileCases, UnsewnIgesPartsAreSewnPunchedAndLabelled) {
  const auto dir = occt::test::fresh_temp_dir("brep_file_unsewn");
  for (const auto& part : occt::test::test_parts())
    occt::test::write_iges_unsewn(part.shape, dir / (part.name + ".igs"));
  const CaseCatalog catalog(user_files_only(dir));
  EXPECT_TRUE(catalog.skipped().empty());
  ASSERT_EQ(catalog.model_notes().size(), occt::test::test_parts().size());
  for (const auto& note : catalog.model_notes())
    EXPECT_NE(note.note.find("sewn with OpenCASCADE's BRepBuilderAPI_Sewing"), std::string::npos)
        << note.name << ": " << note.note;
  const PlanarHoleLabels counts = check_planar_hole_labels(dir);
  EXPECT_GE(counts.planar_holes, 20);
  EXPECT_GE(counts.labelled, 0.9 * counts.planar_holes)
      << counts.labelled << " of " << counts.planar_holes;
}

// The same check on a folder of your own B-Rep files (for example the KiCad subset of
// scripts/fetch_kicad_subset.sh), named by HOLEBENCH_LABEL_CHECK_DIR; skipped without it,
// since CI has no such folder. Prints the count.
TEST(BrepFileCases, PlanarHolesInYourBrepFilesAreLabelledFromTheFaces) {
  const char* dir = std::getenv("HOLEBENCH_LABEL_CHECK_DIR");
  if (!dir)
    GTEST_SKIP() << "set HOLEBENCH_LABEL_CHECK_DIR to a folder of STEP/IGES/BREP files";
  const PlanarHoleLabels counts = check_planar_hole_labels(dir);
  std::cout << counts.labelled << " of " << counts.planar_holes
            << " face, edge and corner holes on planar faces labelled\n";
  EXPECT_GE(counts.labelled, 0.9 * counts.planar_holes)
      << counts.labelled << " of " << counts.planar_holes;
}

}  // namespace
}  // namespace holebench::generators
