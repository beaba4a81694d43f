// Holes across 1, 2 and 3 creases of the fandisk: the cases of the crest-line paper's
// figures 10 and 13 (one hole with one ridge through it, one with two, one at a corner).
//
// Ids: "crease/<model>/<n>" with n = 1, 2, 3, and "crease/<model>/concave_corner" (figure 12:
// three creases at a corner, one of them at least reflex); the catalog lists them for the
// fandisk.
#pragma once

#include "core/case.h"
#include "generators/punch_targets.h"

#include <optional>
#include <string>
#include <vector>

namespace holebench::generators {

struct CreaseHoleOptions {
  /// Hole radii tried in turn (relative to the diagonal) until one has a centre that fits.
  std::vector<double> radii_rel_diag = {0.03, 0.025, 0.035, 0.04, 0.045, 0.05};
  double irregularity = 0.25;  ///< as punched cases: the radius varies by up to this fraction
  double structure_size_rel_diag = 0.06;
  /// n = 3 only: the corner must be concave, one of its three creases at least reflex (the
  /// crest-line paper's figure 12, "a concave corner hole" of the fandisk).
  bool concave_corner = false;
};

/// Where to punch a hole across exactly `creases` sharp-edge chains (1, 2 or 3), and how
/// large: deterministically, the vertex whose ball of the radius (including the boundary's
/// irregularity) meets exactly that many chains, all of them well inside it, with the largest
/// margin to every other chain. n = 1, 2: no chain ends (no corner) inside the ball, so each
/// chain crosses the hole; n = 3: the centre is a corner where exactly three chains meet.
/// Nothing where no such place exists.
struct CreaseTarget {
  PunchTarget target;
  double radius_rel_diag = 0.0;
};
std::optional<CreaseTarget> find_crease_target(const AnalysedModel& model, int creases,
                                               const CreaseHoleOptions& options = {});

/// The case "crease/<model>/<creases>": an irregular hole punched at the target (as
/// make_punched_case does) with its ground truth (removed faces, missing sharp edges,
/// missing corner). Throws std::invalid_argument where the model has no such place.
Case make_crease_hole_case(const AnalysedModel& model, int creases, const std::string& id,
                           const CreaseHoleOptions& options = {});

}  // namespace holebench::generators
