#include "methods/slice_loft/slice_loft.h"

namespace holebench {

MethodResult SliceLoftMethod::run(const Mesh& holed, const MethodParameters&, User&) const {
  MethodResult result;
  result.repaired = holed;
  result.status = MethodStatus::Failed;
  result.message = "slice_loft is not implemented yet";
  return result;
}

MethodResult SliceDirectMethod::run(const Mesh& holed, const MethodParameters&, User&) const {
  MethodResult result;
  result.repaired = holed;
  result.status = MethodStatus::Failed;
  result.message = "slice_direct is not implemented yet";
  return result;
}

}  // namespace holebench
