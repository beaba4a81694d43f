// Method crest_feature: section 3 of "User-guided feature-sensitive hole filling"
// (../shared/papers/user-guided-feature-sensitive-hole-filling.txt). Being written.
#pragma once

#include "methods/method.h"

namespace holebench {

class CrestFeatureMethod final : public Method {
 public:
  std::string id() const override { return "crest_feature"; }
  std::string description() const override {
    return "crest-line paper: feature-first fill (not yet implemented)";
  }
  MethodResult run(const Mesh& holed, const MethodParameters&, User&) const override;
};

}  // namespace holebench
