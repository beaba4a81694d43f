// The vocabulary of CASES.md's hole labels: cardinality, convexity at each transition,
// orientation, boundary kinds and the expected decision. Generators write them as a case's
// ground truth (core/case.h); a classifier (methods/brep_guidance) writes its answer in the
// same shape, which is why a method may include this header and not core/case.h.
#pragma once

#include <string>
#include <vector>

namespace holebench {

enum class Orientation { Inner, Outer };
enum class Convexity { Convex, Reflex };
enum class BoundaryKind { Inner, Outer };  ///< per face of an outer hole: a_i = +1 / -1
enum class Decision { CloseAutomatically, Guide };

/// The labels of CASES.md. As a case's ground truth (HoleTruth::labels), computed by a
/// generator from its construction, never by a classifier; as a classifier's answer
/// (MethodResult's hole classification), what the method computed from the holed mesh.
struct HoleLabels {
  int k = 0;  ///< cardinality: faces along the loop, counted with multiplicity
  /// Region ids of the faces along the loop, in the cyclic order in which the loop's
  /// boundary halfedges (find_boundary_loops) visit them, up to rotation (k entries). A
  /// region the loop leaves and re-enters appears twice.
  std::vector<int> regions;
  /// Convexity at each transition, in loop order: transitions[i] is the transition from
  /// regions[i] to regions[(i + 1) % k]. Empty for k = 1.
  std::vector<Convexity> transitions;
  Orientation orientation = Orientation::Inner;
  /// False where the orientation is not defined for the hole and a classifier does not
  /// compute it (the B-Rep paper: for k > 3 "the calculation of the orientation fails").
  /// Comparisons of orientation skip labels or classifications where this is false.
  bool orientation_known = true;
  /// Per face (same order as `regions`), outer holes only: is the loop part of that face's
  /// inner boundary or of its outer boundary (a_i = +1 / -1 of the B-Rep paper's eq. 4).
  std::vector<BoundaryKind> boundary_kinds;
  /// k = 3 with two linearly dependent (parallel) faces: no corner exists.
  bool linearly_dependent_faces = false;
  /// The hole's size as CASES.md defines it (model units): the largest diameter (k = 1),
  /// the largest distance to the missing edge (k = 2), the distance to the missing corner
  /// (k = 3); the largest diameter otherwise.
  double size = 0.0;
  /// The structure size delta_s the expected decision was taken against (model units).
  double structure_size = 0.0;
  Decision expected_decision = Decision::CloseAutomatically;
  /// Non-empty for the variants the B-Rep paper names as its weak spots, e.g.
  /// "multiple_inner_boundaries" or "twisted_face": what a faithful method is expected to
  /// get wrong, so that tests and reports can say so.
  std::string known_weak_spot;
};

const char* to_string(Orientation value);
const char* to_string(Convexity value);
const char* to_string(BoundaryKind value);
const char* to_string(Decision value);

}  // namespace holebench
