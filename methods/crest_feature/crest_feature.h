// Method crest_feature: section 3 of "User-guided feature-sensitive hole filling"
// (../shared/papers/user-guided-feature-sensitive-hole-filling.txt). Crest lines (3.2) are
// detected on the whole mesh, holes identified (3.3); per hole, feature points where crest
// lines meet its boundary are detected, paired and the corner triple named (3.4.1-3.4.2:
// an automatic rule, then the User), feature lines interpolated across the hole by
// Catmull-Rom splines (3.4.3), the hole split along them into sub-holes (3.4.4), and each
// sub-hole filled by a constrained Delaunay triangulation of its boundary projected on the
// plane of equation 6 (3.5). See docs/crest_feature.md.
#pragma once

#include "methods/crest_feature/crest_lines.h"
#include "methods/crest_feature/feature_line_interpolation.h"
#include "methods/crest_feature/feature_points.h"
#include "methods/crest_feature/hole_filling.h"
#include "methods/crest_feature/hole_identification.h"
#include "methods/method.h"

#include <string>
#include <utility>

namespace holebench {

struct CrestFeatureOptions {
  crest_feature::CrestLineOptions crest_lines;
  crest_feature::HoleIdentificationOptions identification;  ///< islands attached by default
  crest_feature::FeaturePointOptions feature_points;
  crest_feature::InterpolationOptions interpolation;
  crest_feature::HoleFillingOptions filling;  ///< refinement and fairing off by default
};

/// Runs the method on `holed`; the user step of every hole goes through `user`. With
/// `record_layers`, the result's layers show each step: the crest lines (3.2), the feature
/// points used (3.4.1-3.4.2), the feature lines (3.4.3), the sub-holes (3.4.4) and the patch
/// (3.5).
MethodResult run_crest_feature(const Mesh& holed, User& user,
                               const CrestFeatureOptions& options = {}, bool record_layers = false);

/// The crest-line paper's method with its steps as written (default options), or a named
/// variant with the project's departures (`plus()`: crest_feature_plus).
class CrestFeatureMethod final : public Method {
 public:
  explicit CrestFeatureMethod(CrestFeatureOptions options = {}, std::string id = "crest_feature",
                              std::string description = "")
      : options_(options), id_(std::move(id)), description_(std::move(description)) {}
  /// crest_feature_plus: P0/P3 on the fitted tangent line and feature points at the boundary
  /// vertex nearest the crest line's ray (docs/crest_feature.md).
  static CrestFeatureMethod plus() {
    CrestFeatureOptions options;
    options.interpolation.control_points = crest_feature::ControlPoints::TangentLine;
    options.feature_points.on_boundary_edges = false;
    return CrestFeatureMethod(
        options, "crest_feature_plus",
        "crest_feature with the project's departures: Catmull-Rom end points P0/P3 on the "
        "fitted tangent line, feature points at the nearest boundary vertex");
  }
  std::string id() const override { return id_; }
  std::string description() const override {
    if (!description_.empty())
      return description_;
    return "crest-line paper: crest lines, feature points paired by the user, Catmull-Rom "
           "feature lines, sub-holes filled by projected constrained Delaunay triangulation";
  }
  MethodOptions options() const override;
  MethodResult run(const Mesh& holed, const MethodParameters& parameters,
                   User& user) const override {
    return run_crest_feature(holed, user, options_, parameters.record_layers);
  }
  const CrestFeatureOptions& crest_options() const { return options_; }

 private:
  CrestFeatureOptions options_;
  std::string id_, description_;
};

}  // namespace holebench
