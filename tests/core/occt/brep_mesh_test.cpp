// Reading B-Rep files: parts built in code (test_parts.h) are written as STEP, IGES and BREP,
// read back through read_brep_mesh, and checked against the B-Rep they came from.
#include "core/occt/brep_mesh.h"

#include "core/boundary_loops.h"
#include "core/errors.h"
#include "core/mesh_builder.h"
#include "core/occt/shape_tessellation.h"
#include "tests/core/occt/test_parts.h"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <Geom_Plane.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Pln.hxx>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace holebench::occt {
namespace {

int brep_face_count(const TopoDS_Shape& shape) {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  return faces.Extent();
}

std::map<SurfaceType, int> surface_counts(const BrepMesh& brep) {
  std::map<SurfaceType, int> counts;
  for (const SurfaceType type : brep.face_surfaces)
    ++counts[type];
  return counts;
}

// The volume enclosed by a closed, outward-oriented triangle mesh (divergence theorem).
double enclosed_volume(const Mesh& mesh) {
  double six_volume = 0.0;
  for (auto f : mesh.faces()) {
    auto v = mesh.cfv_iter(f);
    const Point a = mesh.point(*v++), b = mesh.point(*v++), c = mesh.point(*v);
    six_volume += OpenMesh::dot(a, OpenMesh::cross(b, c));
  }
  return six_volume / 6.0;
}

struct Box3 {
  Point min, max;
};

Box3 mesh_box(const Mesh& mesh) {
  Box3 box{Point(HUGE_VAL, HUGE_VAL, HUGE_VAL), Point(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL)};
  for (auto v : mesh.vertices()) {
    box.min.minimize(mesh.point(v));
    box.max.maximize(mesh.point(v));
  }
  return box;
}

Box3 shape_box(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::AddOptimal(shape, box, false, false);
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  return {Point(x0, y0, z0), Point(x1, y1, z1)};
}

// Every part, written as STEP and read back: one closed, manifold, outward-oriented surface
// with one region per B-Rep face, within the tessellation's deflection of the B-Rep.
TEST(BrepMesh, StepPartsReadBackClosedWithOneRegionPerBrepFace) {
  const auto dir = test::fresh_temp_dir("brep_mesh_parts");
  const TessellationOptions options;
  for (const auto& part : test::test_parts()) {
    SCOPED_TRACE(part.name);
    const auto path = dir / (part.name + ".step");
    test::write_step(part.shape, path);
    const BrepMesh brep = read_brep_mesh(path, options);
    const Mesh& mesh = brep.mesh;
    // Closed: no boundary loop. Manifold: build_mesh rejects non-manifold edges and vertices,
    // and every edge has two faces.
    EXPECT_TRUE(find_boundary_loops(mesh).empty());
    for (auto e : mesh.edges())
      EXPECT_FALSE(mesh.is_boundary(e));
    // One region per B-Rep face, each with triangles.
    std::set<int> regions;
    for (auto f : mesh.faces())
      regions.insert(region(mesh, f));
    const int faces = brep_face_count(part.shape);
    EXPECT_EQ(static_cast<int>(regions.size()), faces);
    EXPECT_EQ(static_cast<int>(brep.face_surfaces.size()), faces);
    EXPECT_EQ(*regions.begin(), 0);
    EXPECT_EQ(*regions.rbegin(), faces - 1);
    // The bounding box is the shape's within the linear deflection (planar extremes exactly,
    // curved ones up to the deflection inside).
    const Box3 expected = shape_box(part.shape);
    const double diagonal = (expected.max - expected.min).norm();
    const double tolerance = options.linear_deflection_rel_diag * diagonal + 1e-9;
    const Box3 actual = mesh_box(mesh);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(actual.min[i], expected.min[i], tolerance) << "axis " << i;
      EXPECT_NEAR(actual.max[i], expected.max[i], tolerance) << "axis " << i;
    }
    // Outward orientation and the shape: the enclosed volume is the B-Rep's within 1 %
    // (chords cut curved faces by at most the deflection).
    GProp_GProps properties;
    BRepGProp::VolumeProperties(part.shape, properties);
    EXPECT_NEAR(enclosed_volume(mesh), properties.Mass(), 0.01 * properties.Mass());
  }
}

