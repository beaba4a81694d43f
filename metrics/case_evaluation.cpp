#include "metrics/case_evaluation.h"

#include "metrics/embree/triangle_scene.h"

namespace holebench {

CaseEvaluation::CaseEvaluation(const Case& c, const EvaluationOptions& options) {
  if (c.complete.n_faces() > 0)
    complete_scene_ = std::make_unique<embree::TriangleScene>(c.complete);
  if (options.self_intersections)
    input_self_intersections_ = holebench::input_self_intersections(c.input);
}

CaseEvaluation::~CaseEvaluation() = default;

}  // namespace holebench
