// A benchmark case: the holed input a method sees, and the ground truth only metrics see.
#pragma once

#include "core/mesh.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace holebench {

enum class Orientation { Inner, Outer };
enum class Convexity { Convex, Reflex };
enum class BoundaryKind { Inner, Outer };  ///< per face of an outer hole: a_i = +1 / -1
enum class Decision { CloseAutomatically, Guide };

/// The labels of CASES.md, computed by a generator from its construction (never by a
/// classifier).
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

/// Ground truth of one hole.
struct HoleTruth {
  std::string target;              ///< what was hit: "face_interior", "edge", "corner", ...
  std::vector<int> removed_faces;  ///< face indices in the complete model
  std::vector<std::vector<Point>> missing_edges;  ///< sharp edges lost, as polylines
  std::vector<Point> missing_corners;             ///< corners lost
  std::optional<HoleLabels> labels;               ///< where CASES.md labels apply
  /// Where a punched hole carries no labels: why not (its regions, its loops), so that a
  /// listing says which holes fall outside the taxonomy; empty otherwise.
  std::string unlabelled_because;
};

/// Parameters of the experiment that a method may be given (they are settings a user of
/// the method would choose, not ground truth).
struct CaseParameters {
  /// The structure size delta_s of the B-Rep paper (model units): holes smaller than it may
  /// be closed automatically. 0 where the case sets none.
  double structure_size = 0.0;
};

struct Case {
  std::string id;              ///< stable id, e.g. "box/corner"
  std::string family;          ///< generator family, e.g. "box"
  std::string kind;            ///< case kind for reports, e.g. "corner"
  std::uint64_t seed = 0;      ///< with the id, determines the case bit for bit
  double noise_percent = 0.0;  ///< vertex noise, % of 1 % of the bounding-box diagonal
  Mesh input;                  ///< the holed mesh: the only geometry a method sees
  CaseParameters parameters;   ///< settings a method may be given
  Mesh complete;               ///< the complete, clean model (ground truth)
  std::vector<HoleTruth> holes;
};

const char* to_string(Orientation value);
const char* to_string(Convexity value);
const char* to_string(BoundaryKind value);
const char* to_string(Decision value);

}  // namespace holebench
