// Method slice_loft: section 4 of "A slice-based algorithm for automatic and
// feature-preserving hole-filling in a CAD mesh model" (Adhikary and Gurumoorthy;
// ../shared/papers/slice-based-feature-preserving-hole-filling.txt), steps I-VI:
//   I   holes and islands (4.1)          holes_and_islands.h
//   II  segmentation of the boundary (4.2) boundary_segmentation.h
//   III missing features (4.3)            missing_features.h (eqs. 1-3: discrete_curvature.h)
//   IV  composite surface (4.4)           composite_surface.h
//   V   trimming, VI faceting and sewing  trimming_and_sewing.h
// and its comparison slice_direct (Table 2, right column): the same section points faceted
// directly, without the lofted surface. See docs/slice_loft.md.
#pragma once

#include "methods/method.h"
#include "methods/slice_loft/boundary_segmentation.h"
#include "methods/slice_loft/composite_surface.h"
#include "methods/slice_loft/holes_and_islands.h"
#include "methods/slice_loft/missing_features.h"
#include "methods/slice_loft/trimming_and_sewing.h"

#include <string>
#include <utility>

namespace holebench {

struct SliceLoftOptions {
  slice_loft::HoleIdentificationOptions identification;  ///< step I
  slice_loft::BoundarySegmentationOptions segmentation;  ///< step II (thresholds)
  slice_loft::MissingFeatureOptions features;            ///< step III
  slice_loft::CompositeSurfaceOptions surface;           ///< step IV
  slice_loft::TessellationOptions tessellation;          ///< steps V-VI (direct: slice_direct)
};

/// Fills every hole of `holed` (with its islands). A hole that cannot be filled with its
/// missing features is filled as one portion without them; one that cannot be filled at
/// all is left open; each hole's report says which (status Partial / Failed). Never throws
/// for a geometric failure.
/// With `record_layers`, the result's layers show each step: the boundary's segments (II), the
/// missing edges and corner (III), the slices, section curves and lofted surface (IV) and
/// the trimmed patch (V-VI).
MethodResult run_slice_loft(const Mesh& holed, const SliceLoftOptions& options = {},
                            bool record_layers = false);

/// The slice paper's method (`slice_loft`), or with `tessellation.direct` its comparison in
/// Table 2's right column, "direct tessellation of the discrete points generated from the
/// slice sections" (`slice_direct`). Default options are the paper's steps as written; the
/// project's departures and the named variants built from them are in slice_loft_variants.h.
class SliceLoftMethod final : public Method {
 public:
  explicit SliceLoftMethod(SliceLoftOptions options = {}, std::string id = "",
                           std::string description = "")
      : options_(options), id_(std::move(id)), description_(std::move(description)) {}
  /// The comparison method, `slice_direct`.
  static SliceLoftMethod direct() {
    SliceLoftOptions options;
    options.tessellation.direct = true;
    return SliceLoftMethod(options);
  }
  std::string id() const override {
    if (!id_.empty())
      return id_;
    return options_.tessellation.direct ? "slice_direct" : "slice_loft";
  }
  std::string description() const override {
    if (!description_.empty())
      return description_;
    return options_.tessellation.direct
               ? "slice paper's comparison: direct tessellation of the slice section points"
               : "slice paper: segmented boundary, missing edges and corner traced with "
                 "curvature continuity, slice sections lofted, trimmed and faceted";
  }
  MethodOptions options() const override;
  MethodResult run(const Mesh& holed, const MethodParameters& parameters, User&) const override {
    return run_slice_loft(holed, options_, parameters.record_layers);
  }
  const SliceLoftOptions& slice_options() const { return options_; }

 private:
  SliceLoftOptions options_;
  std::string id_, description_;
};

}  // namespace holebench
