// Hole filling (crest-line paper, section 3.5): each sub-hole's boundary is projected onto
// the plane of equation 6 (normal = sum of the normals of its boundary triangles),
// triangulated by a constrained Delaunay triangulation (CGAL), mapped back to 3D by applying
// the triangulation's topology to the 3D boundary points, and stitched into the mesh. Not in
// the paper: a sub-hole around an island is triangulated with the island's loop as an inner
// boundary, and equation 6 sums the triangles along both loops.
// Refinement and fairing are an option, off by default as in the paper.
#pragma once

#include "core/mesh.h"
#include "methods/crest_feature/hole_partitioning.h"
#include "methods/crest_feature/planarity_split.h"

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace holebench::crest_feature {

struct HoleFillingOptions {
  /// Refine the patch to the density of its surroundings and fair it (CGAL
  /// Polygon_mesh_processing::refine and fair; feature-line vertices stay fixed). The paper
  /// does neither.
  bool refine_and_fair = false;
  double density_control_factor = std::sqrt(2.0);
  /// Where no projection plane gives a simple polygon (equation 6, then Newell's normal, then
  /// the least-squares plane), triangulate the sub-hole's 3D boundary by CGAL's
  /// triangulate_hole_polyline instead of leaving it open (not in the paper).
  bool polyline_fallback = true;
  /// Where the patch cannot be stitched, close the hole without feature lines
  /// (fill_hole_without_features) instead of leaving it open (not in the paper).
  bool triangulate_hole_fallback = true;
  /// Where equation 6's projection intersects itself, cut the sub-hole into more planar
  /// pieces before any fallback (not in the paper's steps; planarity_split.h).
  PlanaritySplitOptions planarity_split;
  /// Split each chord the mesh already has at its midpoint before stitching (not in the
  /// paper; split_chords_the_mesh_has).
  bool split_taken_chords = true;
};

struct SubHoleFilling {
  bool ok = false;
  /// The plane the boundary was projected on: "equation 6", or the fallback that worked
  /// where equation 6's projection intersects itself ("newell", "least squares", or none:
  /// the 3D fallback).
  std::string plane;
  /// "" when equation 6's projection was triangulated (the paper's step); otherwise what
  /// stood in: "sub_hole_newell_projection", "sub_hole_least_squares_projection" or
  /// "sub_hole_cgal_triangulate_hole_polyline" (HoleReport::fallback names).
  std::string fallback;
  std::string error;  ///< why equation 6 alone failed, where it did
  int chords = 0;     ///< chords cut to keep equation 6 (planarity_split.h)
};

/// The fallback of a hole whose sub-holes were filled as `sub_holes` say: the one furthest
/// from the paper (the 3D triangulation, then the least-squares plane, then Newell's), or ""
/// when every sub-hole was projected by equation 6.
std::string sub_hole_fallback(const std::vector<SubHoleFilling>& sub_holes);

struct HoleFillingResult {
  std::vector<SubHoleFilling> sub_holes;
  std::size_t new_faces = 0;
  std::size_t new_vertices = 0;
  bool closed = false;           ///< every sub-hole triangulated and every face stitched
  std::size_t split_chords = 0;  ///< chords split by split_chords_the_mesh_has
  std::string error;
};

/// Not in the paper: for each island of `partition`, the sub-hole it lies in (every point of
/// its loop inside the sub-hole's loop seen along the sub-hole's equation-6 normal), or -1.
/// A sub-hole with islands is triangulated as the region between its loop and theirs.
std::vector<int> place_islands(const Mesh& mesh, const HolePartition& partition);

/// Not in the paper: a triangle edge between two hole vertices that the mesh already joins by
/// an inner edge cannot be stitched (the edge would have three faces). Each such chord of
/// `triangles` is split at its midpoint, a new point appended to `new_points` (a Steiner
/// point), and the triangles on it become two each. Returns the number of chords split.
std::size_t split_chords_the_mesh_has(const Mesh& mesh, std::vector<std::array<Node, 3>>& triangles,
                                      std::vector<Point>& new_points);

/// Fills every sub-hole of `partition` in `mesh` (new vertices and faces are
/// Provenance::New). Faces are stitched only if every sub-hole triangulates; otherwise the
/// mesh is left unchanged and the result says why.
HoleFillingResult fill_hole(Mesh& mesh, const HolePartition& partition,
                            const HoleFillingOptions& options = {});

/// Not in the paper: where the patch cannot be stitched (a triangle would reuse an edge the
/// mesh already has), the whole hole is filled by CGAL's triangulate_hole (minimum-weight,
/// no feature lines) from its boundary halfedge `border`. Returns the new faces.
std::size_t fill_hole_without_features(Mesh& mesh, HalfedgeHandle border);

/// Equation 6: the sum of the normals of the sub-hole's boundary triangles (the faces
/// across its edges that are boundary edges of the mesh); zero if it has none.
Point projection_normal(const Mesh& mesh, const std::vector<Node>& sub_hole);

}  // namespace holebench::crest_feature