// The surface types of each part's faces, counted by hand from its construction.
TEST(BrepMesh, SurfaceTypesAreThoseOfTheConstruction) {
  const auto dir = test::fresh_temp_dir("brep_mesh_types");
  using Counts = std::map<SurfaceType, int>;
  const std::map<std::string, Counts> expected = {
      // box 6 + pocket floor and 4 walls; the through hole is one cylinder face.
      {"block_with_pocket_and_hole", {{SurfaceType::Plane, 11}, {SurfaceType::Cylinder, 1}}},
      // 8 planar faces of the L prism; the fillet on the reflex edge is a cylinder.
      {"l_bracket_with_fillet", {{SurfaceType::Plane, 8}, {SurfaceType::Cylinder, 1}}},
      // two end discs and two annular shoulders; three cylinder mantles.
      {"stepped_shaft", {{SurfaceType::Plane, 4}, {SurfaceType::Cylinder, 3}}},
      // plate 6, boss top, cone top; boss mantle; cone mantle.
      {"plate_with_bosses",
       {{SurfaceType::Plane, 8}, {SurfaceType::Cylinder, 1}, {SurfaceType::Cone, 1}}},
  };
  for (const auto& part : test::test_parts()) {
    SCOPED_TRACE(part.name);
    const auto path = dir / (part.name + ".stp");
    test::write_step(part.shape, path);
    EXPECT_EQ(surface_counts(read_brep_mesh(path)), expected.at(part.name));
  }
}

// Same file, same options: the same mesh bit for bit (points, triangles, regions).
TEST(BrepMesh, SameFileGivesTheSameMeshBitForBit) {
  const auto dir = test::fresh_temp_dir("brep_mesh_determinism");
  const auto path = dir / "plate.step";
  test::write_step(test::plate_with_bosses(), path);
  const TriangleSoup first = to_soup(read_brep_mesh(path).mesh);
  const TriangleSoup second = to_soup(read_brep_mesh(path).mesh);
  ASSERT_EQ(first.points.size(), second.points.size());
  for (std::size_t i = 0; i < first.points.size(); ++i) {
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(first.points[i][k], second.points[i][k]);  // exact
  }
  EXPECT_EQ(first.triangles, second.triangles);
  EXPECT_EQ(first.regions, second.regions);
}

// A finer deflection gives more triangles on curved faces (the option is honoured).
TEST(BrepMesh, FinerDeflectionGivesMoreTriangles) {
  TessellationOptions coarse, fine;
  coarse.linear_deflection_rel_diag = 0.01;
  coarse.angular_deflection_radians = 1.0;
  fine.linear_deflection_rel_diag = 0.0005;
  fine.angular_deflection_radians = 0.2;
  const TopoDS_Shape shaft = test::stepped_shaft();
  const std::size_t coarse_faces = tessellate_shape(shaft, coarse).mesh.n_faces();
  const std::size_t fine_faces = tessellate_shape(shaft, fine).mesh.n_faces();
  EXPECT_GT(fine_faces, 2 * coarse_faces);
}

// A sphere's poles and a cone's apex are degenerated edges: their nodes are the vertex, the
// triangles collapsed there are dropped, and the surface stays closed.
TEST(BrepMesh, DegeneratedEdgesCloseAtTheirVertex) {
  const std::vector<std::pair<TopoDS_Shape, SurfaceType>> shapes = {
      {BRepPrimAPI_MakeSphere(5.0).Shape(), SurfaceType::Sphere},
      {BRepPrimAPI_MakeCone(5.0, 0.0, 8.0).Shape(), SurfaceType::Cone},
      {BRepPrimAPI_MakeTorus(8.0, 2.0).Shape(), SurfaceType::Torus},
  };
  for (const auto& [shape, type] : shapes) {
    SCOPED_TRACE(to_string(type));
    const BrepMesh brep = tessellate_shape(shape, TessellationOptions{});
    EXPECT_TRUE(find_boundary_loops(brep.mesh).empty());
    EXPECT_EQ(surface_counts(brep).count(type), 1u);
    GProp_GProps properties;
    BRepGProp::VolumeProperties(shape, properties);
    EXPECT_NEAR(enclosed_volume(brep.mesh), properties.Mass(), 0.01 * properties.Mass());
  }
}

