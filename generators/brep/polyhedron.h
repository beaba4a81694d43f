// A planar polyhedral model (a planar B-Rep): planar faces, each a polygon with an outer
// loop and optional inner loops, and its tessellation into the core mesh.
#pragma once

#include "core/case.h"
#include "core/mesh.h"

#include <array>
#include <map>
#include <optional>
#include <vector>

namespace holebench::generators::brep {

/// One planar face. Its region id is its index in `Polyhedron::faces`.
struct PlanarFace {
  std::vector<Point> outer;               ///< counter-clockwise seen from outside
  std::vector<std::vector<Point>> inner;  ///< holes in the face, clockwise seen from outside

  /// Loop 0 is the outer loop, loop i > 0 the inner loop i - 1.
  const std::vector<Point>& loop(int index) const { return index == 0 ? outer : inner[index - 1]; }
  int loop_count() const { return 1 + static_cast<int>(inner.size()); }
};

/// A set of planar faces sharing their edges: a closed solid, or open (a subset of one).
/// Faces that meet share their polygon edges exactly (same end points, no T-junctions).
struct Polyhedron {
  std::vector<PlanarFace> faces;
};

/// The unit outward normal of a face (Newell's method on its outer loop).
Point face_normal(const PlanarFace& face);

/// The area of a face (outer loop minus inner loops).
double face_area(const PlanarFace& face);

/// A directed polygon edge of a face: `face`'s loop `loop`, from its point `index` to the
/// next one.
struct LoopEdge {
  int face = -1;
  int loop = 0;
  int index = 0;
};

/// The edge structure of a polyhedron: which face loop holds each directed edge, so that
/// an edge's twin (the other face along it) is found in O(log n).
class PolyhedronTopology {
 public:
  explicit PolyhedronTopology(const Polyhedron& polyhedron);

  /// The face loop edge from `from` to `to` (exact points), if any.
  std::optional<LoopEdge> find(const Point& from, const Point& to) const;
  const Point& from(const LoopEdge& edge) const;
  const Point& to(const LoopEdge& edge) const;
  LoopEdge next(const LoopEdge& edge) const;
  LoopEdge previous(const LoopEdge& edge) const;
  /// The twin: the other face's edge from `to` to `from`, if the polyhedron has one.
  std::optional<LoopEdge> twin(const LoopEdge& edge) const;
  /// Convexity of a shared edge, from the two faces' plane normals: convex where
  /// (n_face x n_twin) . (to - from) > 0. \pre The edge has a twin.
  Convexity convexity(const LoopEdge& edge) const;
  /// The edges out of a vertex, one per face around it, counter-clockwise about the outward
  /// normal (the order in which a boundary loop around a small hole at the vertex visits
  /// the faces). The edge between face i and face i + 1 is `previous(edges[i])`.
  /// \pre `vertex` is a polygon vertex of the closed part of the polyhedron.
  std::vector<LoopEdge> edges_around(const Point& vertex) const;
  /// The unit normal of face `face`.
  const Point& normal(int face) const { return normals_[face]; }
  /// Every distinct polygon vertex, in key order.
  std::vector<Point> vertices() const;
  const Polyhedron& polyhedron() const { return polyhedron_; }

 private:
  using Key = std::array<double, 3>;
  const Polyhedron& polyhedron_;
  std::map<std::pair<Key, Key>, LoopEdge> edges_;
  std::vector<Point> normals_;
};

struct TessellationOptions {
  double spacing = 0.2;  ///< target edge length (model units)
  /// Interior lattice points closer than this (in units of `spacing`) to a face's boundary
  /// are dropped.
  double boundary_clearance = 0.5;
};

/// Tessellates every face into triangles of about `options.spacing`: each polygon edge is
/// subdivided uniformly and identically for both faces that share it (the mesh is
/// watertight where the polyhedron is closed), interior points lie on a regular
/// (hexagonal) lattice in the face plane, and each face is triangulated by a constrained
/// Delaunay triangulation in its plane. Face i's triangles get region id i and the face's
/// orientation (outward normals). Deterministic. Throws InvalidInputError (build_mesh) on
/// a polyhedron whose faces do not fit together into a manifold.
Mesh tessellate(const Polyhedron& polyhedron, const TessellationOptions& options = {});

/// `polyhedron` with every point multiplied by `factor`.
Polyhedron scaled(const Polyhedron& polyhedron, double factor);

}  // namespace holebench::generators::brep
