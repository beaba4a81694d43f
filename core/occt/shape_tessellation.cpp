#include "core/occt/shape_tessellation.h"

#include "core/errors.h"
#include "core/mesh_builder.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Poly_PolygonOnTriangulation.hxx>
#include <Poly_Triangulation.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace holebench::occt {
namespace {

SurfaceType surface_type(const TopoDS_Face& face) {
  switch (BRepAdaptor_Surface(face).GetType()) {
    case GeomAbs_Plane:
      return SurfaceType::Plane;
    case GeomAbs_Cylinder:
      return SurfaceType::Cylinder;
    case GeomAbs_Cone:
      return SurfaceType::Cone;
    case GeomAbs_Sphere:
      return SurfaceType::Sphere;
    case GeomAbs_Torus:
      return SurfaceType::Torus;
    case GeomAbs_BSplineSurface:
      return SurfaceType::BSpline;
    default:
      return SurfaceType::Other;
  }
}

Point to_point(const gp_Pnt& p) {
  return Point(p.X(), p.Y(), p.Z());
}

// Welds the faces' triangulations into one indexed triangle list: the nodes of a B-Rep vertex
// or edge become the same soup vertex on every face that shares it.
class TriangulationWelder {
 public:
  TriangulationWelder(const TopoDS_Shape& shape, std::string source) : source_(std::move(source)) {
    TopExp::MapShapes(shape, TopAbs_VERTEX, vertices_);
    TopExp::MapShapes(shape, TopAbs_EDGE, edges_);
    vertex_nodes_.assign(vertices_.Extent() + 1, -1);
    edge_nodes_.resize(edges_.Extent() + 1);
  }

  void add_face(const TopoDS_Face& face, int region) {
    TopLoc_Location location;
    const Handle(Poly_Triangulation) triangulation = BRep_Tool::Triangulation(face, location);
    if (triangulation.IsNull() || triangulation->NbTriangles() == 0)
      fail(fmt::format("B-Rep face {} did not tessellate", region));
    const gp_Trsf transform = location.Transformation();
    std::vector<int> node_of(triangulation->NbNodes() + 1, -1);
    for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
      weld_edge(TopoDS::Edge(it.Current()), triangulation, location, transform, region, node_of);
    }
    for (int i = 1; i <= triangulation->NbNodes(); ++i) {
      if (node_of[i] < 0)
        node_of[i] = new_node(triangulation->Node(i).Transformed(transform));
    }
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    for (int i = 1; i <= triangulation->NbTriangles(); ++i) {
      int a = 0, b = 0, c = 0;
      triangulation->Triangle(i).Get(a, b, c);
      if (reversed)
        std::swap(b, c);
      const std::array<int, 3> triangle = {node_of[a], node_of[b], node_of[c]};
      if (triangle[0] == triangle[1] || triangle[1] == triangle[2] || triangle[2] == triangle[0])
        continue;  // collapsed onto a degenerated edge
      soup_.triangles.push_back(triangle);
      soup_.regions.push_back(region);
    }
  }

  TriangleSoup take_soup() { return std::move(soup_); }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InvalidInputError(fmt::format("{}: {}", source_, what));
  }

  int new_node(const gp_Pnt& p) {
    soup_.points.push_back(to_point(p));
    return static_cast<int>(soup_.points.size()) - 1;
  }

  int vertex_node(const TopoDS_Vertex& vertex) {
    int& node = vertex_nodes_[vertices_.FindIndex(vertex)];
    if (node < 0)
      node = new_node(BRep_Tool::Pnt(vertex));
    return node;
  }

  // Maps the face's nodes on `edge` to the edge's shared vertices, creating them on the first
  // face that visits the edge. BRepMesh discretises an edge once, so its polygon on every
  // face has the same nodes at the same parameters, in the same order.
  void weld_edge(const TopoDS_Edge& edge, const Handle(Poly_Triangulation) & triangulation,
                 const TopLoc_Location& location, const gp_Trsf& transform, int region,
                 std::vector<int>& node_of) {
    const Handle(Poly_PolygonOnTriangulation) polygon =
        BRep_Tool::PolygonOnTriangulation(edge, triangulation, location);
    if (polygon.IsNull())
      fail(fmt::format("an edge of B-Rep face {} has no polygon on its triangulation", region));
    const int count = polygon->NbNodes();
    const TopoDS_Vertex first = TopExp::FirstVertex(edge);
    const TopoDS_Vertex last = TopExp::LastVertex(edge);
    if (first.IsNull() || last.IsNull())
      fail(fmt::format("an edge of B-Rep face {} has no end vertices", region));
    if (BRep_Tool::Degenerated(edge)) {
      for (int i = 1; i <= count; ++i)
        node_of[polygon->Node(i)] = vertex_node(first);
      return;
    }
    node_of[polygon->Node(1)] = vertex_node(first);
    node_of[polygon->Node(count)] = vertex_node(last);
    std::vector<int>& interior = edge_nodes_[edges_.FindIndex(edge)];
    if (interior.empty()) {
      for (int i = 2; i < count; ++i)
        interior.push_back(new_node(triangulation->Node(polygon->Node(i)).Transformed(transform)));
    }
    if (static_cast<int>(interior.size()) != count - 2) {
      fail(fmt::format("an edge of B-Rep face {} has {} nodes on this face and {} on another",
                       region, count, interior.size() + 2));
    }
    for (int i = 2; i < count; ++i)
      node_of[polygon->Node(i)] = interior[i - 2];
  }

  std::string source_;
  TopTools_IndexedMapOfShape vertices_, edges_;
  std::vector<int> vertex_nodes_;             // per vertex map index: its soup vertex
  std::vector<std::vector<int>> edge_nodes_;  // per edge map index: its interior soup vertices
  TriangleSoup soup_;
};

