// Feature recovery: how well a repaired mesh restores the sharp features the holes took
// away (the missing corners and sharp edges of the ground truth), and how well the patch's
// normals follow the complete model.
//
// Definitions (lengths in model units; the evaluation divides them by the diagonal):
//  - corner error: for each missing corner c, min over vertices v of the repaired mesh
//    |v - c| (any vertex, original or new: a method that does not rebuild the corner is
//    charged the distance to the nearest vertex it kept or made);
//  - sharp edges of the repaired mesh: core/features.h's analysis of the repaired mesh
//    (regions by dihedral angle, `features.segmentation.sharp_angle_degrees`);
//  - each missing edge polyline is sampled every `edge_sample_spacing` (ends included);
//    a sample is covered when a sharp edge of the repaired mesh lies within
//    `edge_tolerance` of it; the edge is present when at least half of its samples are;
//  - edge distance: for an edge all of whose samples have a repaired sharp edge within
//    `edge_search_radius`, the largest distance of a sample to its nearest such edge (a
//    one-sided Hausdorff distance from the true polyline to the repaired sharp edges near
//    it); other edges have none;
//  - normal deviation: for each new face, the smallest angle between its normal and the
//    normals of the complete model's normal cone at its centroid (the faces within the
//    nearest distance plus `normal_cone.tolerance`, normal_cone.h); area-weighted mean and
//    maximum. On a crease both sides are in the cone, so a face that follows either side
//    deviates little; a face that folds across it deviates from both.
#pragma once

#include "core/case.h"
#include "core/features.h"
#include "core/mesh.h"
#include "metrics/kept_faces.h"
#include "metrics/normal_cone.h"

#include <optional>
#include <vector>

namespace holebench {

namespace embree {
class TriangleScene;
}

struct FeatureRecoveryOptions {
  FeatureOptions features;            ///< how sharp edges of the repaired mesh are found
  double edge_sample_spacing = 1e-3;  ///< model units (the evaluation scales by the diagonal)
  double edge_tolerance = 5e-3;       ///< model units: a sharp edge this close covers a sample
  double edge_search_radius = 5e-2;   ///< model units: sharp edges farther are not "near"
  NormalConeOptions normal_cone;      ///< the normal deviation's cone (model units)
};

struct MissingEdgeRecovery {
  double covered_fraction = 0.0;   ///< samples with a repaired sharp edge within tolerance
  bool present = false;            ///< covered_fraction >= 0.5
  std::optional<double> distance;  ///< see the header comment
};

struct FeatureRecovery {
  std::vector<double> corner_errors;                ///< per missing corner, in case order
  std::vector<MissingEdgeRecovery> edges;           ///< per missing edge, in case order
  std::optional<double> normal_deviation_mean_deg;  ///< none without new faces
  std::optional<double> normal_deviation_max_deg;
};

/// What feature_recovery can take from the case instead of reading the whole repaired mesh
/// (metrics/case_evaluation.h keeps them); the numbers are the same.
struct FeatureRecoveryShortcuts {
  /// Where every input vertex is a vertex of the repair at its index
  /// (KeptFaces::input_vertices_kept): input_corner_distances(c). The corners' errors then
  /// look at the repair's own vertices only.
  const std::vector<double>* input_corner_distances = nullptr;
  /// Where the repair keeps every input face (kept_faces.h, none dropped) and the sharp edges
  /// come from segment_regions (not regions_from_mesh): the input's regions by input face
  /// (segment_regions(c.input, features.segmentation)), the kept faces and a scene of the
  /// repair. The repair's regions are then the input's joined across its new faces' smooth
  /// edges, and the sharp edges near each missing edge are found through the scene, at the
  /// patch's cost rather than the model's.
  const std::vector<int>* input_face_regions = nullptr;
  const KeptFaces* kept = nullptr;
  const embree::TriangleScene* repaired_scene = nullptr;
  /// new_face_indices(repaired) (face_subset.h), where the caller has them: the faces whose
  /// normal deviation is measured, without a pass over every face to find them again.
  const std::vector<int>* new_faces = nullptr;
};

/// Feature recovery of `repaired` against the ground truth of `c`; `complete_scene` is an
/// Embree scene of `c.complete`.
FeatureRecovery feature_recovery(const Case& c, const Mesh& repaired,
                                 const embree::TriangleScene& complete_scene,
                                 const FeatureRecoveryOptions& options,
                                 const FeatureRecoveryShortcuts& shortcuts = {});

/// Per missing corner of `c` (holes in order, corners in order), the distance to the nearest
/// vertex of the input: what every repair that keeps the input's vertices shares.
std::vector<double> input_corner_distances(const Case& c);

}  // namespace holebench
