// Real holes (generators/real_holes.h): which boundary loops are holes, the rings around a
// hole, the two case kinds, and the catalog's file/<stem>/hole/<i>[/rings-<r>] cases.
#include "generators/real_holes.h"

#include "core/boundary_loops.h"
#include "core/mesh_builder.h"
#include "core/mesh_io.h"
#include "generators/box_solid.h"
#include "generators/case_catalog.h"
#include "generators/hole_punch.h"
#include "tests/test_meshes.h"

#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <filesystem>
#include <set>

namespace holebench::generators {
namespace {

// The box with the faces within 0.2 of its -z face's centre punched out: one hole.
Mesh box_with_one_hole() {
  const Mesh box = make_box();
  return punch_faces(box, faces_in_ball(box, Point(1.0, 0.75, 0.0), 0.2)).holed;
}

TEST(RealHoles, AHoleInAClosedSurfaceIsAHole) {
  const MeshLoops loops = classify_boundary_loops(box_with_one_hole());
  EXPECT_EQ(loops.holes, std::vector<int>{0});
  EXPECT_TRUE(loops.sheet_borders.empty());
}

TEST(RealHoles, TheBorderOfAnOpenSheetIsNotAHole) {
  const Mesh sheet = build_mesh(test::grid_soup(8));
  const MeshLoops plain = classify_boundary_loops(sheet);
  EXPECT_TRUE(plain.holes.empty());
  EXPECT_EQ(plain.sheet_borders.size(), 1u);
  // A sheet with a hole of two cells inside: the hole is one, the border the other.
  const Mesh holed = build_mesh(test::grid_without_cells(8, {{3, 3}, {4, 3}}));
  const auto all = find_boundary_loops(holed);
  const MeshLoops loops = classify_boundary_loops(holed);
  ASSERT_EQ(all.size(), 2u);
  ASSERT_EQ(loops.holes.size(), 1u);
  ASSERT_EQ(loops.sheet_borders.size(), 1u);
  EXPECT_EQ(all[static_cast<std::size_t>(loops.holes[0])].size(), 6u);  // 2 x 1 cells
  EXPECT_EQ(all[static_cast<std::size_t>(loops.sheet_borders[0])].size(), 32u);
}

// The rings around a loop, against their definition checked face by face: ring 1 is every face
// with a vertex on the loop; ring 2 every face with a vertex on a ring-1 face.
TEST(RealHoles, RingsAreTheFacesWithinThatManyVertexRings) {
  const Mesh mesh = box_with_one_hole();
  const BoundaryLoop loop = find_boundary_loops(mesh)[0];
  std::set<int> on_loop;
  for (VertexHandle v : loop_vertices(mesh, loop))
    on_loop.insert(v.idx());
  const auto faces_touching = [&mesh](const std::set<int>& vertices) {
    std::vector<int> faces;
    for (auto f : mesh.faces()) {
      bool touches = false;
      for (auto v : mesh.fv_range(f))
        touches = touches || vertices.count(v.idx()) > 0;
      if (touches)
        faces.push_back(f.idx());
    }
    return faces;
  };
  const std::vector<int> ring1 = faces_touching(on_loop);
  EXPECT_EQ(faces_around_loop(mesh, loop, 1), ring1);
  std::set<int> ring1_vertices;
  for (int f : ring1)
    for (auto v : mesh.fv_range(mesh.face_handle(f)))
      ring1_vertices.insert(v.idx());
  EXPECT_EQ(faces_around_loop(mesh, loop, 2), faces_touching(ring1_vertices));
  EXPECT_GT(faces_around_loop(mesh, loop, 4).size(), faces_around_loop(mesh, loop, 2).size());
}

TEST(RealHoles, ARealHoleHasNoTruthAndTheRingsAreTheTruthOfTheEnlargedHole) {
  const Mesh mesh = box_with_one_hole();
  const Case real = make_real_hole_case(mesh, 0, "file/box/hole/0");
  EXPECT_FALSE(real.has_ground_truth);
  EXPECT_EQ(real.input.n_faces(), mesh.n_faces());
  EXPECT_EQ(real.complete.n_faces(), mesh.n_faces());
  ASSERT_EQ(real.holes.size(), 1u);
  EXPECT_TRUE(real.holes[0].removed_faces.empty());
  EXPECT_FALSE(real.holes[0].labels.has_value());

  const Case rings = make_ring_removal_case(mesh, 0, 2, "file/box/hole/0/rings-2");
  EXPECT_TRUE(rings.has_ground_truth);
  EXPECT_EQ(rings.kind, "rings-2");
  ASSERT_EQ(rings.holes.size(), 1u);
  const std::vector<int> expected = faces_around_loop(mesh, find_boundary_loops(mesh)[0], 2);
  EXPECT_EQ(rings.holes[0].removed_faces, expected);  // the box's rings leave no pinched vertex
  EXPECT_EQ(rings.input.n_faces() + expected.size(), mesh.n_faces());
  EXPECT_EQ(find_boundary_loops(rings.input).size(), 1u);
  EXPECT_THROW(make_real_hole_case(mesh, 1, "file/box/hole/1"), std::invalid_argument);
}

struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& name)
      : path(std::filesystem::temp_directory_path() /
             ("holebench_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
};

// An open mesh given with --mesh is not skipped: each hole is a case as it is and with 1, 2, 4
// rings removed; the same id gives the same case bit for bit; an open sheet is skipped with
// its reason.
TEST(RealHoles, TheCatalogListsAnOpenMeshsHolesAndSkipsASheet) {
  const TempDir dir("real_holes_catalog");
  write_mesh(box_with_one_hole(), dir.path / "holed_box.off");
  write_mesh(build_mesh(test::grid_soup(6)), dir.path / "sheet.off");
  CatalogOptions options;
  options.include_cad = false;
  options.families = {"file"};
  options.user_meshes = {dir.path};
  const CaseCatalog catalog(options);
  std::vector<std::string> ids;
  for (const auto& descriptor : catalog.cases())
    ids.push_back(descriptor.id);
  EXPECT_EQ(ids, (std::vector<std::string>{"file/holed_box/hole/0", "file/holed_box/hole/0/rings-1",
                                           "file/holed_box/hole/0/rings-2",
                                           "file/holed_box/hole/0/rings-4"}));
  ASSERT_EQ(catalog.skipped().size(), 1u);
  EXPECT_EQ(catalog.skipped()[0].name, "file/sheet");
  EXPECT_NE(catalog.skipped()[0].reason.find("an open sheet"), std::string::npos);
  for (const auto& id : ids) {
    SCOPED_TRACE(id);
    const Case a = catalog.make(id, 3, 5.0);
    const Case b = catalog.make(id, 3, 5.0);
    EXPECT_EQ(to_soup(a.input).points, to_soup(b.input).points);
    EXPECT_EQ(to_soup(a.input).triangles, to_soup(b.input).triangles);
    EXPECT_EQ(a.has_ground_truth, id == "file/holed_box/hole/0" ? false : true);
  }
  EXPECT_THROW(catalog.make("file/holed_box/hole/1"), std::invalid_argument);
  EXPECT_THROW(catalog.make("file/holed_box/hole/0/rings-x"), std::invalid_argument);
}

}  // namespace
}  // namespace holebench::generators
