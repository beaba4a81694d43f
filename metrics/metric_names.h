// The name of every metric a record can carry, written once: metrics/evaluation.cpp records
// them under these names, and the harness (reports, figures, tables, tolerances) looks them
// up by them. docs/results.md says what each measures. Lengths are relative to the complete
// model's bounding-box diagonal (`_rel_diag`), angles in degrees (`_deg`), times in seconds.
#pragma once

namespace holebench::metric_names {

// In the order metrics/evaluation.cpp records them.
inline constexpr char kHausdorffRelDiag[] = "hausdorff_rel_diag";
inline constexpr char kHausdorffUpperRelDiag[] = "hausdorff_upper_rel_diag";
inline constexpr char kMeanDistanceRelDiag[] = "mean_distance_rel_diag";
inline constexpr char kMeanDistanceLowerRelDiag[] = "mean_distance_lower_rel_diag";
inline constexpr char kMeanDistanceUpperRelDiag[] = "mean_distance_upper_rel_diag";
inline constexpr char kRmsDistanceRelDiag[] = "rms_distance_rel_diag";
inline constexpr char kRmsDistanceLowerRelDiag[] = "rms_distance_lower_rel_diag";
inline constexpr char kRmsDistanceUpperRelDiag[] = "rms_distance_upper_rel_diag";
inline constexpr char kHoleDistanceConvergedOk[] = "hole_distance_converged_ok";
inline constexpr char kHoleHausdorffRelDiag[] = "hole_hausdorff_rel_diag";
inline constexpr char kHoleHausdorffUpperRelDiag[] = "hole_hausdorff_upper_rel_diag";
inline constexpr char kHoleMeanDistanceRelDiag[] = "hole_mean_distance_rel_diag";
inline constexpr char kHoleMeanDistanceLowerRelDiag[] = "hole_mean_distance_lower_rel_diag";
inline constexpr char kHoleMeanDistanceUpperRelDiag[] = "hole_mean_distance_upper_rel_diag";
inline constexpr char kHoleRmsDistanceRelDiag[] = "hole_rms_distance_rel_diag";
inline constexpr char kHoleRmsDistanceLowerRelDiag[] = "hole_rms_distance_lower_rel_diag";
inline constexpr char kHoleRmsDistanceUpperRelDiag[] = "hole_rms_distance_upper_rel_diag";
inline constexpr char kDistanceConvergedOk[] = "distance_converged_ok";
// The literature's metrics (metrics/literature_metrics.h), whole model, then hole region.
inline constexpr char kChamferL1RelDiag[] = "chamfer_l1_rel_diag";
inline constexpr char kChamferL1LowerRelDiag[] = "chamfer_l1_lower_rel_diag";
inline constexpr char kChamferL1UpperRelDiag[] = "chamfer_l1_upper_rel_diag";
inline constexpr char kChamferL2RelDiag2[] = "chamfer_l2_rel_diag2";  ///< squared lengths
inline constexpr char kChamferL2LowerRelDiag2[] = "chamfer_l2_lower_rel_diag2";
inline constexpr char kChamferL2UpperRelDiag2[] = "chamfer_l2_upper_rel_diag2";
inline constexpr char kFScore0p5PctFraction[] = "f_score_0_5pct_fraction";  ///< tau 0.5 % diag
inline constexpr char kFScore1PctFraction[] = "f_score_1pct_fraction";      ///< tau 1 % diag
inline constexpr char kNormalConsistencyFraction[] = "normal_consistency_fraction";
inline constexpr char kHoleChamferL1RelDiag[] = "hole_chamfer_l1_rel_diag";
inline constexpr char kHoleChamferL1LowerRelDiag[] = "hole_chamfer_l1_lower_rel_diag";
inline constexpr char kHoleChamferL1UpperRelDiag[] = "hole_chamfer_l1_upper_rel_diag";
inline constexpr char kHoleChamferL2RelDiag2[] = "hole_chamfer_l2_rel_diag2";
inline constexpr char kHoleChamferL2LowerRelDiag2[] = "hole_chamfer_l2_lower_rel_diag2";
inline constexpr char kHoleChamferL2UpperRelDiag2[] = "hole_chamfer_l2_upper_rel_diag2";
inline constexpr char kHoleFScore0p5PctFraction[] = "hole_f_score_0_5pct_fraction";
inline constexpr char kHoleFScore1PctFraction[] = "hole_f_score_1pct_fraction";
inline constexpr char kHoleNormalConsistencyFraction[] = "hole_normal_consistency_fraction";
inline constexpr char kHoleEdgeChamferRelDiag[] = "hole_edge_chamfer_rel_diag";
inline constexpr char kNewVertexMeanErrorRelDiag[] = "new_vertex_mean_error_rel_diag";
inline constexpr char kMissingCornerErrorMeanRelDiag[] = "missing_corner_error_mean_rel_diag";
inline constexpr char kMissingCornerErrorMaxRelDiag[] = "missing_corner_error_max_rel_diag";
inline constexpr char kMissingEdgePresentFraction[] = "missing_edge_present_fraction";
inline constexpr char kMissingEdgeCoveredFraction[] = "missing_edge_covered_fraction";
inline constexpr char kMissingEdgeDistanceMaxRelDiag[] = "missing_edge_distance_max_rel_diag";
inline constexpr char kPatchNormalDeviationMeanDeg[] = "patch_normal_deviation_mean_deg";
inline constexpr char kPatchNormalDeviationMaxDeg[] = "patch_normal_deviation_max_deg";
// Ring-removal cases (generators/real_holes.h): the removed rings against the repair, the one
// direction the real hole left open in the complete model does not bias.
inline constexpr char kRingHausdorffRelDiag[] = "ring_hausdorff_rel_diag";
inline constexpr char kRingHausdorffUpperRelDiag[] = "ring_hausdorff_upper_rel_diag";
inline constexpr char kRingMeanDistanceRelDiag[] = "ring_mean_distance_rel_diag";
inline constexpr char kRingMeanDistanceLowerRelDiag[] = "ring_mean_distance_lower_rel_diag";
inline constexpr char kRingMeanDistanceUpperRelDiag[] = "ring_mean_distance_upper_rel_diag";
// Real holes (no ground truth: metrics/patch_quality.h).
inline constexpr char kPatchBoundaryNormalJumpMeanDeg[] = "patch_boundary_normal_jump_mean_deg";
inline constexpr char kPatchBoundaryNormalJumpMaxDeg[] = "patch_boundary_normal_jump_max_deg";
inline constexpr char kPatchDihedralMeanDeg[] = "patch_dihedral_mean_deg";
inline constexpr char kPatchDihedralMaxDeg[] = "patch_dihedral_max_deg";
inline constexpr char kPatchTriangleQualityMinFraction[] = "patch_triangle_quality_min_fraction";
inline constexpr char kPatchTriangleQualityMeanFraction[] = "patch_triangle_quality_mean_fraction";
inline constexpr char kOpenBoundaryLoopsCount[] = "open_boundary_loops_count";
inline constexpr char kIsClosed[] = "is_closed";
inline constexpr char kNonManifoldVerticesCount[] = "non_manifold_vertices_count";
inline constexpr char kIsManifold[] = "is_manifold";
inline constexpr char kIsConsistentlyOriented[] = "is_consistently_oriented";
inline constexpr char kSelfIntersectionsCount[] = "self_intersections_count";
inline constexpr char kPatchSelfIntersectionsCount[] = "patch_self_intersections_count";
inline constexpr char kNewFacesCount[] = "new_faces_count";
inline constexpr char kInputFacesCount[] = "input_faces_count";
inline constexpr char kNewDegenerateFacesCount[] = "new_degenerate_faces_count";
inline constexpr char kOriginalFacesChangedCount[] = "original_faces_changed_count";
inline constexpr char kOriginalFacesUnchangedOk[] = "original_faces_unchanged_ok";
/// Every hole closed, the output closed, manifold and consistently oriented, no
/// self-intersection that involves a new face, the input's faces away from the holes
/// unchanged (docs/results.md, "Valid repair").
inline constexpr char kValidRepairOk[] = "valid_repair_ok";
inline constexpr char kClassificationKCorrectFraction[] = "classification_k_correct_fraction";
inline constexpr char kClassificationOrientationCorrectFraction[] =
    "classification_orientation_correct_fraction";
inline constexpr char kClassificationConvexityCorrectFraction[] =
    "classification_convexity_correct_fraction";
inline constexpr char kClassificationBoundaryKindCorrectFraction[] =
    "classification_boundary_kind_correct_fraction";
inline constexpr char kClassificationDecisionCorrectFraction[] =
    "classification_decision_correct_fraction";
inline constexpr char kClassificationAllCorrectFraction[] = "classification_all_correct_fraction";
/// Share of the classified holes handled as the truth's decision says (closed / guided).
inline constexpr char kDecisionHandledFraction[] = "decision_handled_fraction";
inline constexpr char kArrowsUndefinedCount[] = "arrows_undefined_count";
inline constexpr char kArrowsCount[] = "arrows_count";
inline constexpr char kArrowPositionOutsideOk[] = "arrow_position_outside_ok";
inline constexpr char kArrowShaftFreeOk[] = "arrow_shaft_free_ok";
inline constexpr char kArrowVisibleFraction[] = "arrow_visible_fraction";
inline constexpr char kArrowBestVisibleFraction[] = "arrow_best_visible_fraction";
inline constexpr char kArrowDirectionErrorDeg[] = "arrow_direction_error_deg";
inline constexpr char kFallbackHolesFraction[] = "fallback_holes_fraction";
/// Share of the holes whose method found a defect in its own result (HoleReport::defect).
inline constexpr char kDefectHolesFraction[] = "defect_holes_fraction";

/// The method's wall time (the median over its runs): recorded by the harness, not judged by
/// `holebench compare` unless a suite says so.
inline constexpr char kTimeMethodS[] = "time_method_s";

/// A distance with its interval: the value, and its lower and upper bounds where the search
/// gives them.
struct IntervalNames {
  const char* value;
  const char* lower;
  const char* upper;
};
inline constexpr IntervalNames kMeanDistance{kMeanDistanceRelDiag, kMeanDistanceLowerRelDiag,
                                             kMeanDistanceUpperRelDiag};
inline constexpr IntervalNames kRmsDistance{kRmsDistanceRelDiag, kRmsDistanceLowerRelDiag,
                                            kRmsDistanceUpperRelDiag};
inline constexpr IntervalNames kRingMeanDistance{
    kRingMeanDistanceRelDiag, kRingMeanDistanceLowerRelDiag, kRingMeanDistanceUpperRelDiag};
inline constexpr IntervalNames kHoleMeanDistance{
    kHoleMeanDistanceRelDiag, kHoleMeanDistanceLowerRelDiag, kHoleMeanDistanceUpperRelDiag};
inline constexpr IntervalNames kHoleRmsDistance{
    kHoleRmsDistanceRelDiag, kHoleRmsDistanceLowerRelDiag, kHoleRmsDistanceUpperRelDiag};
inline constexpr IntervalNames kChamferL1{kChamferL1RelDiag, kChamferL1LowerRelDiag,
                                          kChamferL1UpperRelDiag};
inline constexpr IntervalNames kChamferL2{kChamferL2RelDiag2, kChamferL2LowerRelDiag2,
                                          kChamferL2UpperRelDiag2};
inline constexpr IntervalNames kHoleChamferL1{kHoleChamferL1RelDiag, kHoleChamferL1LowerRelDiag,
                                              kHoleChamferL1UpperRelDiag};
inline constexpr IntervalNames kHoleChamferL2{kHoleChamferL2RelDiag2, kHoleChamferL2LowerRelDiag2,
                                              kHoleChamferL2UpperRelDiag2};

}  // namespace holebench::metric_names
