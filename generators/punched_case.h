// A case made by punching one hole into a complete, analysed model, with its ground truth.
#pragma once

#include "core/case.h"
#include "generators/punch_targets.h"

#include <cstdint>
#include <string>

namespace holebench::generators {

struct PunchedCaseOptions {
  double radius_rel_diag = 0.02;          ///< hole radius, relative to the model's diagonal
  double irregularity = 0.25;             ///< radius varies by up to this fraction around the hole
  double island_ratio = 0.45;             ///< island: inner radius / outer radius
  double structure_size_rel_diag = 0.04;  ///< delta_s for the expected decision
  std::uint64_t shape_seed = 0;           ///< phases of the irregular boundary
  /// false: the input has no region ids (a scan); true: it keeps the model's regions (the
  /// faces of a B-Rep file: the B-Rep paper's input).
  bool keep_input_regions = false;
  /// A hole that cuts through a thin part (several boundary loops) or removes a whole face
  /// of the model is punched again with its radius times shrink_factor, up to shrink_steps
  /// times (an island excepted).
  double shrink_factor = 0.8;
  int shrink_steps = 6;
  /// Also punched again while it takes more features away than its target names (a
  /// face-interior hole an edge or corner, an edge hole a second edge or a corner, a corner
  /// hole a fourth edge or a second corner). The catalog sets it for the procedural solids,
  /// whose parts can be thinner than a large hole (the helical sweep's square section); the
  /// CAD models' cases are punched without it, as their baselines were.
  bool shrink_to_target = false;
};

/// Removes the faces around `target` (an irregular disc on the surface, grown only through
/// faces connected to the target, so that thin parts are not cut through; an annulus for
/// "island") and records the ground truth: removed faces, missing sharp edges as polylines
/// (sharp edges with both faces removed), missing corners (corners with every face
/// removed), and the labels of CASES.md where the hole runs along planar regions only. A
/// hole that would cut through a thin part or take a whole face away is made smaller
/// (PunchedCaseOptions::shrink_factor), so that it is one hole of the taxonomy.
Case make_punched_case(const AnalysedModel& model, const PunchTarget& target,
                       const PunchedCaseOptions& options);

}  // namespace holebench::generators
