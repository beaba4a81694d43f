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

/// The labels of CASES.md, computed by a generator from its construction.
struct HoleLabels {
  int k = 0;                           ///< cardinality (faces counted with multiplicity)
  std::vector<Convexity> transitions;  ///< convexity at each transition (k entries, k>=2)
  Orientation orientation = Orientation::Inner;
  std::vector<BoundaryKind> boundary_kinds;  ///< per face, outer holes only
  Decision expected_decision = Decision::CloseAutomatically;
};

/// Ground truth of one hole.
struct HoleTruth {
  std::string target;              ///< what was hit: "face_interior", "edge", "corner", ...
  std::vector<int> removed_faces;  ///< face indices in the complete model
  std::vector<std::vector<Point>> missing_edges;  ///< sharp edges lost, as polylines
  std::vector<Point> missing_corners;             ///< corners lost
  std::optional<HoleLabels> labels;               ///< where CASES.md labels apply
};

struct Case {
  std::string id;              ///< stable id, e.g. "box/corner"
  std::string family;          ///< generator family, e.g. "box"
  std::string kind;            ///< case kind for reports, e.g. "corner"
  std::uint64_t seed = 0;      ///< with the id, determines the case bit for bit
  double noise_percent = 0.0;  ///< vertex noise, % of 1 % of the bounding-box diagonal
  Mesh input;                  ///< the holed mesh: the only thing a method sees
  Mesh complete;               ///< the complete, clean model (ground truth)
  std::vector<HoleTruth> holes;
};

const char* to_string(Orientation value);
const char* to_string(Convexity value);
const char* to_string(BoundaryKind value);
const char* to_string(Decision value);

}  // namespace holebench
