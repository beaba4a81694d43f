// Validity of a repaired mesh: is it closed, manifold, consistently oriented, free of
// self-intersections and of new degenerate triangles, and are the input's faces away from
// the holes untouched?
//
// Definitions:
//  - open_boundary_loops: boundary loops of the repaired mesh (core/boundary_loops.h);
//  - non_manifold_vertices: vertices whose incident faces do not form one fan (OpenMesh
//    cannot hold a non-manifold edge, so this is the one non-manifoldness left);
//  - orientation_conflicts: directed edges (u, v) used by two faces, counted from the faces'
//    vertex lists (not from the half-edge links), so the check does not trust the structure;
//  - self_intersections: pairs of faces that intersect other than in a shared vertex or
//    edge (CGAL::Polygon_mesh_processing::self_intersections, exact predicates);
//    patch_self_intersections: the pairs with at least one new face;
//  - new_degenerate_faces: new faces whose area is at most degenerate_area (model units^2)
//    or whose smallest angle is below min_angle_degrees;
//  - original_faces_changed: faces of the input that touch no boundary vertex (are away
//    from the holes) and have no face with exactly the same three points (bit for bit, in
//    the same cyclic order) in the repaired mesh.
#pragma once

#include "core/mesh.h"

#include <cstddef>

namespace holebench {

struct ValidityOptions {
  double degenerate_area = 1e-14;   ///< model units^2 (the evaluation scales by diagonal^2)
  double min_angle_degrees = 1e-3;  ///< a new face with a smaller angle is degenerate
  bool self_intersections = true;   ///< run CGAL's self-intersection test
};

struct Validity {
  std::size_t open_boundary_loops = 0;
  std::size_t non_manifold_vertices = 0;
  std::size_t orientation_conflicts = 0;
  bool self_intersections_tested = false;
  std::size_t self_intersections = 0;        ///< intersecting face pairs
  std::size_t patch_self_intersections = 0;  ///< of which at least one face is new
  std::size_t new_degenerate_faces = 0;
  std::size_t original_faces_changed = 0;
};

/// Validity of `repaired`, the repair of `input`.
Validity validity(const Mesh& input, const Mesh& repaired, const ValidityOptions& options = {});

namespace cgal {
struct SelfIntersections {
  std::size_t pairs = 0;        ///< intersecting face pairs
  std::size_t patch_pairs = 0;  ///< pairs with at least one `Provenance::New` face
};
/// CGAL::Polygon_mesh_processing::self_intersections on the mesh itself (CGAL's OpenMesh
/// graph traits). metrics/cgal/self_intersections.cpp: the metrics' one CGAL translation
/// unit.
SelfIntersections self_intersections(const Mesh& mesh);
}  // namespace cgal

}  // namespace holebench
