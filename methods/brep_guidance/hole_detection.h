// Section 3.1 and 3.2 of the B-Rep paper: holes as loops of half-edges without twin
// (Algorithm 1), their cardinality k, transition vertices t_i with positions T_i,
// transition half-edge directions h_i, the vectors v_ij, and for k = 3 the intersection S
// of the three planes with s_i = S - T_i.
#pragma once

#include "core/mesh.h"
#include "methods/brep_guidance/brep_faces.h"

#include <optional>
#include <vector>

namespace holebench::brep_guidance {

struct Transition {
  VertexHandle vertex;  ///< t_i: where the hole passes from face f_{i-1} to f_i
  Point position;       ///< T_i
  /// h_i: the transition half-edge of f_i ending in t_i, as a unit direction. It is the next
  /// half-edge of f_i's boundary (f_i on its left, as in a B-Rep) before the hole half-edges
  /// of f_i that start in t_i; usually the edge f_i shares with f_{i-1}. The chord of up to
  /// three such boundary half-edges along the same neighbouring face. 0 if none.
  Point direction{0, 0, 0};
  /// The transition half-edge of f_{i-1} starting in t_i: the half-edge of f_{i-1}'s
  /// boundary after its hole half-edges that end in t_i (the twin of h_i when the two faces
  /// share the edge; not necessarily, as the paper notes). 0 if none.
  Point direction_previous{0, 0, 0};
};

struct Hole {
  /// The paper's hole half-edges: half-edges of faces whose twin is missing, in the order
  /// Algorithm 1 visits them (the faces' own direction: each face on the left).
  std::vector<HalfedgeHandle> halfedges;
  /// f_1 .. f_k: the face (region) of each run of the loop, with multiplicity.
  std::vector<int> faces;
  /// The half-edges of each run; runs[i] lies on faces[i] and starts at transitions[i].
  std::vector<std::vector<HalfedgeHandle>> runs;
  std::vector<Transition> transitions;  ///< k entries for k >= 2; none for k = 1
  std::vector<Point> v;                 ///< v_i = T_{i+1} - T_i (the paper's v_ij, j = i + 1)
  std::optional<Point> S;               ///< k = 3: the intersection of the three planes
  std::vector<Point> s;                 ///< k = 3: s_i = S - T_i
  bool linearly_dependent = false;      ///< k = 2, 3: the planes have no unique intersection
  Point centroid{0, 0, 0};              ///< Ps: the mean of the hole's vertices

  int k() const { return static_cast<int>(faces.size()); }
};

/// Algorithm 1 on the mesh's half-edge structure, then each hole's attributes. Holes are
/// returned in the order of their smallest half-edge index. Planes whose normals' triple
/// product (k = 3) or cross product (k = 2) is below `dependence_tolerance` count as
/// linearly dependent.
std::vector<Hole> detect_holes(const Mesh& mesh, const BrepFaces& faces,
                               double dependence_tolerance = 1e-3);

}  // namespace holebench::brep_guidance