// IGES (with B-Rep entities) and BREP files read like STEP: closed, one region per face.
TEST(BrepMesh, IgesAndBrepFilesReadLikeStep) {
  const auto dir = test::fresh_temp_dir("brep_mesh_formats");
  const TopoDS_Shape block = test::block_with_pocket_and_hole();
  test::write_iges(block, dir / "block.igs");
  ASSERT_TRUE(BRepTools::Write(block, (dir / "block.brep").c_str()));
  for (const char* name : {"block.igs", "block.brep"}) {
    SCOPED_TRACE(name);
    const BrepMesh brep = read_brep_mesh(dir / name);
    EXPECT_TRUE(find_boundary_loops(brep.mesh).empty());
    EXPECT_EQ(static_cast<int>(brep.face_surfaces.size()), brep_face_count(block));
    EXPECT_EQ(region_count(brep.mesh), brep_face_count(block));
  }
}

// IGES faces that were never sewn into a shell (each face with edges of its own, as many part
// libraries' IGES files hold them) are sewn before tessellation: the mesh is closed, with one
// region per face, and the mesh's notes say so. Without sewing the same file is open along
// every B-Rep edge.
TEST(BrepMesh, UnsewnIgesFacesAreSewnWithANote) {
  const auto dir = test::fresh_temp_dir("brep_mesh_unsewn");
  const TopoDS_Shape block = test::block_with_pocket_and_hole();
  test::write_iges_unsewn(block, dir / "block.igs");
  const BrepMesh sewn = read_brep_mesh(dir / "block.igs");
  EXPECT_TRUE(find_boundary_loops(sewn.mesh).empty());
  EXPECT_EQ(region_count(sewn.mesh), brep_face_count(block));
  ASSERT_EQ(sewn.notes.size(), 1u);
  EXPECT_NE(sewn.notes[0].find("not sewn into a shell"), std::string::npos) << sewn.notes[0];
  EXPECT_NE(sewn.notes[0].find(": 0 free edges left"), std::string::npos) << sewn.notes[0];

  TessellationOptions unsewn_options;
  unsewn_options.sewing_tolerance_rel_diag = 0.0;
  const BrepMesh unsewn = read_brep_mesh(dir / "block.igs", unsewn_options);
  EXPECT_GE(find_boundary_loops(unsewn.mesh).size(),
            static_cast<std::size_t>(brep_face_count(block)));
  EXPECT_TRUE(unsewn.notes.empty());

  // A sewn file is not sewn again: no note, the faces in the file's order.
  test::write_iges(block, dir / "solid.igs");
  EXPECT_TRUE(read_brep_mesh(dir / "solid.igs").notes.empty());
}

// The message of the InvalidInputError reading `path` throws ("" if none), with nothing
// written to stdout.
std::string read_error(const std::filesystem::path& path) {
  testing::internal::CaptureStdout();
  std::string message;
  try {
    read_brep_mesh(path);
  } catch (const InvalidInputError& e) {
    message = e.what();
  }
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
  return message;
}

