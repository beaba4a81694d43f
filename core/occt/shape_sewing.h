// Sewing a B-Rep whose faces are not joined into a shell: IGES and STEP files from CAD part
// libraries often hold each face with edges of its own (IGES trimmed surfaces, entity 144;
// STEP faces exported one by one), so that the tessellated faces share no vertex and the mesh
// is open along every B-Rep edge. OpenCASCADE's BRepBuilderAPI_Sewing joins edges that
// coincide within a tolerance.
#pragma once

// Before any OpenCASCADE header: OpenCASCADE's `Handle` macro breaks OpenMesh's headers.
#include "core/occt/brep_mesh.h"

#include <TopoDS_Shape.hxx>

#include <string>

namespace holebench::occt {

/// The edges of `shape` that bound one face only (a seam, which bounds its face twice, and a
/// degenerated edge are not counted): the open border of a sheet, or every edge of faces that
/// were never sewn.
int count_free_edges(const TopoDS_Shape& shape);

struct SewingResult {
  TopoDS_Shape shape;         ///< the sewn shape, or the shape itself where nothing was sewn
  int free_edges_before = 0;  ///< sewing ran where this is not 0
  int free_edges_after = 0;
  double tolerance = 0.0;  ///< model units
  std::string note;        ///< what was done, for the model's notes; empty where nothing
};

/// Sews `shape` with BRepBuilderAPI_Sewing at `tolerance_rel_diag` times the diagonal of its
/// exact bounding box (exact_bounding_box_diagonal, as the tessellation's deflection) where it has
/// free edges (count_free_edges); a shape without free edges (a closed, sewn solid) is returned as
/// it is, so its faces keep their order. The note says how many free edges there were before and
/// after.
SewingResult sew_free_edges(const TopoDS_Shape& shape, double tolerance_rel_diag,
                            const std::string& source);

}  // namespace holebench::occt
