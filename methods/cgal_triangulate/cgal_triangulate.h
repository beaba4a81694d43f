// Baseline: CGAL's plain hole triangulation, the plainest filling many tools ship
// (CGAL::Polygon_mesh_processing::triangulate_hole alone: no refinement, no fairing). Each
// hole gets the minimum-weight triangulation of its boundary loop (Liepa 2003, the O(n^3)
// dynamic program over all the loop's vertices): no new vertices, so a patch is as coarse as
// its loop and flat between its boundary vertices. It knows nothing of features.
#pragma once

#include "methods/method.h"

namespace holebench {

struct CgalTriangulateOptions {
  /// Restrict the search to the faces of a 3D Delaunay triangulation of the loop (CGAL's
  /// default). Off: on co-spherical loops it depends on memory addresses (docs/methods.md).
  bool use_delaunay_triangulation = false;
  /// First try a 2D constrained Delaunay triangulation of the loop in its fitted plane where
  /// the loop is near planar (CGAL 5.5's default in code: off).
  bool use_2d_constrained_delaunay_triangulation = false;
};

/// Fills every hole of `holed` (all boundary loops) by triangulate_hole. New faces are
/// `Provenance::New` and belong to no region; no vertex is added.
MethodResult fill_holes_cgal_triangulate(const Mesh& holed,
                                         const CgalTriangulateOptions& options = {});

class CgalTriangulateMethod final : public Method {
 public:
  explicit CgalTriangulateMethod(CgalTriangulateOptions options = {}) : options_(options) {}
  std::string id() const override { return "cgal_triangulate"; }
  std::string description() const override {
    return "baseline: CGAL triangulate_hole alone (no refinement, no fairing), no feature handling";
  }
  MethodOptions options() const override;
  MethodResult run(const Mesh& holed, const MethodParameters&, User&) const override {
    return fill_holes_cgal_triangulate(holed, options_);
  }

 private:
  CgalTriangulateOptions options_;
};

}  // namespace holebench