// Soup vertices that no triangle uses (a vertex of a face that is not meshed) are dropped.
void drop_unused_points(TriangleSoup& soup) {
  std::vector<int> index(soup.points.size(), -1);
  std::vector<Point> points;
  for (auto& triangle : soup.triangles) {
    for (int& v : triangle) {
      if (index[v] < 0) {
        index[v] = static_cast<int>(points.size());
        points.push_back(soup.points[v]);
      }
      v = index[v];
    }
  }
  soup.points = std::move(points);
}

void mesh_shape(const TopoDS_Shape& shape, double linear_deflection, double angular_deflection) {
  BRepTools::Clean(shape);
  BRepMesh_IncrementalMesh mesher(shape, linear_deflection, /*isRelative=*/false,
                                  angular_deflection, /*isInParallel=*/false);
}

// The region ids (0-based) of the faces that have no triangulation.
std::vector<int> untessellated_faces(const TopTools_IndexedMapOfShape& faces) {
  std::vector<int> missing;
  for (int i = 1; i <= faces.Extent(); ++i) {
    TopLoc_Location location;
    const Handle(Poly_Triangulation) triangulation =
        BRep_Tool::Triangulation(TopoDS::Face(faces(i)), location);
    if (triangulation.IsNull() || triangulation->NbTriangles() == 0)
      missing.push_back(i - 1);
  }
  return missing;
}

std::string face_list(const std::vector<int>& faces) {
  return fmt::format("{} {}", faces.size() == 1 ? "face" : "faces", fmt::join(faces, ", "));
}

// Meshes `shape` at the options' deflection and, where a face does not tessellate, at each
// retry factor in turn; returns the notes of a retry that succeeded, throws where none did.
std::vector<std::string> mesh_every_face(const TopoDS_Shape& shape,
                                         const TopTools_IndexedMapOfShape& faces, double diagonal,
                                         const TessellationOptions& options,
                                         const std::string& source) {
  const double deflection = options.linear_deflection_rel_diag * diagonal;
  mesh_shape(shape, deflection, options.angular_deflection_radians);
  const std::vector<int> missing = untessellated_faces(faces);
  if (missing.empty())
    return {};
  for (double factor : options.retry_deflection_factors) {
    mesh_shape(shape, factor * deflection, options.angular_deflection_radians);
    if (untessellated_faces(faces).empty()) {
      return {
          fmt::format("B-Rep {} did not tessellate at a linear deflection of {:g} of the "
                      "diagonal; tessellated at {:g} times it ({} {})",
                      face_list(missing), options.linear_deflection_rel_diag, factor,
                      factor < 1.0 ? "finer" : "coarser", factor * deflection)};
    }
  }
  throw InvalidInputError(fmt::format(
      "{}: B-Rep {} did not tessellate (tried at a linear deflection of {:g} of the diagonal "
      "and {:g} times it)",
      source, face_list(missing), options.linear_deflection_rel_diag,
      fmt::join(options.retry_deflection_factors, ", ")));
}

TessellatedSoup tessellate(const TopoDS_Shape& shape, const TessellationOptions& options,
                           const std::string& source) {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  const double diagonal = exact_bounding_box_diagonal(shape);
  if (faces.IsEmpty() || !(diagonal > 0.0))
    throw InvalidInputError(fmt::format("{}: no faces to tessellate", source));
  TessellatedSoup result;
  result.notes = mesh_every_face(shape, faces, diagonal, options, source);
  TriangulationWelder welder(shape, source);
  for (int i = 1; i <= faces.Extent(); ++i) {
    const TopoDS_Face& face = TopoDS::Face(faces(i));
    result.face_surfaces.push_back(surface_type(face));
    welder.add_face(face, i - 1);
  }
  result.soup = welder.take_soup();
  drop_unused_points(result.soup);
  return result;
}

}  // namespace

double exact_bounding_box_diagonal(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::AddOptimal(shape, box, /*useTriangulation=*/false, /*useShapeTolerance=*/false);
  return box.IsVoid() ? 0.0 : std::sqrt(box.SquareExtent());
}

TessellatedSoup tessellate_shape_soup(const TopoDS_Shape& shape, const TessellationOptions& options,
                                      const std::string& source) {
  try {
    return tessellate(shape, options, source);
  } catch (const Standard_Failure& e) {
    throw InvalidInputError(fmt::format("{}: OpenCASCADE failed tessellating it ({}: {})", source,
                                        e.DynamicType()->Name(), e.GetMessageString()));
  }
}

BrepMesh tessellate_shape(const TopoDS_Shape& shape, const TessellationOptions& options,
                          const std::string& source) {
  TessellatedSoup tessellated = tessellate_shape_soup(shape, options, source);
  BuildOptions build;
  build.source = source;
  BrepMesh result;
  result.face_surfaces = std::move(tessellated.face_surfaces);
  result.mesh = build_mesh(tessellated.soup, build);
  return result;
}

}  // namespace holebench::occt