// Bad files give one line naming the file and what is wrong, and never a crash.
TEST(BrepMesh, BadFilesGiveAOneLineErrorNamingTheFile) {
  const auto dir = test::fresh_temp_dir("brep_mesh_bad");
  const auto write = [&](const std::string& name, const std::string& content) {
    std::ofstream(dir / name, std::ios::binary) << content;
    return dir / name;
  };
  struct BadFile {
    std::filesystem::path path;
    std::string says;
  };
  const std::vector<BadFile> bad = {
      {write("garbage.step", "this is not a STEP file\n\x01\x02\x03"), "not a readable STEP file"},
      {write("empty.step", ""), "not a readable STEP file"},
      {write("garbage.igs", "not IGES either"), "IGES"},
      {write("garbage.brep", "nor a BREP file"), "not a readable BREP file"},
      {dir / "missing.step", "no such file"},
      {write("mesh.off", "OFF\n0 0 0\n"), "unknown B-Rep file extension"},
  };
  for (const auto& file : bad) {
    SCOPED_TRACE(file.path.string());
    const std::string message = read_error(file.path);
    EXPECT_NE(message.find(file.path.string() + ": "), std::string::npos) << message;
    EXPECT_NE(message.find(file.says), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

// Two bad inputs that a real corpus holds: a file cut short, a file with no solid (a lone
// edge). Each is a one-line error that names the file and what is wrong. (An open shell
// reads; the catalog refuses it: BrepFileCases.AnOpenShellIsSkippedWithItsReason.)
TEST(BrepMesh, TruncatedFilesAndShapesWithoutFacesAreRefused) {
  const auto dir = test::fresh_temp_dir("brep_mesh_bad_shapes");
  test::write_step(test::block_with_pocket_and_hole(), dir / "whole.step");
  std::string bytes;
  {
    std::ifstream in(dir / "whole.step", std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  std::ofstream(dir / "truncated.step", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  test::write_step(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0)).Edge(),
                   dir / "edge_only.step");

  struct BadFile {
    std::string name;
    std::vector<std::string> says_one_of;
  };
  const std::vector<BadFile> bad = {
      {"truncated.step", {"not a readable STEP file (OpenCASCADE read status: fail"}},
      {"edge_only.step", {"no faces (the file holds no solid, shell or face)"}},
  };
  for (const auto& file : bad) {
    SCOPED_TRACE(file.name);
    const std::string message = read_error(dir / file.name);
    EXPECT_EQ(message.rfind((dir / file.name).string() + ": ", 0), 0u) << message;
    EXPECT_TRUE(
        std::any_of(file.says_one_of.begin(), file.says_one_of.end(),
                    [&](const std::string& s) { return message.find(s) != std::string::npos; }))
        << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

// A face that does not tessellate: a planar face bounded by a wire of zero area (an edge
// there and back), beside a box, in a BREP file (STEP would not keep it). The error is one
// line naming the file and the face, and the read does not crash.
TEST(BrepMesh, AFaceThatDoesNotTessellateIsNamed) {
  const auto dir = test::fresh_temp_dir("brep_mesh_untessellated_face");
  const gp_Pnt a(3, 0, 0), b(4, 0, 0);
  const TopoDS_Vertex va = BRepBuilderAPI_MakeVertex(a), vb = BRepBuilderAPI_MakeVertex(b);
  const TopoDS_Edge there = BRepBuilderAPI_MakeEdge(va, vb);
  const TopoDS_Edge back = BRepBuilderAPI_MakeEdge(vb, va);
  BRep_Builder builder;
  TopoDS_Wire wire;
  builder.MakeWire(wire);
  builder.Add(wire, there);
  builder.Add(wire, back);
  TopoDS_Face sliver;
  builder.MakeFace(sliver, new Geom_Plane(gp_Pln(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1))), 1e-7);
  builder.Add(sliver, wire);
  TopoDS_Compound compound;
  builder.MakeCompound(compound);
  builder.Add(compound, BRepPrimAPI_MakeBox(1.0, 1.0, 1.0).Shape());
  builder.Add(compound, sliver);
  const auto file = dir / "sliver.brep";
  ASSERT_TRUE(BRepTools::Write(compound, file.string().c_str()));
  const std::string message = read_error(file);
  EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
  EXPECT_NE(message.find("B-Rep face 6 did not tessellate (tried at a linear deflection of 0.001 "
                         "of the diagonal and 0.25, 4 times it)"),
            std::string::npos)
      << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(BrepMesh, BrepFileExtensionsAnyCase) {
  EXPECT_TRUE(is_brep_file("a.STEP"));
  EXPECT_TRUE(is_brep_file("a.stp"));
  EXPECT_TRUE(is_brep_file("a.Iges"));
  EXPECT_TRUE(is_brep_file("a.igs"));
  EXPECT_TRUE(is_brep_file("a.brep"));
  EXPECT_TRUE(is_brep_file("a.brp"));
  EXPECT_FALSE(is_brep_file("a.off"));
  EXPECT_FALSE(is_brep_file("step"));
}

}  // namespace
}  // namespace holebench::occt
