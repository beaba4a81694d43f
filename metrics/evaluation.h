// The metrics of one job: pure functions of the case (with its ground truth) and the
// repaired mesh a method returned. Metrics never see the method itself.
#pragma once

#include "core/case.h"
#include "core/mesh.h"

#include <string>
#include <vector>

namespace holebench {

/// One named number. Names carry their unit: `_rel_diag` is relative to the bounding-box
/// diagonal of the complete model, `_s` seconds, `_count` a count.
struct MetricValue {
  std::string name;
  double value = 0.0;
};

struct EvaluationOptions {
  /// Error bound of the Hausdorff distance, relative to the complete model's diagonal.
  double hausdorff_error_bound_rel_diag = 1e-4;
};

struct Evaluation {
  std::vector<MetricValue> values;
  const MetricValue* find(const std::string& name) const;
};

/// Evaluates `repaired` against `c.complete`:
///  - hausdorff_rel_diag: two-sided Hausdorff distance (its attained lower bound), and
///    hausdorff_upper_rel_diag, the bound it is guaranteed below;
///  - open_boundary_loops_count: boundary loops the repaired mesh still has;
///  - new_faces_count: faces marked `Provenance::New`.
Evaluation evaluate(const Case& c, const Mesh& repaired, const EvaluationOptions& options = {});

}  // namespace holebench
