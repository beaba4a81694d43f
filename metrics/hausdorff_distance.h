// Two-sided Hausdorff distance between two triangle meshes, with a guaranteed error bound.
//
// Definition: h(A, B) = max over points a of A of min over points b of B |a - b|, and the
// two-sided H(A, B) = max(h(A, B), h(B, A)). Both are computed over the surfaces (not
// only the vertices) by branch and bound on the triangles of A:
//  - a lower bound L is the largest distance found at any sampled point;
//  - every triangle t of A has an upper bound U(t) >= max over t of d(x, B), the smaller of
//    (i) max over t's corners of their distance to one single triangle T of B (distance
//        to a triangle is convex, so its maximum over t is at a corner; T is tried among
//        the triangles nearest to t's centroid and corners, and the matching face: the
//        triangle of B whose corners are the vertices of B nearest to t's corners, which
//        where B is A perturbed by less than its edges is the copy of t), and
//    (ii) max over the corners of d(corner, B) + longest edge / sqrt(3) (every point of t
//        lies within that of a corner, and d(., B) is 1-Lipschitz), and
//    (iii) for two triangles of B nearest to t's corners that share an edge and whose union,
//        projected onto the first one's plane, is a convex quadrilateral Q: max over t's
//        corners of d(corner, Q) + the second triangle's height above that plane (a flat
//        region of B triangulated otherwise than A);
//  - the triangle with the largest U is split in four until U <= L + error_bound.
// The true value then lies in [lower, upper] with upper - lower <= error_bound (unless the
// work limit stops the search first, which the result says). Every closest-point query
// carries an upper bound from a point already measured (1-Lipschitz), which lets Embree's
// BVH skip far boxes; the first pass over the vertices can be shared with the mean distance
// (vertex_distances.h). Ties between closest faces
// are broken by face index, so the same inputs give the same numbers on every run.
#pragma once

#include "core/mesh.h"
#include "metrics/surface_change.h"
#include "metrics/vertex_distances.h"

#include <cstddef>
#include <memory>

namespace holebench {

namespace embree {
class TriangleScene;
}

struct HausdorffOptions {
  /// Absolute error bound, in model units (callers pass a fraction of the diagonal).
  double error_bound = 1e-4;
  /// Stop after this many closest-point queries per direction (then `converged` = false).
  std::size_t max_queries = 20'000'000;
};

struct DirectedHausdorff {
  double lower = 0.0;  ///< a distance attained at a point of A
  double upper = 0.0;  ///< no point of A is farther from B than this
  std::size_t queries = 0;
  /// First cells whose bounds were taken from a HausdorffCellBounds (their queries are
  /// counted in `queries` all the same).
  std::size_t cells_taken = 0;
  bool converged = true;
};

struct HausdorffResult {
  DirectedHausdorff a_to_b;
  DirectedHausdorff b_to_a;
  double lower() const { return std::max(a_to_b.lower, b_to_a.lower); }
  double upper() const { return std::max(a_to_b.upper, b_to_a.upper); }
  bool converged() const { return a_to_b.converged && b_to_a.converged; }
};

class HausdorffCellBounds;

/// h(A, B) with `b_scene` an Embree scene of B (reuse it across calls; it may hold only the
/// faces of B that points of A's unshared faces can be closest to) and, optionally, what is
/// known already: A's vertex distances and the faces A shares with B (vertex_distances.h),
/// and the first bounds of another mesh's faces against B or a B0 (`first`: taken for A's
/// faces with the same cells). `change` (optional; null: B is the B0 of `first`): how B
/// differs from B0; a cell's bounds are then taken where its corners' nearest faces are B0's
/// and what its steps read of B0 lies outside `change->changed`.
DirectedHausdorff directed_hausdorff(const Mesh& a, const embree::TriangleScene& b_scene,
                                     const HausdorffOptions& options = {},
                                     const KnownDistances& known = {},
                                     const HausdorffCellBounds* first = nullptr,
                                     const SurfaceChange* change = nullptr);

/// The Hausdorff search's first bounds of the faces of a mesh A0 against a surface B0: each
/// face's cell (its corners in the face's order, their distances to B0 and nearest faces of
/// B0, as the first pass over A0's vertices gives them) with every step of its upper bound
/// (i)-(iii) and its centroid's query, taken whether or not the search would need them, and
/// the box of the ball of B0 its centroid's query read and of the corners' nearest vertices.
/// A search of another mesh A against a B replays them for every face of A whose cell is the
/// same, bit for bit, where B is B0 (the same triangles in the same order) or differs from it
/// only outside that box (SurfaceChange: the steps read B0's triangles at the corners' and
/// the centroid's nearest faces, which B has too, the faces on the corners' nearest vertices
/// (the matching face), which a face of B or B0 the other lacks would lie within the box of,
/// and the centroid's query, which no face of B inside its ball changes): each step in the order
/// and under the conditions the search takes it, so that the cell gets the same bound, counts the
/// same query and the search gives the same result as without them. Built once per case
/// (case_evaluation.h): the input's faces against the complete model, which a repair keeps for the
/// most part, so that each job bounds only the faces it made or changed; and the complete model's
/// faces against the input, which a repair is away from its patch.
class HausdorffCellBounds {
 public:
  /// `first_pass`: A0's against B0 (vertex_distances.h; the faces A0 shares with B0 need no
  /// bounds).
  HausdorffCellBounds(const Mesh& a0, const embree::TriangleScene& b0_scene,
                      const FirstPass& first_pass);
  ~HausdorffCellBounds();
  HausdorffCellBounds(const HausdorffCellBounds&) = delete;
  HausdorffCellBounds& operator=(const HausdorffCellBounds&) = delete;

  std::size_t size() const;  ///< cells held

  struct Table;  ///< hausdorff_distance.cpp
  const Table& table() const { return *table_; }

 private:
  std::unique_ptr<Table> table_;
};

/// H(A, B): both directions.
HausdorffResult hausdorff_distance(const Mesh& a, const Mesh& b,
                                   const HausdorffOptions& options = {});

}  // namespace holebench
