// Method slice_loft: section 4 of "Slice-based feature-preserving hole filling"
// (../shared/papers/slice-based-feature-preserving-hole-filling.txt). Being written.
#pragma once

#include "methods/method.h"

namespace holebench {

class SliceLoftMethod final : public Method {
 public:
  std::string id() const override { return "slice_loft"; }
  std::string description() const override {
    return "slice paper: slice-based, feature-preserving fill (not yet implemented)";
  }
  MethodResult run(const Mesh& holed, const MethodParameters&, User&) const override;
};

/// The slice paper's comparison (Table 2, right column): "direct tessellation of the discrete
/// points generated from the slice sections".
class SliceDirectMethod final : public Method {
 public:
  std::string id() const override { return "slice_direct"; }
  std::string description() const override {
    return "slice paper's comparison: direct tessellation of the slice points (not yet "
           "implemented)";
  }
  MethodResult run(const Mesh& holed, const MethodParameters&, User&) const override;
};

}  // namespace holebench
