// Section 3.2-3.3 of the B-Rep paper: the convexity of two faces at a transition vertex
// (figure 3), the orientation (equations 1 and 2), the boundary kind of each face (the a_i of
// equation 4), the size of a hole, and the decision against the structure size delta_s.
#pragma once

#include "core/case.h"
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

struct ClassificationOptions {
  double structure_size = 1.0;  ///< delta_s, model units
  /// How many hole half-edges on each side of a transition vertex are projected onto the
  /// plane pi to find on which side of the other face a face lies (figure 3).
  int projected_halfedges = 3;
};

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
