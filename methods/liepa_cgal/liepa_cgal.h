// Baseline: CGAL's hole filling after Liepa (2003), "Filling holes in meshes":
// a minimum-weight triangulation of each hole, refined to the density of its
// surroundings and faired (CGAL::Polygon_mesh_processing::triangulate_refine_and_fair_hole).
// It knows nothing of features; it is the "plain filling" every feature-preserving
// method must beat.
#pragma once

#include "methods/method.h"

#include <cmath>

namespace holebench {

struct LiepaCgalOptions {
  bool refine = true;  ///< refine the patch to the density of the surroundings
  bool fair = true;    ///< fair the refined patch (bi-Laplacian, Eigen solver)
  double density_control_factor = std::sqrt(2.0);  ///< CGAL's default
  unsigned fairing_continuity = 1;                 ///< 0: C0, 1: C1 (CGAL's default), 2: C2
};

/// Fills every hole of `holed` (all boundary loops). New faces and vertices are marked
/// `Provenance::New` and belong to no region.
MethodResult fill_holes_liepa_cgal(const Mesh& holed, const LiepaCgalOptions& options = {});

class LiepaCgalMethod final : public Method {
 public:
  explicit LiepaCgalMethod(LiepaCgalOptions options = {}) : options_(options) {}
  std::string id() const override { return "liepa_cgal"; }
  std::string description() const override {
    return "baseline: CGAL triangulate_refine_and_fair_hole (Liepa 2003), no feature handling";
  }
  MethodOptions options() const override;
  MethodResult run(const Mesh& holed, const MethodParameters&, User&) const override {
    return fill_holes_liepa_cgal(holed, options_);
  }

 private:
  LiepaCgalOptions options_;
};

}  // namespace holebench
