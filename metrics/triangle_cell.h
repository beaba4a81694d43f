// The cell of the branch-and-bound searches over the triangles of a mesh A against a
// surface B (hausdorff_distance.h, surface_distance.h): a triangle of A, or a piece of one,
// with its corners' distances to B and the faces of B nearest to them, and its four-way
// split at the midpoints of its edges.
//
// The split is the same for both searches: the three midpoints are queried (each with an
// upper bound on its answer from the nearer end of its edge, the distance being
// 1-Lipschitz), and the children are the three corner triangles and the middle one, so the
// children tile the parent and each child's corners carry their measured distances.
#pragma once

#include "core/mesh.h"
#include "metrics/vertex_distances.h"

#include <array>
#include <cstddef>
#include <cstdint>

namespace holebench {

struct TriangleCell {
  std::array<Point, 3> corners;
  std::array<double, 3> corner_distance;          // d(corner, B)
  std::array<int, 3> corner_face = {-1, -1, -1};  // faces of B nearest to the corners
  double priority = 0.0;  // the queue refines the largest first (cell_queue.h)
  std::size_t order = 0;  // creation order: breaks ties in the queue deterministically
};

/// A cell's inputs to a search's bounds, bit for bit: its corners, their distances and
/// nearest faces of B. Tables of bounds computed once per case (MeanCellBounds,
/// HausdorffCellBounds) are keyed by it.
struct CellKey {
  std::array<std::uint64_t, 12> bits{};
  std::array<int, 3> faces{};
  bool operator==(const CellKey& other) const { return bits == other.bits && faces == other.faces; }
};
struct CellKeyHash {
  std::size_t operator()(const CellKey& key) const;  ///< FNV-1a over the words
};
CellKey key_of(const TriangleCell& cell);

/// The cell of face `f` of A: its corners (in the face's vertex order) with their distances
/// and nearest faces from the first pass over A's vertices.
TriangleCell face_cell(const Mesh& a, FaceHandle f, const VertexDistances& vertices);

/// The centroid of the cell, (c0 + c1 + c2) / 3 summed in corner order: the point the
/// searches and the case's first pass query first, which must be the same bits in each so
/// that one query's answer serves them all (FirstPass::centroid).
inline Point cell_centroid(const TriangleCell& cell) {
  const auto& c = cell.corners;
  return (c[0] + c[1] + c[2]) / 3.0;
}

/// An upper bound on the distance to B at a point `p` of the cell from its corners' distances
/// (1-Lipschitz): the least of d(corner, B) + |p - corner|.
double distance_bound_from_corners(const TriangleCell& cell, const Point& p);

/// The midpoints of a cell's edges c0c1, c1c2, c2c0 and, for each, an upper bound on its
/// distance to B: the nearer end's distance plus half the edge (1-Lipschitz).
struct EdgeMidpoints {
  std::array<Point, 3> points;
  std::array<double, 3> distance_bound;
};
EdgeMidpoints edge_midpoints(const TriangleCell& cell);

/// The four children of a cell, given its edge midpoints with their distances to B and
/// nearest faces: the triangles at corners 0, 1 and 2, then the middle one. Priority and
/// order are left to the search.
std::array<TriangleCell, 4> midpoint_children(const TriangleCell& cell,
                                              const std::array<Point, 3>& midpoint,
                                              const std::array<double, 3>& midpoint_distance,
                                              const std::array<int, 3>& midpoint_face);

/// The cell split in four at its edge midpoints, each midpoint measured by
/// `query(point, distance_bound)` (a closest point with `distance` and `face`), edge c0c1
/// first.
template <class Query>
std::array<TriangleCell, 4> split_at_midpoints(const TriangleCell& cell, Query&& query) {
  const EdgeMidpoints mid = edge_midpoints(cell);
  std::array<double, 3> distance;
  std::array<int, 3> face;
  for (int i = 0; i < 3; ++i) {
    const auto closest = query(mid.points[i], mid.distance_bound[i]);
    distance[i] = closest.distance;
    face[i] = closest.face;
  }
  return midpoint_children(cell, mid.points, distance, face);
}

}  // namespace holebench
