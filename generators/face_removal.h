// The face-removal family: whole B-Rep faces (one, or a few adjacent ones) removed from a
// model whose regions are B-Rep faces (a STEP, IGES or BREP file), as a scan that misses
// faces would, with the labels of CASES.md read off the topology (docs/step_input.md).
#pragma once

#include "core/case.h"
#include "generators/punch_targets.h"

#include <optional>
#include <string>
#include <vector>

namespace holebench::generators {

/// At most this many adjacent faces are removed together.
constexpr int kMaxRemovedFaces = 3;
/// At most this many face-removal cases are listed per model.
constexpr int kMaxFaceRemovalCases = 24;

/// A set of faces whose removal leaves a hole the family keeps, with its label combination.
struct FaceRemoval {
  std::vector<int> faces;  ///< removed B-Rep face ids (region ids), ascending
  /// The label combination, as the B-Rep family writes it: "k<k>/<orientation>[/<convexities>]
  /// [/<boundary kinds>]" with the convexities and kinds as sorted multisets.
  std::string combo;
  int k = 0;
  Orientation orientation = Orientation::Outer;
};

/// Every set of 1 to kMaxRemovedFaces edge-adjacent faces whose removal leaves one boundary
/// loop along at most 3 faces, all planar, that meet at every transition along an edge with a
/// dihedral angle (no third face at the transition, no tangent or coplanar edge), and whose
/// boundary kinds are defined; ordered by the number of faces, then by the face ids.
std::vector<FaceRemoval> all_face_removals(const AnalysedModel& model);

/// The listed ones: grouped by label combination (combinations sorted by name), taken round
/// robin (the first set of each combination, then the second of each, ...) up to
/// kMaxFaceRemovalCases, then ordered as in all_face_removals.
std::vector<FaceRemoval> listed_face_removals(const AnalysedModel& model);

/// The id part naming a set of faces: the ids ascending, joined by '-' ("3-7-8").
std::string face_set_name(const std::vector<int>& faces);

/// The face ids a name gives, or nothing if it is not a canonical face set name.
std::optional<std::vector<int>> parse_face_set_name(const std::string& name);

/// The case removing `faces` from `model` (its regions must be B-Rep faces): the input keeps
/// the face ids, the ground truth has the removed triangles, the missing sharp edges and
/// corners and the labels. Throws std::invalid_argument, with the reason, for a set the family
/// does not keep.
Case make_face_removal_case(const AnalysedModel& model, const std::vector<int>& faces,
                            double structure_size_rel_diag);

}  // namespace holebench::generators
