// Tessellating an OpenCASCADE shape into holebench's mesh, welded along the B-Rep's edges.
#pragma once

// Before any OpenCASCADE header: OpenCASCADE's `Handle` macro breaks OpenMesh's headers.
#include "core/occt/brep_mesh.h"

#include "core/mesh_builder.h"

#include <TopoDS_Shape.hxx>

#include <string>

namespace holebench::occt {

/// Tessellates `shape` with BRepMesh_IncrementalMesh (sequential, so deterministic) at a
/// linear deflection of options.linear_deflection_rel_diag times the diagonal of the shape's
/// exact bounding box, and welds the faces' triangulations into one mesh:
/// - the nodes of a B-Rep vertex are one mesh vertex (at the vertex's point);
/// - the nodes on a B-Rep edge come from the edge's polygon on each face's triangulation,
///   which BRepMesh discretises once per edge, so neighbouring faces (and the two sides of a
///   seam) share these vertices;
/// - the nodes on a degenerated edge (a sphere's pole, a cone's apex) are the vertex's;
///   triangles that thereby repeat a vertex are dropped;
/// - triangles of a face with orientation TopAbs_REVERSED are flipped, so normals point out
///   of a solid.
/// Region id of each triangle: the index of its face in TopExp::MapShapes(shape, FACE),
/// 0-based. Any existing triangulation of the shape is replaced (BRepTools::Clean).
/// Where a face does not tessellate, the whole shape is tessellated again at the deflection
/// times each of options.retry_deflection_factors in turn, and the first at which every face
/// tessellates is kept, with a note (TessellatedSoup::notes).
/// Throws InvalidInputError naming `source` for a shape without faces, a face without
/// triangulation at every deflection tried, or a mesh that build_mesh rejects (e.g. a
/// non-manifold edge).
/// \bug An open shell gives an open mesh; callers that need a closed one check it.
BrepMesh tessellate_shape(const TopoDS_Shape& shape, const TessellationOptions& options,
                          const std::string& source = "<shape>");

/// The diagonal of the shape's exact bounding box (BRepBndLib::AddOptimal, without the shapes'
/// tolerances): what the deflection and the sewing tolerance are relative to. 0 for a void box.
double exact_bounding_box_diagonal(const TopoDS_Shape& shape);

/// The welded triangles before build_mesh, with the faces' surface types: what
/// tessellate_shape builds its mesh from (build_mesh with mark_original and `source`).
struct TessellatedSoup {
  TriangleSoup soup;
  std::vector<SurfaceType> face_surfaces;
  std::vector<std::string> notes;  ///< as BrepMesh::notes
};
TessellatedSoup tessellate_shape_soup(const TopoDS_Shape& shape, const TessellationOptions& options,
                                      const std::string& source = "<shape>");

}  // namespace holebench::occt
