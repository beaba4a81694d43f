#include "methods/crest_feature/crest_feature.h"

namespace holebench {

MethodResult CrestFeatureMethod::run(const Mesh& holed, const MethodParameters&, User&) const {
  MethodResult result;
  result.repaired = holed;
  result.status = MethodStatus::Failed;
  result.message = "crest_feature is not implemented yet";
  return result;
}

}  // namespace holebench
