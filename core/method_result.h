// What a method returns: shared by methods (which produce it) and metrics (which judge
// it), so that neither has to include the other.
#pragma once

#include "core/hole_labels.h"
#include "core/mesh.h"
#include "core/method_layers.h"

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace holebench {

enum class MethodStatus {
  Ok,       ///< every hole handled as the method intends
  Partial,  ///< some holes were left open or only partly handled (see the hole reports)
  Failed,   ///< no usable result
};
const char* to_string(MethodStatus status);

/// A guidance arrow of the B-Rep paper (section 3.3): where a depth-camera user should
/// stand (position P) and look (unit direction r) to capture a hole.
struct GuidanceArrow {
  Point position{0.0, 0.0, 0.0};
  Point direction{0.0, 0.0, -1.0};
};

/// Whether the arrow is defined: finite coordinates and a non-zero direction.
inline bool is_finite(const GuidanceArrow& arrow) {
  for (int k = 0; k < 3; ++k) {
    if (!std::isfinite(arrow.position[k]) || !std::isfinite(arrow.direction[k]))
      return false;
  }
  return arrow.direction.sqrnorm() > 0.0;
}

/// What a method did with one boundary loop of its input.
struct HoleReport {
  int hole_index = 0;             ///< index in the method's own detection order
  std::size_t loop_size = 0;      ///< boundary edges of the hole
  Point centroid{0.0, 0.0, 0.0};  ///< mean of the loop's vertices (to match ground truth)
  bool closed = false;            ///< the method produced faces that close it
  std::size_t new_faces = 0;
  std::size_t new_vertices = 0;
  /// For methods that classify holes: the labels they computed (same fields as the
  /// generator's labels, so that metrics compare them field by field).
  std::optional<HoleLabels> classification;
  /// For methods that guide the user instead of (or before) closing.
  std::optional<GuidanceArrow> arrow;
  std::string note;  ///< what went wrong, or what the method decided
  /// Empty when the method's own path (its paper's steps) handled the hole; otherwise the
  /// short, stable snake_case name of what stood in for it (e.g. "cgal_triangulate_hole"),
  /// whether or not the stand-in closed the hole (see `closed`). The names, by method, are in
  /// docs/results.md; `note` keeps the free-text reason.
  std::string fallback;
  /// Empty unless the method's check of its own result found a defect there: the short,
  /// stable snake_case name of it ("self_intersecting_patch": the hole's new faces intersect
  /// each other or the mesh around the hole), whatever the fallback. `note` says more; the
  /// tables count these holes beside the fallbacks (docs/results.md).
  std::string defect;
  double seconds = 0.0;
};

struct PhaseTiming {
  std::string phase;  ///< a step named as in the method's paper
  double seconds = 0.0;
};

struct MethodResult {
  Mesh repaired;  ///< the input with the method's patches; new elements are `Provenance::New`
  std::vector<HoleReport> holes;
  MethodStatus status = MethodStatus::Ok;
  std::string message;
  std::vector<PhaseTiming> phases;
  /// The method's steps as geometry (core/method_layers.h), filled only when
  /// MethodParameters::record_layers asks: drawn, never measured.
  std::vector<MethodLayer> layers;
};

}  // namespace holebench
