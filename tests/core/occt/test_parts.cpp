#include "tests/core/occt/test_parts.h"

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRep_Tool.hxx>
#include <IGESControl_Writer.hxx>
#include <STEPControl_Writer.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include <unistd.h>
#include <stdexcept>

namespace holebench::occt::test {

TopoDS_Shape block_with_pocket_and_hole() {
  const TopoDS_Shape block = BRepPrimAPI_MakeBox(40.0, 30.0, 20.0).Shape();
  const TopoDS_Shape pocket =
      BRepPrimAPI_MakeBox(gp_Pnt(5.0, 10.0, 12.0), 12.0, 10.0, 10.0).Shape();
  const TopoDS_Shape hole =
      BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(30.0, 15.0, -1.0), gp::DZ()), 4.0, 22.0).Shape();
  const TopoDS_Shape pocketed = BRepAlgoAPI_Cut(block, pocket).Shape();
  return BRepAlgoAPI_Cut(pocketed, hole).Shape();
}

TopoDS_Shape l_bracket_with_fillet() {
  // The L profile in the xy plane: a 40 long foot and a 30 high wall, both 8 thick.
  BRepBuilderAPI_MakePolygon profile;
  for (const auto& [x, y] :
       {std::pair{0.0, 0.0}, {40.0, 0.0}, {40.0, 8.0}, {8.0, 8.0}, {8.0, 30.0}, {0.0, 30.0}}) {
    profile.Add(gp_Pnt(x, y, 0.0));
  }
  profile.Close();
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(profile.Wire());
  const TopoDS_Shape prism = BRepPrimAPI_MakePrism(face, gp_Vec(0.0, 0.0, 20.0)).Shape();
  // The reflex edge: the one parallel to z through (8, 8).
  BRepFilletAPI_MakeFillet fillet(prism);
  for (TopExp_Explorer it(prism, TopAbs_EDGE); it.More(); it.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
    const gp_Pnt a = BRep_Tool::Pnt(TopExp::FirstVertex(edge));
    const gp_Pnt b = BRep_Tool::Pnt(TopExp::LastVertex(edge));
    if (a.Distance(gp_Pnt(8.0, 8.0, a.Z())) < 1e-9 && b.Distance(gp_Pnt(8.0, 8.0, b.Z())) < 1e-9)
      fillet.Add(4.0, edge);
  }
  return fillet.Shape();
}

TopoDS_Shape stepped_shaft() {
  TopoDS_Shape shaft = BRepPrimAPI_MakeCylinder(10.0, 20.0).Shape();
  double z = 20.0;
  for (const auto& [radius, length] : {std::pair{7.0, 15.0}, {4.0, 10.0}}) {
    const TopoDS_Shape step =
        BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0.0, 0.0, z), gp::DZ()), radius, length).Shape();
    shaft = BRepAlgoAPI_Fuse(shaft, step).Shape();
    z += length;
  }
  return shaft;
}

TopoDS_Shape plate_with_bosses() {
  const TopoDS_Shape plate = BRepPrimAPI_MakeBox(60.0, 40.0, 5.0).Shape();
  const TopoDS_Shape boss =
      BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(15.0, 20.0, 5.0), gp::DZ()), 6.0, 10.0).Shape();
  const TopoDS_Shape cone =
      BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(42.0, 20.0, 5.0), gp::DZ()), 6.0, 3.0, 8.0).Shape();
  return BRepAlgoAPI_Fuse(BRepAlgoAPI_Fuse(plate, boss).Shape(), cone).Shape();
}

namespace {
// A prism of height `height` along z over the triangle (a, b, c).
TopoDS_Shape triangular_prism(const gp_Pnt& a, const gp_Pnt& b, const gp_Pnt& c, double height) {
  BRepBuilderAPI_MakePolygon profile(a, b, c, /*Close=*/true);
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(profile.Wire());
  return BRepPrimAPI_MakePrism(face, gp_Vec(0.0, 0.0, height)).Shape();
}
}  // namespace

TopoDS_Shape block_with_pad_pocket_and_split_faces() {
  TopoDS_Shape part = BRepPrimAPI_MakeBox(60.0, 40.0, 20.0).Shape();
  part = BRepAlgoAPI_Fuse(part, triangular_prism(gp_Pnt(8.0, 22.0, 20.0), gp_Pnt(24.0, 22.0, 20.0),
                                                 gp_Pnt(14.0, 34.0, 20.0), 5.0))
             .Shape();
  part = BRepAlgoAPI_Cut(part, triangular_prism(gp_Pnt(32.0, 22.0, 14.0), gp_Pnt(48.0, 22.0, 14.0),
                                                gp_Pnt(40.0, 34.0, 14.0), 7.0))
             .Shape();
  // Boxes inside the block, flush with its faces: the Boolean keeps the coincident faces split.
  // Small enough (the structure size is 6 % of the diagonal, 4.6) that removing them gives
  // inner holes to be closed automatically.
  for (const auto& [corner, size] : {std::pair{gp_Pnt(8.0, 6.0, 17.0), gp_Vec(3.0, 3.0, 3.0)},
                                     {gp_Pnt(26.0, 0.0, 17.0), gp_Vec(3.0, 3.0, 3.0)},
                                     {gp_Pnt(57.0, 0.0, 17.0), gp_Vec(3.0, 3.0, 3.0)}}) {
    part = BRepAlgoAPI_Fuse(part, BRepPrimAPI_MakeBox(corner, size.X(), size.Y(), size.Z()).Shape())
               .Shape();
  }
  return part;
}

std::vector<TestPart> test_parts() {
  return {{"block_with_pocket_and_hole", block_with_pocket_and_hole()},
          {"l_bracket_with_fillet", l_bracket_with_fillet()},
          {"stepped_shaft", stepped_shaft()},
          {"plate_with_bosses", plate_with_bosses()}};
}

void write_step(const TopoDS_Shape& shape, const std::filesystem::path& path) {
  silence_opencascade_messages();  // the writer prints its statistics
  STEPControl_Writer writer;
  if (writer.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone ||
      writer.Write(path.c_str()) != IFSelect_RetDone) {
    throw std::runtime_error("cannot write STEP file " + path.string());
  }
}

void write_iges(const TopoDS_Shape& shape, const std::filesystem::path& path) {
  IGESControl_Writer writer("MM", /*modecr=*/1);  // 1: B-Rep entities (MSBO)
  if (!writer.AddShape(shape))
    throw std::runtime_error("cannot convert the shape to IGES for " + path.string());
  writer.ComputeModel();
  if (!writer.Write(path.c_str()))
    throw std::runtime_error("cannot write IGES file " + path.string());
}

void write_iges_unsewn(const TopoDS_Shape& shape, const std::filesystem::path& path) {
  IGESControl_Writer writer("MM", /*modecr=*/0);  // 0: faces (trimmed surfaces, entity 144)
  for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) {
    // A copy of the face alone has edges and vertices of its own, shared with no other face.
    const TopoDS_Shape face = BRepBuilderAPI_Copy(it.Current()).Shape();
    if (!writer.AddShape(face))
      throw std::runtime_error("cannot convert a face to IGES for " + path.string());
  }
  writer.ComputeModel();
  if (!writer.Write(path.c_str()))
    throw std::runtime_error("cannot write IGES file " + path.string());
}

std::filesystem::path fresh_temp_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("holebench_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace holebench::occt::test
