// A benchmark case: the holed input a method sees, and the ground truth only metrics and the
// oracle user see (the complete model, the removed faces, the labels).
//
// The ground-truth fence: no file under methods/ includes this header, directly or through
// another (checked by cmake/check_include_fence.cmake, test include_fence_methods). A method
// is given the holed mesh and its parameters (methods/method.h); the vocabulary of labels,
// which a classifier also produces, is core/hole_labels.h.
#pragma once

#include "core/hole_labels.h"
#include "core/mesh.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace holebench {

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
  /// False for a real hole (generators/real_holes.h, file/<stem>/hole/<i>): `complete` is the
  /// open mesh itself, no hole has removed faces, and the evaluation reports only the metrics
  /// that need no ground truth (metrics/patch_quality.h).
  bool has_ground_truth = true;
  /// True for a ring-removal case (file/<stem>/hole/<i>/rings-<r>): the truth is the rings
  /// around a real hole, which the complete model still has open, so the patch's distance to
  /// the complete model over that hole measures the hole's size, not the repair; the
  /// evaluation adds the truth-to-repair direction alone (ring_* metrics).
  bool truth_surrounds_a_real_hole = false;
};

}  // namespace holebench
