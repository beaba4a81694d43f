#include "metrics/evaluation.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"
#include "metrics/hausdorff_distance.h"

namespace holebench {

const MetricValue* Evaluation::find(const std::string& name) const {
  for (const auto& value : values) {
    if (value.name == name)
      return &value;
  }
  return nullptr;
}

Evaluation evaluate(const Case& c, const Mesh& repaired, const EvaluationOptions& options) {
  Evaluation evaluation;
  const double diagonal = bounding_box_diagonal(c.complete);
  HausdorffOptions hausdorff_options;
  hausdorff_options.error_bound = options.hausdorff_error_bound_rel_diag * diagonal;
  const HausdorffResult hausdorff = hausdorff_distance(repaired, c.complete, hausdorff_options);
  evaluation.values.push_back({"hausdorff_rel_diag", hausdorff.lower() / diagonal});
  evaluation.values.push_back({"hausdorff_upper_rel_diag", hausdorff.upper() / diagonal});
  evaluation.values.push_back(
      {"open_boundary_loops_count", static_cast<double>(find_boundary_loops(repaired).size())});
  evaluation.values.push_back({"new_faces_count", static_cast<double>(count_new_faces(repaired))});
  return evaluation;
}

}  // namespace holebench
