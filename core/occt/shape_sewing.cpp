#include "core/occt/shape_sewing.h"

#include "core/errors.h"
#include "core/occt/shape_tessellation.h"

#include <BRepBuilderAPI_Sewing.hxx>
#include <BRep_Tool.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

#include <fmt/format.h>

namespace holebench::occt {
namespace {

// The distinct faces in `faces` (an edge's ancestors list a face once per use).
int distinct_faces(const TopTools_ListOfShape& faces) {
  int count = 0;
  for (auto it = faces.cbegin(); it != faces.cend(); ++it) {
    bool seen = false;
    for (auto before = faces.cbegin(); before != it; ++before)
      seen = seen || before->IsSame(*it);
    count += seen ? 0 : 1;
  }
  return count;
}

}  // namespace

int count_free_edges(const TopoDS_Shape& shape) {
  TopTools_IndexedDataMapOfShapeListOfShape faces_of_edge;
  TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, faces_of_edge);
  int free_edges = 0;
  for (int i = 1; i <= faces_of_edge.Extent(); ++i) {
    const TopoDS_Edge& edge = TopoDS::Edge(faces_of_edge.FindKey(i));
    const TopTools_ListOfShape& faces = faces_of_edge(i);
    if (BRep_Tool::Degenerated(edge) || faces.IsEmpty() || distinct_faces(faces) > 1)
      continue;
    if (BRep_Tool::IsClosed(edge, TopoDS::Face(faces.First())))
      continue;  // a seam: both sides of the edge are the one face
    ++free_edges;
  }
  return free_edges;
}

SewingResult sew_free_edges(const TopoDS_Shape& shape, double tolerance_rel_diag,
                            const std::string& source) {
  SewingResult result;
  result.shape = shape;
  result.free_edges_before = count_free_edges(shape);
  result.free_edges_after = result.free_edges_before;
  if (result.free_edges_before == 0)
    return result;
  result.tolerance = tolerance_rel_diag * exact_bounding_box_diagonal(shape);
  try {
    BRepBuilderAPI_Sewing sewing(result.tolerance);
    sewing.Add(shape);
    sewing.Perform();
    const TopoDS_Shape sewn = sewing.SewedShape();
    if (sewn.IsNull())
      throw InvalidInputError(source + ": sewing its faces gave no shape");
    result.shape = sewn;
  } catch (const Standard_Failure& e) {
    throw InvalidInputError(fmt::format("{}: OpenCASCADE failed sewing its faces ({}: {})", source,
                                        e.DynamicType()->Name(), e.GetMessageString()));
  }
  result.free_edges_after = count_free_edges(result.shape);
  result.note = fmt::format(
      "its faces were not sewn into a shell ({} free edges); sewn with OpenCASCADE's "
      "BRepBuilderAPI_Sewing at tolerance {:.3g} ({:g} of the diagonal): {} free edges left",
      result.free_edges_before, result.tolerance, tolerance_rel_diag, result.free_edges_after);
  return result;
}

}  // namespace holebench::occt
