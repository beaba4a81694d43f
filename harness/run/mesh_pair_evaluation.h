// `holebench evaluate --complete A --repaired B [--holed C]`: the metrics of one repaired mesh
// against a complete one, for any two mesh files (what MeshLab's Metro and PyMeshLab's
// Hausdorff filter are used for), with holebench's bounded distances.
//
// Without the holed mesh, the repaired mesh is measured as a whole: the two-sided Hausdorff
// distance with its bound, the mean and RMS distance intervals, the literature's sampled
// metrics over the whole model, and the validity a mesh has alone (closed, manifold,
// oriented, self-intersections). With it, the repair is the holed mesh plus a patch (its
// faces must come back unchanged: methods/external/output_patch.h), the hole is the complete
// model's faces the holed mesh lacks (one hole per connected set of them, their missing sharp
// edges and corners from a feature analysis of the complete mesh, as punched holes have), and
// every hole-region metric and the patch's validity are added. The holed mesh's faces must be
// the complete mesh's, bit for bit (a hole cut from a clean model); where at most half of the
// complete mesh's faces are found in it (a noisy input), it is not used, with a note.
#pragma once

#include "core/mesh.h"
#include "core/mesh_builder.h"
#include "metrics/evaluation.h"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <vector>

namespace holebench::harness {

struct MeshPairEvaluation {
  std::vector<MetricValue> metrics;  ///< named as in a run's records (docs/metrics.md)
  double diagonal = 0.0;             ///< the complete mesh's bounding-box diagonal
  std::size_t holes = 0;             ///< with the holed mesh: the holes found
  std::size_t removed_faces = 0;     ///< ... the complete mesh's faces they remove
  std::size_t new_faces = 0;         ///< ... the repaired mesh's faces not in the holed mesh
  /// Where the holed mesh was given but could not be used (the repair changed its faces, or it
  /// shares too few faces with the complete mesh): why;
  /// the metrics are then those of the two meshes alone.
  std::string note;
};

/// The metrics of `repaired` against `complete` (and `holed`, where given): see the file comment.
/// Throws InvalidInputError where the repaired mesh has a non-finite coordinate or an index out of
/// range, or the complete mesh has no faces.
MeshPairEvaluation evaluate_mesh_pair(const Mesh& complete, const TriangleSoup& repaired,
                                      const Mesh* holed, const EvaluationOptions& options = {});

/// The evaluation as `holebench evaluate --complete ... --json` prints it (the file names
/// aside): holes, removed_faces and new_faces where the holed mesh was given (`with_holed`),
/// complete_bounding_box_diagonal, note where there is one, and metrics (name -> value).
nlohmann::ordered_json mesh_pair_to_json(const MeshPairEvaluation& pair, bool with_holed);

}  // namespace holebench::harness
