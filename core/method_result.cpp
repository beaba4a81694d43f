#include "core/method_result.h"

namespace holebench {

const char* to_string(MethodStatus status) {
  switch (status) {
    case MethodStatus::Ok:
      return "ok";
    case MethodStatus::Partial:
      return "partial";
    case MethodStatus::Failed:
      return "failed";
  }
  return "unknown";
}

}  // namespace holebench
