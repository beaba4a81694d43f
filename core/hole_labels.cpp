#include "core/hole_labels.h"

namespace holebench {

const char* to_string(Orientation value) {
  return value == Orientation::Inner ? "inner" : "outer";
}
const char* to_string(Convexity value) {
  return value == Convexity::Convex ? "convex" : "reflex";
}
const char* to_string(BoundaryKind value) {
  return value == BoundaryKind::Inner ? "inner" : "outer";
}
const char* to_string(Decision value) {
  return value == Decision::CloseAutomatically ? "close" : "guide";
}

}  // namespace holebench
