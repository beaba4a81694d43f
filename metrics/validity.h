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
#include "metrics/input_topology.h"
#include "metrics/kept_faces.h"

#include <cstddef>
#include <utility>
#include <vector>

namespace holebench {

namespace embree {
class TriangleScene;
}

struct ValidityOptions {
  double degenerate_area = 1e-14;   ///< model units^2 (the evaluation scales by diagonal^2)
  double min_angle_degrees = 1e-3;  ///< a new face with a smaller angle is degenerate
  bool self_intersections = true;   ///< run CGAL's self-intersection test
};

namespace cgal {
struct SelfIntersections {
  std::size_t pairs = 0;        ///< intersecting face pairs
  std::size_t patch_pairs = 0;  ///< pairs with at least one `Provenance::New` face
};
}  // namespace cgal

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

/// A pair of face indices that intersect, the smaller first.
using FacePair = std::pair<int, int>;

/// The input's own intersecting face pairs (input face indices), which every repair of it
/// that keeps the input's faces shares: computed once per case (metrics/case_evaluation.h)
/// so that each repair's self-intersection test only covers its new faces and their
/// neighbourhood.
struct InputSelfIntersections {
  std::vector<FacePair> pairs;  ///< sorted
};

/// CGAL's self-intersection test on the input alone.
InputSelfIntersections input_self_intersections(const Mesh& input);

/// What a caller already knows of the input and the repair, each optional: the same counts
/// with less work.
struct ValidityShortcuts {
  /// The input's own pairs (input_self_intersections): the self-intersections are then
  /// counted from them and from a test of the faces that are not the input's and of the
  /// input's faces in their bounding box (self_intersections_from_input): the same counts as
  /// the test of the whole repaired mesh.
  const InputSelfIntersections* input_pairs = nullptr;
  /// kept_faces(input, repaired).
  const KeptFaces* kept_of_input = nullptr;
  /// With `kept_of_input`: input_topology(input); the open loops, non-manifold vertices and
  /// orientation conflicts are then counted at the repair's changes (input_topology.h).
  const InputTopology* topology = nullptr;
  /// With `input_pairs` and `kept_of_input`: the repaired mesh's scene, which finds the kept
  /// faces near the others without a pass over every face.
  const embree::TriangleScene* repaired_scene = nullptr;
  /// new_face_indices(repaired) (face_subset.h): no pass over every face to find them again.
  const std::vector<int>* new_faces = nullptr;
};

/// Validity of `repaired`, the repair of `input`.
Validity validity(const Mesh& input, const Mesh& repaired, const ValidityOptions& options = {},
                  const ValidityShortcuts& known = {});

/// The self-intersections of `repaired` from the input's own pairs. The faces of `repaired`
/// that are the input's (kept_faces.h; a rotated face is not kept, only tested again): two
/// kept faces intersect in `repaired` exactly when they do in
/// the input (the same points and the same shared vertices). Every other pair has a face
/// that is not kept, whose box lies in the bounding box of those faces: CGAL tests those
/// faces and the kept faces whose box meets that bounding box, and the pairs of two kept
/// faces it finds there are the input's. With `repaired_scene` (a scene of `repaired`), those
/// kept faces are the ones it finds within the sphere about that box, filtered by the same box
/// test: the same faces in the same order.
cgal::SelfIntersections self_intersections_from_input(const Mesh& input, const Mesh& repaired,
                                                      const InputSelfIntersections& known_input);
cgal::SelfIntersections self_intersections_from_input(
    const Mesh& repaired, const InputSelfIntersections& known_input, const KeptFaces& kept_of_input,
    const embree::TriangleScene* repaired_scene = nullptr);

namespace cgal {
/// CGAL::Polygon_mesh_processing::self_intersections on the mesh itself (CGAL's OpenMesh
/// graph traits), each pair once, sorted. metrics/cgal/self_intersections.cpp: the metrics'
/// one CGAL translation unit.
std::vector<FacePair> self_intersecting_pairs(const Mesh& mesh);
/// The same among the faces `among` only (face indices of `mesh`; adjacency is the mesh's).
std::vector<FacePair> self_intersecting_pairs(const Mesh& mesh, const std::vector<int>& among);
}  // namespace cgal

}  // namespace holebench
