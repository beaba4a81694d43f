// Section 3.2-3.3 of the B-Rep paper: the convexity of two faces at a transition vertex
// (figure 3), the orientation (equations 1 and 2), the boundary kind of each face (the a_i of
// equation 4), the size of a hole, and the decision against the structure size delta_s.
#pragma once

#include "core/hole_labels.h"
#include "methods/brep_guidance/hole_detection.h"

#include <vector>

namespace holebench::brep_guidance {

struct Classification {
  /// Convexity at each transition t_i, between faces f_{i-1} and f_i (k >= 2).
  std::vector<Convexity> convexity;
  /// The figure-3 case at each transition: false for the two obvious cases, true where the
  /// overlaps a_i, a_j decided.
  std::vector<bool> decided_by_overlap;
  Orientation orientation = Orientation::Inner;
  bool orientation_known = true;  ///< false for k > 3 ("the calculation fails")
  /// Per face visit (outer holes): the loop on that face is part of its inner or outer boundary.
  std::vector<BoundaryKind> boundary_kinds;
  double size = 0.0;
  Decision decision = Decision::Guide;
};

/// How figure 3 finds on which side of the other face's plane each face lies.
enum class Figure3Rule {
  /// As written: each face lies to the left of its transition half-edge h_i; the overlaps
  /// of the projected hole half-edges settle the undefined cases (`figure_3`).
  TransitionHalfEdges,
  /// The earlier reading, kept as an alternative: each face's side from the sum of the
  /// vectors from T_i to its `nearest_hole_vertices` nearest hole vertices, the overlap as
  /// |w . n_other|. Better on one labelled job of the nightly suite (cad/joint/edge_reflex/
  /// large at 0 %), worse on 60 brep jobs at 0, 5 and 25 % (docs/methods.md).
  NearestHoleVertices,
};

struct ClassificationOptions {
  double structure_size = 1.0;  ///< delta_s, model units
  Figure3Rule figure_3_rule = Figure3Rule::TransitionHalfEdges;
  /// Figure3Rule::NearestHoleVertices: hole vertices on each side of t_i that are summed.
  int nearest_hole_vertices = 3;
  /// How many hole half-edges of each face, from the transition vertex on, are projected
  /// onto the plane pi for the overlaps a_i, a_j of figure 3 (0: the face's whole run).
  int projected_halfedges = 0;
};

/// Figure 3 at one transition vertex t between faces f_i and f_j, in the plane pi through T
/// with normal n_i x n_j. Each face's plane cuts pi in a line through T, g_i and g_j; a
/// point's side of g_j is the sign of its offset along n_j (n_j is orthogonal to pi's
/// normal, so projecting onto pi keeps it). h_i and h_j are the faces' transition half-edges
/// at t (each face on its left, as in a B-Rep): f_i lies to the left of h_i, along n_i x h_i,
/// which projected onto pi is one of the two rays of g_i; likewise f_j along n_j x h_j. Where
/// they lie gives the four cases:
///   (a) f_i's ray below g_j and f_j's ray below g_i (against the normals): convex;
///   (b) both above: reflex;
///   (c), (d) one below and one above: undefined. This needs h_i and h_j not to be twins:
///       for twins both tests are the same triple product. The overlaps decide: a_i is the
///       length of f_i's hole half-edges, projected onto pi, on f_i's side of g_j (a
///       half-edge that crosses g_j counts for its part beyond it), a_j likewise; the face
///       with the larger overlap gives the answer.
struct Figure3 {
  Convexity convexity = Convexity::Convex;
  bool decided_by_overlap = false;  ///< cases (c), (d)
  int side_i = 0;                   ///< f_i's side of g_j: -1 below, +1 above, 0 undefined
  int side_j = 0;                   ///< f_j's side of g_i
  double a_i = 0.0;                 ///< overlap of f_i's projected hole half-edges beyond g_j
  double a_j = 0.0;                 ///< overlap of f_j's projected hole half-edges beyond g_i
};

/// The geometry of figure 3. `h_i`, `h_j`: the transition half-edges' directions (f_i's
/// ends in t, f_j's starts there). `path_i`: f_i's hole vertices after T, walked away from
/// t; `path_j`: f_j's hole vertices before T, walked away from t (both without T). At most
/// `halfedges` half-edges of each path count for the overlaps (0: all).
Figure3 figure_3(const Point& T, const Point& n_i, const Point& n_j, const Point& h_i,
                 const Point& h_j, const std::vector<Point>& path_i,
                 const std::vector<Point>& path_j, int halfedges = 0);

/// Figure 3 at transition i of `hole`, between faces f_{i-1} (= f_j) and f_i.
Figure3 figure_3(const Mesh& mesh, const BrepFaces& faces, const Hole& hole, int i,
                 const ClassificationOptions& options);

/// Convexity of faces f_{i-1} and f_i at transition i (figure 3), with whether the overlap
/// rule decided it.
std::pair<Convexity, bool> transition_convexity(const Mesh& mesh, const BrepFaces& faces,
                                                const Hole& hole, int i,
                                                const ClassificationOptions& options);

/// Whether the loop on face visit i belongs to that face's inner boundary (a_i = +1) or its
/// outer boundary (a_i = -1): the face's boundary loop through the run, walked with the face
/// on its left, turns clockwise about the face normal for an inner boundary.
BoundaryKind boundary_kind(const Mesh& mesh, const BrepFaces& faces, const Hole& hole, int i);

Classification classify_hole(const Mesh& mesh, const BrepFaces& faces, const Hole& hole,
                             const ClassificationOptions& options);

/// The classification in the generators' label convention (core/case.h: regions in the
/// order of the mesh's boundary half-edges, which run against the faces' half-edges), so that
/// metrics compare it with the labels field by field.
HoleLabels to_labels(const Hole& hole, const Classification& classification, double structure_size);

}  // namespace holebench::brep_guidance
