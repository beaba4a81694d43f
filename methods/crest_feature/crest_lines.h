// Crest line detection (crest-line paper, section 3.2): ridges and ravines after Yoshizawa
// et al. (the paper's reference [16]), from principal curvatures, principal directions and
// their derivatives estimated by fitting a local polynomial (jet) at every vertex.
#pragma once

#include "core/mesh.h"

#include <array>
#include <vector>

namespace holebench::crest_feature {

struct CrestLineOptions {
  /// Degree of the fitted jet and of the Monge form (>= 3: the ridges need the third-order
  /// coefficients b0 and b3, the derivatives of the principal curvatures).
  int jet_degree = 3;
  /// Rings of neighbours gathered for the fit, grown until at least `min_fit_points` points.
  int min_rings = 2;
  int max_rings = 4;
  int min_fit_points = 16;
  /// A crest line is kept if its mean |k| along the line is at least this over the mean
  /// edge length (weak lines on flat or gently curved parts are dropped).
  double min_mean_curvature_times_edge = 0.15;
  /// ... and if it has at least this many segments.
  int min_segments = 3;
  /// Curvatures are fitted and crest lines traced only within this many rings of a boundary
  /// vertex (the holes); 0: over the whole mesh.
  int band_rings = 12;
  /// Sharp creases (not in the paper; sharp_creases.h): edges whose dihedral angle exceeds
  /// this (degrees; the project's sharp-edge threshold, core/region_segmentation.h) make
  /// crest lines of their own; 180: none.
  double sharp_crease_angle_degrees = 30.0;
  /// A sharp crease's chain ends where it turns by more than this at a vertex (degrees).
  double sharp_crease_bend_degrees = 45.0;
  /// Jet-fitted crest points within this many mean edge lengths of a sharp crease are
  /// dropped: the fitted ridges that run beside the crease.
  double sharp_crease_clearance_edges = 2.0;
};

enum class CrestType { Ridge, Ravine };

struct CrestLine {
  CrestType type = CrestType::Ridge;
  std::vector<Point> points;    ///< crest points, in order along the line (on mesh edges)
  double mean_curvature = 0.0;  ///< mean |k| along the line (strength / length)
  /// Per end (front, back): whether the line runs out there, so that it may be extrapolated
  /// to a hole's boundary (3.4.1). A sharp crease's end at a corner or a bend does not.
  std::array<bool, 2> runs_out = {true, true};
};

struct CrestLines {
  std::vector<CrestLine> lines;
  double mean_edge_length = 0.0;
  std::size_t dropped_weak = 0;  ///< lines found but dropped by the strength filter
  /// The principal directions were degenerate on some triangle (exactly planar parts with
  /// exactly orthogonal directions), where CGAL's ridge tracing cannot run: no crest lines.
  bool skipped = false;
};

/// Ridges (eq. 1: c_max = 0, dc_max/dt_max < 0, k_max > |k_min|) and ravines (eq. 2:
/// c_min = 0, dc_min/dt_min > 0, k_min < -|k_max|) of `mesh`, with curvature signs such that
/// a convex crease has k_max > 0 (normals oriented outward, as the paper's convention).
/// Uses CGAL's Monge_via_jet_fitting and Ridge_approximation (compute_crest_ridges, order
/// 3). The mesh may have boundaries.
CrestLines detect_crest_lines(const Mesh& mesh, const CrestLineOptions& options = {});

}  // namespace holebench::crest_feature
